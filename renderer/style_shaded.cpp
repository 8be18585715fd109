// The shaded style: colour (a uniform grey for a scan without colour) times the intensity of the
// pixel's normal under this frame's light (octopoint/styles.h). Two table look-ups and two
// multiplies per pixel; nothing in the decoder changes.
#include "octopoint/styles.h"

namespace octopoint {

void shadedRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                std::int32_t end_row, std::span<std::uint8_t> rgb) {
  const std::int32_t width = frame.width();
  const std::uint32_t* word =
      frame.pixels().data() + static_cast<std::ptrdiff_t>(first_row) * width;
  const std::uint32_t* const end =
      frame.pixels().data() + static_cast<std::ptrdiff_t>(end_row) * width;
  auto at = static_cast<std::size_t>(first_row) * static_cast<std::size_t>(width);
  for (std::uint8_t* out = rgb.data(); word != end; ++word, ++at, out += 3) {
    const std::uint32_t w = *word;
    storeRgb(out, w == Framebuffer::kEmpty
                      ? pass.background
                      : scaledRgb(pass.colourAt(w, at), pass.intensityAt(w, at)));
  }
}

}  // namespace octopoint
