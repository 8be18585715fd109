// The colour style: each covered pixel takes its palette colour, as the scan was captured.
#include "octopoint/styles.h"

namespace octopoint {

void colourRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                std::int32_t end_row, std::span<std::uint8_t> rgb) {
  const std::int32_t width = frame.width();
  const std::uint32_t* word =
      frame.pixels().data() + static_cast<std::ptrdiff_t>(first_row) * width;
  const std::uint32_t* const end =
      frame.pixels().data() + static_cast<std::ptrdiff_t>(end_row) * width;
  auto at = static_cast<std::size_t>(first_row) * static_cast<std::size_t>(width);
  for (std::uint8_t* out = rgb.data(); word != end; ++word, ++at, out += 3) {
    storeRgb(out, *word == Framebuffer::kEmpty ? pass.background : pass.colourAt(*word, at));
  }
}

}  // namespace octopoint
