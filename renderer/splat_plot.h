#pragma once
// How fixed_fast (and fixed_simd on the frame's edge) writes a leaf's footprint splat
// (renderer/splat_footprint.h): its packed word into every pixel of a columns x rows rectangle,
// z-tested per pixel by the same unsigned min as a single pixel, so the frame still does not
// depend on the order leaves are drawn in. Two flavours, as FixedPlot: clipped per pixel to the
// framebuffer it is given (a band of a frame, too), and unchecked for subtrees that SubtreeClip,
// widened by the splat, proved to lie on screen.

#include <algorithm>
#include <cassert>
#include <cstdint>

#include "renderer/framebuffer_plot.h"
#include "renderer/splat_footprint.h"

namespace octopoint {

struct SplatPlot : PlotTarget {
  SplatPlot(FrameView& frame, const FrameSetup& setup) : PlotTarget(frame, setup), footprint(setup.splat) {}

  // Writes `word` (Framebuffer::pack) over columns [x_begin, x_end) and rows [y_begin, y_end),
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
      std::uint32_t* const row = pixel + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
      for (std::int32_t x = x_begin; x < x_end; ++x) row[x] = std::min(row[x], word);
    }
  }

  // The splat of a leaf at `p` (Q(32-F).F). buildFrameSetup checked that p + offset + span fits
  // 32 bits.
  template <bool kChecked>
  void plot(const Vec3& p, std::uint8_t palette_index) const {
    const std::int32_t x = p.x + footprint.offset_x;
    const std::int32_t y = p.y + footprint.offset_y;
    fill<kChecked>(x >> fraction_bits, ((x + footprint.span_x) >> fraction_bits) + 1, y >> fraction_bits,
                   ((y + footprint.span_y) >> fraction_bits) + 1, Framebuffer::pack(depthKey(p.z), palette_index));
  }

  SplatFootprint footprint;
};

}  // namespace octopoint
