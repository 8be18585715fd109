#include "renderer/rgb565.h"

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
  // `out` may alias `words`: the halfword stores go through a may_alias type, so the compiler keeps
  // each word's read before the stores that may overwrite it, and both accesses stay aligned
  // single loads and stores (byte copies would cost a Cortex-M0+ ten instructions a pixel).
  using AliasingHalfword [[gnu::may_alias]] = std::uint16_t;
  using AliasingWord [[gnu::may_alias]] = std::uint32_t;
  const auto* from = reinterpret_cast<const AliasingWord*>(words);
  auto* to = static_cast<AliasingHalfword*>(static_cast<void*>(out));
  const auto convert = [&](std::uint32_t word) {
    return word == FrameView::kEmpty ? palette.background : palette.colour[FrameView::colourIndexOf(word)];
  };
  // Two pixels a step: half the loop overhead, which a Cortex-M0+ pays per instruction.
  std::size_t i = 0;
  for (; i + 1 < count; i += 2) {
    const std::uint32_t first = from[i], second = from[i + 1];
    to[i] = convert(first);
    to[i + 1] = convert(second);
  }
  if (i < count) to[i] = convert(from[i]);
}

}  // namespace octopoint
