#pragma once
// How fixed_fast (and fixed_simd on the frame's edge) writes a leaf's footprint splat
// (octopoint/camera.h): its packed word into every pixel of a columns x rows rectangle,
// z-tested per pixel by the same unsigned min as a single pixel, so the frame still does not
// depend on the order leaves are drawn in. Two flavours, as FixedPlot: clipped per pixel to the
// framebuffer it is given (a band of a frame, too), and unchecked for subtrees that SubtreeClip,
// widened by the splat, proved to lie on screen. The unchecked flavour writes footprints of up to
// 4 x 4 pixels as their whole box, unrolled (renderer/splat_box.h): the loops' exits, a leaf's
// one or two columns, were a coin toss per leaf.

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "octopoint/camera.h"
#include "renderer/framebuffer_plot.h"
#include "renderer/splat_box.h"

namespace octopoint {

struct SplatPlot : PlotTarget {
  SplatPlot(FrameView& frame, const FrameSetup& setup)
      : PlotTarget(frame, setup),
        footprint(setup.splat),
        box(setup.splat.columns <= kMostBoxSide && setup.splat.rows <= kMostBoxSide
                ? (setup.splat.rows - 1) * kMostBoxSide + setup.splat.columns - 1
                : kNoBox),
        box_last_first(width * height - ((setup.splat.rows - 1) * width + setup.splat.columns)) {}

  // Writes `word` (Framebuffer::packLeaf) over columns [x_begin, x_end) and rows [y_begin, y_end),
  // clipped to the frame when kChecked.
  template <bool kChecked>
  void fill(std::int32_t x_begin, std::int32_t x_end, std::int32_t y_begin, std::int32_t y_end,
            std::uint32_t word) const {
    if constexpr (kChecked) {
      x_begin = std::max<std::int32_t>(x_begin, 0);
      x_end = std::min(x_end, width);
      y_begin = std::max<std::int32_t>(y_begin, 0);
      y_end = std::min(y_end, height);
    } else {
      assert(x_begin >= 0 && x_end <= width && y_begin >= 0 && y_end <= height);
    }
    for (std::int32_t y = y_begin; y < y_end; ++y) {
      std::uint32_t* const row =
          pixel + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
      for (std::int32_t x = x_begin; x < x_end; ++x) row[x] = std::min(row[x], word);
    }
  }

  // The splat of a leaf at `p` (Q(32-F).F) whose payload (renderer/leaf_cursor.h) is `payload`.
  // buildFrameSetup checked that p + offset + span fits 32 bits.
  template <bool kChecked, PixelPayload kPayload = PixelPayload::kColour>
  void plot(const Vec3& p, std::uint32_t payload) const {
    const std::int32_t x = p.x + footprint.offset_x;
    const std::int32_t y = p.y + footprint.offset_y;
    const std::uint32_t word = Framebuffer::packLeaf<kPayload>(depthKey(p.z), payload);
    if constexpr (kChecked) {
      fill<true>(x >> fraction_bits, ((x + footprint.span_x) >> fraction_bits) + 1,
                 y >> fraction_bits, ((y + footprint.span_y) >> fraction_bits) + 1, word);
    } else {
      plotByKernel(x, y, word);
    }
  }

  // Which kernel writes this frame's unchecked splats (plotUnchecked): the box of the footprint,
  // box = (rows - 1) * kMostBoxSide + columns - 1, or kNoBox for footprints past 4 x 4.
  static constexpr int kNoBox = -1;

  // Calls `draw` with std::integral_constant<int, K>, K this frame's box kernel if it is one of
  // kBox..., kNoBox otherwise: one jump per call, and the kernel a constant inside it, for a
  // caller that draws one leaf (plot) or a whole subtree (fixed_fast) by it.
  template <int... kBox, typename Draw>
  __attribute__((always_inline)) void withBoxKernel(std::integer_sequence<int, kBox...>,
                                                    Draw&& draw) const {
    if (!((box == kBox ? (draw(std::integral_constant<int, kBox>{}), true) : false) || ...)) {
      draw(std::integral_constant<int, kNoBox>{});
    }
  }

  // The unchecked splat whose first pixel is at (x, y), Q(32-F).F (a leaf's position plus the
  // footprint's offset), of packed word `word`, by kernel kBox (withBoxKernel: the caller chooses
  // it once, not per leaf).
  template <int kBox>
  __attribute__((always_inline)) void plotUnchecked(std::int32_t x, std::int32_t y,
                                                    std::uint32_t word) const {
    const std::int32_t x_begin = x >> fraction_bits,
                       x_end = ((x + footprint.span_x) >> fraction_bits) + 1;
    const std::int32_t y_begin = y >> fraction_bits,
                       y_end = ((y + footprint.span_y) >> fraction_bits) + 1;
    if constexpr (kBox != kNoBox) {
      // On screen: the index fits 32 bits (at most 8192^2 pixels).
      const std::uint32_t at =
          static_cast<std::uint32_t>(y_begin) * static_cast<std::uint32_t>(width) +
          static_cast<std::uint32_t>(x_begin);
      // The box may reach one column or row past the leaf's rectangle: not past the frame's end.
      if (static_cast<std::int32_t>(at) <= box_last_first) {
        constexpr int kColumns = kBox % kMostBoxSide + 1, kRows = kBox / kMostBoxSide + 1;
        minBox<kColumns, kRows>(pixel + at, static_cast<std::size_t>(width), word,
                                shortOf<kColumns>(x_end - x_begin),
                                shortOf<kRows>(y_end - y_begin));
        return;
      }
    }
    fill<false>(x_begin, x_end, y_begin, y_end, word);
  }

  SplatFootprint footprint;

 private:
  // plotUnchecked by this frame's kernel, chosen per leaf: one function whatever the payload or
  // caller, not a copy of the 16 kernels' dispatch inlined into each (about 3.3 KB of Thumb code).
  void plotByKernel(std::int32_t x, std::int32_t y, std::uint32_t word) const {
    withBoxKernel(
        std::make_integer_sequence<int, kMostBoxSide * kMostBoxSide>{},
        [&](auto kernel)
            __attribute__((always_inline)) { plotUnchecked<decltype(kernel)::value>(x, y, word); });
  }

  int box;  // which box kernel, or kNoBox for footprints past 4 x 4
  // The last first pixel whose box ends inside the frame: width * height minus the box's reach,
  // (rows - 1) * width + columns; below 0 when no box fits.
  std::int32_t box_last_first;
};

}  // namespace octopoint
