#pragma once
// RGB565, the pixel format of the small SPI panels (ILI9341, ST7789) a microcontroller drives: five
// bits of red, six of green, five of blue in one 16-bit word. Band rendering
// (renderer/band_renderer.h) converts each finished band to it in place, through a 256-entry table
// built once per model at set-up, so a pixel costs one table load.

#include <array>
#include <cstddef>
#include <cstdint>

#include "renderer/framebuffer.h"
#include "renderer/model.h"

namespace octopoint {

constexpr std::uint16_t toRgb565(Rgb colour) {
  return static_cast<std::uint16_t>((colour.r >> 3) << 11 | (colour.g >> 2) << 5 | colour.b >> 3);
}

struct Rgb565Palette {
  std::array<std::uint16_t, 256> colour{};  // by palette index
  std::uint16_t background = 0;             // for pixels without a point
  // No leaf names index 255 (the model has at most 255 colours). An empty pixel's word
  // (FrameView::kEmpty) has 255 in its palette-index byte, so with colour[255] == background the
  // conversion needs no emptiness test: one table load per pixel (makeRgb565Palette sets both).
  bool last_index_unused = false;
};

Rgb565Palette makeRgb565Palette(const ModelView& model, Rgb background);

// Converts `count` packed pixel words to RGB565 halfwords in the CPU's byte order, writing halfword
// i to bytes 2i and 2i + 1 of `out` (2-byte aligned). `out` may be the words' own memory (then the
// band becomes its RGB565 image in its first half): halfword i lands in bytes a word that was
// already read held.
void packedToRgb565(const std::uint32_t* words, std::size_t count, const Rgb565Palette& palette,
                    std::uint8_t* out);

}  // namespace octopoint
