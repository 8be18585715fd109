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

template <int kColumns, int kRows>
void plotSmall(const SplatBatch& b) {
  const int half = b.count / 2;
  for (int i = 0; i < half; ++i) {  // the two halves in turn: two independent chains
    plotBox<kColumns, kRows>(b, i);
    plotBox<kColumns, kRows>(b, half + i);
  }
  if (b.count % 2 != 0) plotBox<kColumns, kRows>(b, b.count - 1);
}

// Footprints wider or taller than 4: eight pixels of a row per vector min.
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

constexpr int kMostSmall = kMostBoxSide;

template <int... kIndex>
constexpr std::array<SplatBatchPlot, sizeof...(kIndex)> smallKernels(
    std::integer_sequence<int, kIndex...>) {
  return {&plotSmall<kIndex % kMostSmall + 1, kIndex / kMostSmall + 1>...};
}
// kSmall[(rows - 1) * 4 + columns - 1]
constexpr auto kSmall = smallKernels(std::make_integer_sequence<int, kMostSmall * kMostSmall>{});

}  // namespace

SplatBatchPlot splatBatchPlot(std::int32_t columns, std::int32_t rows) {
  assert(columns >= 1 && rows >= 1);
  if (columns > kMostSmall || rows > kMostSmall) return &plotWide;
  return kSmall[static_cast<std::size_t>((rows - 1) * kMostSmall + columns - 1)];
}

}  // namespace octopoint

#endif
