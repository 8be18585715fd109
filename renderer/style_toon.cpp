// The toon style: the shaded style's intensities cut into three flat bands, silhouettes in dark
// ink, creases in the darkest band's colour.
#include "octopoint/styles.h"

namespace octopoint {
namespace {

constexpr std::uint32_t kInk = 0x202020;
// Intensity (Q8) below kShadowBelow is shadow, below kLitBelow half-lit, above that lit.
constexpr std::uint32_t kShadowBelow = 110, kLitBelow = 190;
constexpr std::uint32_t kShadow = 115, kHalfLit = 190, kLit = 256;  // band brightness, Q8

}  // namespace

void toonRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
              std::int32_t end_row, std::span<std::uint8_t> rgb) {
  forEachStyledPixel(frame, first_row, end_row, pass.rule, rgb,
                     [&pass](std::uint32_t word, Edge edge, std::size_t at) {
                       if (word == Framebuffer::kEmpty) return pass.background;
                       if (edge == Edge::kSilhouette) return kInk;
                       const std::uint32_t base = pass.colourAt(word, at);
                       if (edge == Edge::kCrease) return scaledRgb(base, kShadow);
                       const std::uint32_t intensity = pass.intensityAt(word, at);
                       return scaledRgb(base, intensity < kShadowBelow ? kShadow
                                              : intensity < kLitBelow  ? kHalfLit
                                                                       : kLit);
                     });
}

}  // namespace octopoint
