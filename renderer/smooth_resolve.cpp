// Smooth splats' last step (octopoint/smooth.h, docs/splats.md "Smooth splats"): a frame's
// blended colours, left packed in the red sums by SmoothSplats::finish, and its box colours
// elsewhere, to RGB or RGB565; and renderSmooth, the box frame and its blend in one call.

#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define OCTOPOINT_RESOLVE_AVX2 1
#endif

#include "octopoint/smooth.h"

namespace octopoint {
namespace {

std::size_t resolvedPixelCount(std::int32_t width, std::int32_t height) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

#ifdef OCTOPOINT_RESOLVE_AVX2
// The blended run's first pixels, eight at a time while two more pixels follow in the run (each
// step stores 32 bytes, of which the last 8 are the next pixels', written again after it):
// a covered pixel's colour packed 0x00RRGGBB in its red sum (SmoothSplats::finish), `background`
// where the word is kEmpty, as the scalar loop gives them. Returns the pixels done.
__attribute__((target("avx2"))) std::size_t resolveBlendedAvx2(const std::uint32_t* words,
                                                               const SmoothSplats::Sums* sums,
                                                               std::size_t count, Rgb background,
                                                               std::uint8_t* rgb) {
  const __m256i empty = _mm256_set1_epi32(-1);
  const __m256i fill = _mm256_set1_epi32(static_cast<int>(
      std::uint32_t{background.r} << 16 | std::uint32_t{background.g} << 8 | background.b));
  const __m256i to_pixels = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);  // lanes 0 2 4 6 1 3 5 7
  // 0x00RRGGBB to R G B bytes, four pixels per 128-bit half (12 bytes, then 4 zero bytes).
  const __m256i to_bytes = _mm256_setr_epi8(2, 1, 0, 6, 5, 4, 10, 9, 8, 14, 13, 12, -1, -1, -1, -1,
                                            2, 1, 0, 6, 5, 4, 10, 9, 8, 14, 13, 12, -1, -1, -1, -1);
  std::size_t i = 0;
  for (; i + 10 <= count; i += 8) {
    const __m256i word = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(words + i));
    const auto* const sum_at = reinterpret_cast<const __m256i*>(sums + i);
    const __m256i low = _mm256_unpacklo_epi32(_mm256_loadu_si256(sum_at),
                                              _mm256_loadu_si256(sum_at + 1));  // r0 r2 . . r1 r3
    const __m256i high = _mm256_unpacklo_epi32(_mm256_loadu_si256(sum_at + 2),
                                               _mm256_loadu_si256(sum_at + 3));  // r4 r6 . . r5 r7
    const __m256i packed = _mm256_permutevar8x32_epi32(_mm256_unpacklo_epi64(low, high), to_pixels);
    const __m256i colour = _mm256_blendv_epi8(packed, fill, _mm256_cmpeq_epi32(word, empty));
    const __m256i bytes = _mm256_shuffle_epi8(colour, to_bytes);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(rgb + 3 * i), _mm256_castsi256_si128(bytes));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(rgb + 3 * i + 12),
                     _mm256_extracti128_si256(bytes, 1));
  }
  return i;
}
#endif

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
  [[maybe_unused]] const bool avx2 = simdDecoderAvailable();
  for (std::int32_t y = 0; y < frame.height(); ++y) {
    const std::size_t row_at = static_cast<std::size_t>(y) * width;
    if (!blended_ || y < blended_rect_.y_begin || y >= blended_rect_.y_end) {
      resolveRun(row_at, 0, width_, false);
      continue;
    }
    resolveRun(row_at, 0, blended_rect_.x_begin, false);
    std::int32_t from = blended_rect_.x_begin;
#ifdef OCTOPOINT_RESOLVE_AVX2
    if (avx2) {
      const std::size_t at = row_at + static_cast<std::size_t>(from);
      from += static_cast<std::int32_t>(resolveBlendedAvx2(
          words.data() + at, sums_.data() + at,
          static_cast<std::size_t>(blended_rect_.x_end - from), background, rgb.data() + 3 * at));
    }
#endif
    resolveRun(row_at, from, blended_rect_.x_end, true);
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
