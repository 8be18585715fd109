#include <bit>

#include "octopoint/framebuffer.h"

namespace octopoint {
namespace {

static_assert(FrameView::colourIndexOf(FrameView::kEmpty) == 255,
              "an empty word reads as palette index 255");

// The stores go through a may_alias type: `out` may alias the words, so the compiler must keep
// each word's read before the stores that may overwrite it; both accesses stay aligned single
// loads and stores (byte copies would cost a Cortex-M0+ ten instructions a pixel).
using AliasingHalfword [[gnu::may_alias]] = std::uint16_t;
using AliasingWord [[gnu::may_alias]] = std::uint32_t;

// Any palette: empty words get the background. Four pixels a step with constant offsets (one
// loop test per four, which a Cortex-M0+ pays per instruction). Halfword i covers bytes 2i and
// 2i + 1, below word i + 1's, so converting word by word in place is safe.
void convertTestingEmpty(const std::uint32_t* words, std::size_t count,
                         const Rgb565Palette& palette, AliasingHalfword* to) {
  const auto* from = reinterpret_cast<const AliasingWord*>(words);
  const std::uint16_t* const colour = palette.colour.data();
  const std::uint16_t background = palette.background;
  const auto convert = [&](std::uint32_t word) {
    return word == FrameView::kEmpty ? background : colour[static_cast<std::uint8_t>(word)];
  };
  const AliasingHalfword* const end = to + count;
  for (; end - to >= 4; from += 4, to += 4) {
    to[0] = convert(from[0]);
    to[1] = convert(from[1]);
    to[2] = convert(from[2]);
    to[3] = convert(from[3]);
  }
  for (; to != end; ++from, ++to) *to = convert(*from);
}

// A palette whose index 255 is the background: one table load per pixel, the index read as the
// word's low byte (little-endian: its first byte), eight pixels a step with constant offsets. On
// a Cortex-M0+ that is four instructions a pixel (ldrb, lsls, ldrh, strh) and half a one of loop.
// Pixel i's index byte (4i) lies at or past the bytes halfword i - 1 and earlier wrote (< 2i), so
// reading bytes and writing halfwords in this order is safe in place; char reads alias anything.
void convertByIndexByte(const std::uint32_t* words, std::size_t count, const Rgb565Palette& palette,
                        AliasingHalfword* to) {
  const auto* index = reinterpret_cast<const std::uint8_t*>(words);
  const std::uint16_t* const colour = palette.colour.data();
  const AliasingHalfword* const end = to + count;
  for (; end - to >= 8; index += 32, to += 8) {
    to[0] = colour[index[0]];
    to[1] = colour[index[4]];
    to[2] = colour[index[8]];
    to[3] = colour[index[12]];
    to[4] = colour[index[16]];
    to[5] = colour[index[20]];
    to[6] = colour[index[24]];
    to[7] = colour[index[28]];
  }
  for (; to != end; index += 4, ++to) *to = colour[*index];
}

}  // namespace

Rgb565Palette makeRgb565Palette(const ModelView& model, Rgb background) {
  Rgb565Palette palette;
  for (int i = 0; i < model.paletteCount(); ++i) {
    palette.colour[static_cast<std::size_t>(i)] = toRgb565(model.paletteColour(i));
  }
  palette.background = toRgb565(background);
  palette.last_index_unused = model.paletteCount() < 256;
  if (palette.last_index_unused) palette.colour[255] = palette.background;
  return palette;
}

void packedToRgb565(const std::uint32_t* words, std::size_t count, const Rgb565Palette& palette,
                    std::uint8_t* out) {
  auto* to = static_cast<AliasingHalfword*>(static_cast<void*>(out));
  if (std::endian::native == std::endian::little && palette.last_index_unused &&
      palette.colour[255] == palette.background) {
    convertByIndexByte(words, count, palette, to);
  } else {
    convertTestingEmpty(words, count, palette, to);
  }
}

}  // namespace octopoint
