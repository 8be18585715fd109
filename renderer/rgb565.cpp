#include "renderer/rgb565.h"

#include <cstring>

namespace octopoint {

Rgb565Palette makeRgb565Palette(const ModelView& model, Rgb background) {
  Rgb565Palette palette;
  for (int i = 0; i < model.paletteCount(); ++i) {
    palette.colour[static_cast<std::size_t>(i)] = toRgb565(model.paletteColour(i));
  }
  palette.background = toRgb565(background);
  return palette;
}

void packedToRgb565(const std::uint32_t* words, std::size_t count, const Rgb565Palette& palette,
                    std::uint8_t* out) {
  for (std::size_t i = 0; i < count; ++i) {
    std::uint32_t word;
    // Byte copies: `out` may alias `words`, and memcpy tells the compiler so (the reads of word i
    // stay before the writes of halfwords 2i and 2i + 1).
    std::memcpy(&word, reinterpret_cast<const std::uint8_t*>(words) + 4 * i, 4);
    const std::uint16_t pixel = word == FrameView::kEmpty ? palette.background
                                                          : palette.colour[FrameView::colourIndexOf(word)];
    std::memcpy(out + 2 * i, &pixel, 2);
  }
}

}  // namespace octopoint
