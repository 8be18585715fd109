// Smooth splats' last step (octopoint/smooth.h, docs/splats.md "Smooth splats"): a frame's
// blended colours, left packed in the red sums by SmoothSplats::finish, and its box colours
// elsewhere, to RGB or RGB565; and renderSmooth, the box frame and its blend in one call.

#include <cstring>

#include "octopoint/smooth.h"

namespace octopoint {
namespace {

std::size_t resolvedPixelCount(std::int32_t width, std::int32_t height) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

bool SmoothSplats::resolveToRgb(const FrameView& frame, const PaletteRgb& palette, Rgb background,
                                std::span<std::uint8_t> rgb) const {
  if (width_ == 0 || frame.width() != width_ || frame.height() > height_ ||
      rgb.size() < resolvedPixelCount(width_, frame.height()) * 3) {
    return false;
  }
  const std::span<const std::uint32_t> words = frame.pixels();
  const auto width = static_cast<std::size_t>(width_);
  // Pixels [begin, end) of row `row_at`: palette colours of the box frame, or the blended ones.
  const auto resolveRun = [&](std::size_t row_at, std::int32_t begin, std::int32_t end,
                              bool blended) {
    for (std::size_t at = row_at + static_cast<std::size_t>(begin),
                     stop = row_at + static_cast<std::size_t>(end);
         at < stop; ++at) {
      const std::uint32_t word = words[at];
      Rgb colour = background;
      if (word != FrameView::kEmpty) {
        if (blended) {
          const std::uint32_t packed = sums_[at].r;
          colour = {static_cast<std::uint8_t>(packed >> 16), static_cast<std::uint8_t>(packed >> 8),
                    static_cast<std::uint8_t>(packed)};
        } else {
          colour = palette[FrameView::colourIndexOf(word)];
        }
      }
      rgb[3 * at + 0] = colour.r;
      rgb[3 * at + 1] = colour.g;
      rgb[3 * at + 2] = colour.b;
    }
  };
  for (std::int32_t y = 0; y < frame.height(); ++y) {
    const std::size_t row_at = static_cast<std::size_t>(y) * width;
    if (!blended_ || y < blended_rect_.y_begin || y >= blended_rect_.y_end) {
      resolveRun(row_at, 0, width_, false);
      continue;
    }
    resolveRun(row_at, 0, blended_rect_.x_begin, false);
    resolveRun(row_at, blended_rect_.x_begin, blended_rect_.x_end, true);
    resolveRun(row_at, blended_rect_.x_end, width_, false);
  }
  return true;
}

bool SmoothSplats::resolveToRgb565(const FrameView& frame, const Rgb565Palette& palette,
                                   std::uint8_t* out) const {
  if (width_ == 0 || frame.width() != width_ || frame.height() > height_) return false;
  const std::uint32_t* const words = frame.pixels().data();
  const std::size_t count = resolvedPixelCount(width_, frame.height());
  if (!blended_ || blended_rect_.empty()) {
    packedToRgb565(words, count, palette, out);
    return true;
  }
  // In place as packedToRgb565 (`out` may be the words' memory): pixel i's word and sums are read
  // before its halfword lands in bytes 2i and 2i + 1, which no later pixel's word occupies. Every
  // covered pixel lies in the blended rectangle (finish), where its colour is the blend's.
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t word = words[i];
    std::uint16_t colour = palette.background;
    if (word != FrameView::kEmpty) {
      const std::uint32_t packed = sums_[i].r;
      colour =
          toRgb565({static_cast<std::uint8_t>(packed >> 16), static_cast<std::uint8_t>(packed >> 8),
                    static_cast<std::uint8_t>(packed)});
    }
    std::memcpy(out + 2 * i, &colour, 2);
  }
  return true;
}

bool renderSmooth(Variant variant, const LevelView& level, const FrameSetup& setup,
                  FrameView& frame, SmoothSplats& smooth, const PaletteRgb& palette,
                  const std::atomic<bool>* abort) {
  // Pass 1 needs the footprints: a variant that sets one pixel per leaf finds no nearest depth
  // where a magnified voxel's other pixels lie.
  if (setup.splat.active() && !drawsSplats(variant)) return false;
  // The frame's payload is the buffers' to check (fits): kColourNormal needs them made for normals.
  if (smooth.width() != frame.width() || smooth.height() < frame.height()) return false;
  return renderLevel(variant, level, setup, frame, abort) &&
         smooth.blend(level, setup, frame, palette, abort);
}

}  // namespace octopoint
