#pragma once
// A leaf's footprint splat written as the footprint's whole box (octopoint/camera.h): a
// leaf covers the footprint's columns x rows, or one column (row) fewer, by where it falls. For
// small footprints the box is written unrolled, with no branch on the leaf's own counts: its last
// column (row) takes the min with the leaf's word or'ed with all ones when the leaf is one column
// (row) short, i.e. with kEmpty, which keeps the pixel as it is. So the frame is exactly the
// leaf's rectangle's. Used by fixed_fast (renderer/splat_plot.h) and fixed_simd's box kernel
// (renderer/splat_batch.cpp); the caller checks the box stays inside the frame's pixels.

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace octopoint {

inline constexpr int kMostBoxSide = 4;  // boxes up to 4 x 4 are unrolled

// All ones when `count` < `most` (the leaf has one column or row fewer than the box), else 0.
template <int kMost>
std::uint32_t shortOf(std::int32_t count) {
  return static_cast<std::uint32_t>((count - kMost) >> 31);
}

// Mins `word` into the kColumns x kRows box whose first pixel is `first`, rows `width` apart.
template <int kColumns, int kRows>
__attribute__((always_inline)) inline void minBox(std::uint32_t* first, std::size_t width,
                                                  std::uint32_t word, std::uint32_t short_column,
                                                  std::uint32_t short_row) {
  std::uint32_t* row = first;
  for (int r = 0; r < kRows; ++r, row += width) {
    const std::uint32_t row_word = r + 1 == kRows ? word | short_row : word;
    for (int x = 0; x < kColumns; ++x) {
      const std::uint32_t pixel_word = x + 1 == kColumns ? row_word | short_column : row_word;
      row[x] = std::min(row[x], pixel_word);
    }
  }
}

}  // namespace octopoint
