#pragma once
// The loop of the line styles (lines, toon, outlined): every pixel of some rows of a frame, with
// its class from the line pass (renderer/edges.h), painted into RGB888. Internal to the style
// passes (renderer/style_passes.h).
//
// What it costs is what the frame holds: rows and columns outside the frame's drawn rectangle
// (FrameView::drawnRect, where every pixel is background) are filled with the background colour
// without being looked at; inside it, the frame's inner pixels go through a loop without bounds
// tests and without branches on the normals (paintInnerRun), the frame's first and last rows and
// columns through classifyPixel. Every pixel gets exactly the class classifyPixel defines
// (tests/edges_fast_path_test.cpp compares them).

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>

#include "renderer/edges.h"
#include "renderer/framebuffer.h"

namespace octopoint {

inline void storeRgb(std::uint8_t* out, std::uint32_t rgb) {
  out[0] = static_cast<std::uint8_t>(rgb >> 16);
  out[1] = static_cast<std::uint8_t>(rgb >> 8);
  out[2] = static_cast<std::uint8_t>(rgb);
}

// `count` pixels of RGB888 colour `rgb` (0xRRGGBB) from `out` on: four pixels (12 bytes) a step,
// copied from a pattern, so a run of background costs under one store per pixel.
inline void fillRgb(std::uint8_t* out, std::int32_t count, std::uint32_t rgb) {
  std::uint8_t pattern[12];
  for (int i = 0; i < 12; i += 3) storeRgb(pattern + i, rgb);
  std::int32_t i = 0;
  for (; i + 4 <= count; i += 4, out += 12) std::memcpy(out, pattern, 12);
  for (; i < count; ++i, out += 3) storeRgb(out, rgb);
}

namespace styled_rows_detail {

// Whether normals n and the one of `neighbour`'s word are a crease pair (0 or 1); 0 for a
// neighbour of the same index (CreaseTable::build) and, without a table, always.
template <bool kCreases>
inline std::uint32_t creaseBit(const CreaseTable* creases, std::uint32_t n,
                               std::uint32_t neighbour) {
  if constexpr (kCreases) {
    return creases->crease(n, Framebuffer::normalIndexOf(neighbour)) ? 1u : 0u;
  } else {
    return 0u;
  }
}

// Pixels [x, x_end) of inner row y of a kColourNormal frame (1 <= x, x_end <= width - 1, rows
// above and below present), painted. What classifyPixel decides,
// with the words compared whole:
// - A neighbour's key (word >> 16) exceeds depth + jump exactly when its word exceeds
//   (depth + jump) << 16 | 0xFFFF. Where depth + jump reaches 0xFFFF no key exceeds it, and the
//   limit is 0xFFFFFEFF, the largest real word (normal indices stop at 254), which only kEmpty
//   exceeds. So one comparison of the largest of the four neighbour words finds both a
//   background neighbour and one farther than the jump; a neighbour farther than the jump but
//   no background (a few percent of the covered pixels, on steep surfaces) goes through
//   classifyPixel, which asks whether the pair's surface slope explains it (SurfaceSlopes).
// - p draws the crease it shares with q when q is farther (left, above: key > depth, i.e. word >
//   word | 0xFFFF) or as far (right, below: word >= word & 0xFFFF0000). Where the left, upper
//   and lower neighbours have p's normal index (most pixels where splats cover several), only
//   the right pair can be a crease (CreaseTable: none with itself); otherwise the look-ups and
//   side tests go without branches. A pair's look-up is symmetric: the one with the right
//   neighbour is kept for the next pixel's left pair. A pixel these find a crease for (under 1%
//   of the covered pixels) goes through classifyPixel, which also asks whether the pair's other
//   pixel is a silhouette.
template <bool kCreases, typename Paint>
void paintInnerRun(const FrameView& frame, std::int32_t y, std::int32_t x, std::int32_t x_end,
                   const EdgeRule& rule, std::uint32_t background, std::uint8_t* out,
                   Paint& paint) {
  const std::ptrdiff_t stride = frame.width();
  const std::uint32_t* const row = frame.pixels().data() + y * stride;
  const CreaseTable* creases = rule.creases;
  const std::uint32_t* const above = row - stride;
  const std::uint32_t* const below = row + stride;
  constexpr std::uint32_t kLargestWord = 0xFFFF'FEFFu, kNormalBits = 0xFF00u;
  // creaseBit of pixel x - 1 with pixel x (read only when both are covered)
  std::uint32_t left_pair =
      creaseBit<kCreases>(creases, Framebuffer::normalIndexOf(row[x - 1]), row[x]);
  for (; x < x_end; ++x) {
    const std::uint32_t word = row[x];
    std::uint8_t* const pixel_out = out + static_cast<std::ptrdiff_t>(x) * 3;
    if (word == Framebuffer::kEmpty) {
      // A run of background; the pixel after it, if covered, is a silhouette: left_pair unread.
      std::int32_t end = x + 1;
      while (end < x_end && row[end] == Framebuffer::kEmpty) ++end;
      fillRgb(pixel_out, end - x, background);
      x = end - 1;
      continue;
    }
    const std::uint32_t l = row[x - 1], r = row[x + 1], a = above[x], b = below[x];
    const std::uint32_t farthest = (word >> 16) + rule.jump;
    const std::uint32_t limit = farthest < 0xFFFFu ? farthest << 16 | 0xFFFFu : kLargestWord;
    const std::uint32_t n = Framebuffer::normalIndexOf(word);
    const std::uint32_t right_pair = creaseBit<kCreases>(creases, n, r);
    const std::uint32_t largest = std::max(std::max(l, r), std::max(a, b));
    Edge edge = Edge::kSilhouette;
    if (largest <= limit) {
      edge = Edge::kNone;
      if (kCreases && (((l ^ word) | (a ^ word) | (b ^ word)) & kNormalBits) != 0) {
        const std::uint32_t farther = word | 0xFFFFu, as_far = word & 0xFFFF'0000u;
        const std::uint32_t crease =
            (left_pair & static_cast<std::uint32_t>(l > farther)) |
            (right_pair & static_cast<std::uint32_t>(r >= as_far)) |
            (creaseBit<kCreases>(creases, n, a) & static_cast<std::uint32_t>(a > farther)) |
            (creaseBit<kCreases>(creases, n, b) & static_cast<std::uint32_t>(b >= as_far));
        if (crease != 0) edge = classifyPixel(frame, x, y, rule);
      } else if (right_pair != 0 && r >= (word & 0xFFFF'0000u)) {
        edge = classifyPixel(frame, x, y, rule);
      }
    } else if (rule.slopes != nullptr && largest != Framebuffer::kEmpty) {
      edge = classifyPixel(frame, x, y, rule);  // farther than the jump: is it the slope's?
    }
    left_pair = right_pair;
    storeRgb(pixel_out, paint(word, edge));
  }
}

}  // namespace styled_rows_detail

// Calls paint(word, edge) for every covered pixel of rows [first_row, end_row) of `frame` and
// stores the RGB888 it returns (packed 0xRRGGBB) into `rgb`, row first_row first; background pixels
// (word Framebuffer::kEmpty) get paint(kEmpty, Edge::kNone), asked once. `paint` must be a
// function of its arguments only.
template <typename Paint>
void forEachStyledPixel(const FrameView& frame, std::int32_t first_row, std::int32_t end_row,
                        const EdgeRule& rule, std::span<std::uint8_t> rgb, Paint paint) {
  const std::int32_t width = frame.width();
  const std::uint32_t* pixels = frame.pixels().data();
  const std::uint32_t background = paint(Framebuffer::kEmpty, Edge::kNone);
  const PixelRect& drawn = frame.drawnRect();
  const std::int32_t x_begin = std::max<std::int32_t>(drawn.x_begin, 0);
  const std::int32_t x_end = std::min<std::int32_t>(drawn.x_end, width);
  // The whole-word comparisons hold for kColourNormal words only (key in the top 16 bits).
  const bool words_compare = rule.key_shift == 16 && frame.payload() == PixelPayload::kColourNormal;
  for (std::int32_t y = first_row; y < end_row; ++y) {
    std::uint8_t* const out = rgb.data() + static_cast<std::ptrdiff_t>(y - first_row) * width * 3;
    if (y < drawn.y_begin || y >= drawn.y_end || x_begin >= x_end) {
      fillRgb(out, width, background);
      continue;
    }
    fillRgb(out, x_begin, background);
    fillRgb(out + static_cast<std::ptrdiff_t>(x_end) * 3, width - x_end, background);
    const std::uint32_t* row = pixels + static_cast<std::ptrdiff_t>(y) * width;
    const std::uint32_t* above = y > 0 ? row - width : nullptr;
    const std::uint32_t* below = y + 1 < frame.height() ? row + width : nullptr;
    const auto onePixel = [&](std::int32_t x) {
      const std::uint32_t word = row[x];
      storeRgb(
          out + static_cast<std::ptrdiff_t>(x) * 3,
          word == Framebuffer::kEmpty ? background : paint(word, classifyPixel(frame, x, y, rule)));
    };
    std::int32_t x = x_begin;
    if (above == nullptr || below == nullptr || !words_compare) {
      for (; x < x_end; ++x) onePixel(x);
      continue;
    }
    if (x == 0) onePixel(x++);
    const std::int32_t inner_end = std::min<std::int32_t>(x_end, width - 1);
    if (x < inner_end) {
      if (rule.creases != nullptr) {
        styled_rows_detail::paintInnerRun<true>(frame, y, x, inner_end, rule, background, out,
                                                paint);
      } else {
        styled_rows_detail::paintInnerRun<false>(frame, y, x, inner_end, rule, background, out,
                                                 paint);
      }
      x = inner_end;
    }
    if (x < x_end) onePixel(x);  // the frame's last column
  }
}

}  // namespace octopoint
