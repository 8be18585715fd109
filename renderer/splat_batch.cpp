#include "renderer/splat_batch.h"

#include "renderer/splat_box.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <utility>

namespace octopoint {
namespace {

constexpr std::uint32_t kEmptyWord = 0xFFFF'FFFF;  // Framebuffer::kEmpty: min with it keeps a pixel

std::int32_t columnsOf(std::uint32_t extent) { return static_cast<std::int32_t>(extent & 0xFFFF); }
std::int32_t rowsOf(std::uint32_t extent) { return static_cast<std::int32_t>(extent >> 16); }

// Point i's rectangle, pixel by pixel: where a box or chunk would pass the frame's last pixel.
void plotExact(const SplatBatch& b, int i) {
  const std::uint32_t word = b.word[i];
  const std::int32_t columns = columnsOf(b.extent[i]);
  std::uint32_t* row = b.pixel + b.index[i];
  for (std::int32_t r = rowsOf(b.extent[i]); r > 0; --r, row += b.width) {
    for (std::int32_t x = 0; x < columns; ++x) row[x] = std::min(row[x], word);
  }
}

// Point i's kColumns x kRows box (see the header): unrolled scalar mins.
template <int kColumns, int kRows>
__attribute__((always_inline)) inline void plotBox(const SplatBatch& b, int i) {
  const std::size_t at = b.index[i];
  if (at + (kRows - 1) * b.width + kColumns > b.end) {
    plotExact(b, i);
    return;
  }
  minBox<kColumns, kRows>(b.pixel + at, b.width, b.word[i],
                          shortOf<kColumns>(columnsOf(b.extent[i])),
                          shortOf<kRows>(rowsOf(b.extent[i])));
}

// Footprints of 1 or 2 columns and up to 4 rows (fixed_simd emits those of up to 4 pixels as
// single pixels: this writes 2 x 3 and 2 x 4).
template <int kColumns, int kRows>
void plotSmall(const SplatBatch& b) {
  const int half = b.count / 2;
  for (int i = 0; i < half; ++i) {  // the two halves in turn: two independent chains
    plotBox<kColumns, kRows>(b, i);
    plotBox<kColumns, kRows>(b, half + i);
  }
  if (b.count % 2 != 0) plotBox<kColumns, kRows>(b, b.count - 1);
}

// Footprints of 3 or 4 columns and up to 4 rows: point i's box of four columns and kRows rows,
// one four-pixel vector min per row; the lanes at or past the point's columns, and its last row
// when it has one fewer, get kEmpty. Overlapping vectors of neighbours (see the header) still cost
// less than four scalar mins per row: docs/splats.md "Small footprints".
template <int kRows>
__attribute__((target("avx2"), always_inline)) inline void plotQuadBox(const SplatBatch& b, int i,
                                                                       __m128i lane) {
  const std::size_t at = b.index[i];
  if (at + (kRows - 1) * b.width + 4 > b.end) {
    plotExact(b, i);
    return;
  }
  const __m128i word =
      _mm_or_si128(_mm_set1_epi32(static_cast<std::int32_t>(b.word[i])),
                   _mm_cmpgt_epi32(lane, _mm_set1_epi32(columnsOf(b.extent[i]) - 1)));
  const __m128i last_word = _mm_or_si128(
      word, _mm_set1_epi32(static_cast<std::int32_t>(shortOf<kRows>(rowsOf(b.extent[i])))));
  std::uint32_t* row = b.pixel + at;
  for (int r = 0; r < kRows; ++r, row += b.width) {
    auto* chunk = reinterpret_cast<__m128i*>(row);
    _mm_storeu_si128(chunk,
                     _mm_min_epu32(_mm_loadu_si128(chunk), r + 1 == kRows ? last_word : word));
  }
}

template <int kRows>
__attribute__((target("avx2"))) void plotQuad(const SplatBatch& b) {
  const __m128i lane = _mm_setr_epi32(0, 1, 2, 3);
  const int half = b.count / 2;
  for (int i = 0; i < half; ++i) {  // the two halves in turn: two independent chains
    plotQuadBox<kRows>(b, i, lane);
    plotQuadBox<kRows>(b, half + i, lane);
  }
  if (b.count % 2 != 0) plotQuadBox<kRows>(b, b.count - 1, lane);
}

// Footprints of 5 to 8 columns, or taller than 4: one eight-pixel vector min per row, no loop over
// the row's chunks (plotWide's per-row loop and tail test cost about 20 instructions a row); the
// lanes at or past the point's columns get kEmpty. A point whose last row's vector would reach
// past the frame's last pixel is written exactly.
__attribute__((target("avx2"))) void plotEightWide(const SplatBatch& b) {
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  for (int i = 0; i < b.count; ++i) {
    const std::int32_t columns = columnsOf(b.extent[i]);
    const std::int32_t rows = rowsOf(b.extent[i]);
    const std::size_t at = b.index[i];
    if (at + static_cast<std::size_t>(rows - 1) * b.width + 8 > b.end) {
      plotExact(b, i);
      continue;
    }
    const __m256i word = _mm256_or_si256(_mm256_set1_epi32(static_cast<std::int32_t>(b.word[i])),
                                         _mm256_cmpgt_epi32(lane, _mm256_set1_epi32(columns - 1)));
    std::uint32_t* row = b.pixel + at;
    for (std::int32_t r = 0; r < rows; ++r, row += b.width) {
      auto* chunk = reinterpret_cast<__m256i*>(row);
      _mm256_storeu_si256(chunk, _mm256_min_epu32(_mm256_loadu_si256(chunk), word));
    }
  }
}

// Footprints wider than 8: eight pixels of a row per vector min, the row's chunks in a loop.
__attribute__((target("avx2"))) void plotWide(const SplatBatch& b) {
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  for (int i = 0; i < b.count; ++i) {
    const std::uint32_t word_value = b.word[i];
    const __m256i word = _mm256_set1_epi32(static_cast<std::int32_t>(word_value));
    const std::int32_t columns = columnsOf(b.extent[i]);
    const std::int32_t rows = rowsOf(b.extent[i]);
    const std::int32_t full = columns & ~7;
    // The last chunk's lanes at or past the rectangle's end get kEmpty: they keep their pixels.
    const __m256i tail_word =
        _mm256_or_si256(word, _mm256_cmpgt_epi32(lane, _mm256_set1_epi32(columns - full - 1)));
    std::size_t at = b.index[i];
    for (std::int32_t r = 0; r < rows; ++r, at += b.width) {
      std::uint32_t* const row = b.pixel + at;
      for (std::int32_t x = 0; x < full; x += 8) {
        auto* chunk = reinterpret_cast<__m256i*>(row + x);
        _mm256_storeu_si256(chunk, _mm256_min_epu32(_mm256_loadu_si256(chunk), word));
      }
      if (full == columns) continue;
      if (at + static_cast<std::size_t>(full) + 8 <= b.end) {
        auto* chunk = reinterpret_cast<__m256i*>(row + full);
        _mm256_storeu_si256(chunk, _mm256_min_epu32(_mm256_loadu_si256(chunk), tail_word));
      } else {
        for (std::int32_t x = full; x < columns; ++x) row[x] = std::min(row[x], word_value);
      }
    }
  }
}

constexpr int kMostScalar = 2;  // columns of the scalar boxes; up to kMostBoxSide rows

template <int... kIndex>
constexpr std::array<SplatBatchPlot, sizeof...(kIndex)> scalarKernels(
    std::integer_sequence<int, kIndex...>) {
  return {&plotSmall<kIndex % kMostScalar + 1, kIndex / kMostScalar + 1>...};
}
// kScalar[(rows - 1) * kMostScalar + columns - 1]
constexpr auto kScalar =
    scalarKernels(std::make_integer_sequence<int, kMostScalar * kMostBoxSide>{});
constexpr std::array<SplatBatchPlot, kMostBoxSide> kQuad = {&plotQuad<1>, &plotQuad<2>,
                                                            &plotQuad<3>, &plotQuad<4>};

}  // namespace

SplatBatchPlot splatBatchPlot(std::int32_t columns, std::int32_t rows) {
  assert(columns >= 1 && rows >= 1);
  if (columns > 8) return &plotWide;
  if (columns > kMostBoxSide || rows > kMostBoxSide) return &plotEightWide;
  if (columns > kMostScalar) return kQuad[static_cast<std::size_t>(rows - 1)];
  return kScalar[static_cast<std::size_t>((rows - 1) * kMostScalar + columns - 1)];
}

}  // namespace octopoint

#endif
