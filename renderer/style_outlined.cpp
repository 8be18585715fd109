// The outlined style: the colour image with silhouettes in dark ink and creases darkened over it.
#include "octopoint/styles.h"

namespace octopoint {
namespace {

constexpr std::uint32_t kInk = 0x101010;
constexpr std::uint32_t kCreaseDarkening = 110;  // Q8: a crease keeps 43% of its colour

}  // namespace

void outlinedRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                  std::int32_t end_row, std::span<std::uint8_t> rgb) {
  forEachStyledPixel(frame, first_row, end_row, pass.rule, rgb,
                     [&pass](std::uint32_t word, Edge edge, std::size_t at) {
                       if (word == Framebuffer::kEmpty) return pass.background;
                       if (edge == Edge::kSilhouette) return kInk;
                       const std::uint32_t colour = pass.colourAt(word, at);
                       return edge == Edge::kCrease ? scaledRgb(colour, kCreaseDarkening) : colour;
                     });
}

}  // namespace octopoint
