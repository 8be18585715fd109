// The lines style, after Hekmatzada et al.: a white page, silhouettes in black, creases in grey,
// nothing else (octopoint/styles.h finds them).
#include "octopoint/styles.h"

namespace octopoint {
namespace {

constexpr std::uint32_t kPaper = 0xFFFFFF;
constexpr std::uint32_t kSilhouetteInk = 0x000000;
constexpr std::uint32_t kCreaseInk = 0x808080;

}  // namespace

void linesRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
               std::int32_t end_row, std::span<std::uint8_t> rgb) {
  forEachStyledPixel(frame, first_row, end_row, pass.rule, rgb, [](std::uint32_t, Edge edge) {
    return edge == Edge::kSilhouette ? kSilhouetteInk : edge == Edge::kCrease ? kCreaseInk : kPaper;
  });
}

}  // namespace octopoint
