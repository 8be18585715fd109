#pragma once
// Hierarchical clipping (fixed_clipped, fixed_fast): whether all leaves of a subtree land on
// screen, all off screen, or some of each, decided once per node instead of once per leaf.
//
// Leaves of a node at tree level l lie within reach[l] = sum over l' >= l of max_k |offset[l'][k]|
// of its centre, per axis (Q(32-F).F). A leaf at p covers the pixels (p + low) >> F to
// (p + high) >> F per axis: low = high = 0 for one pixel per leaf, the splat's first and last
// pixel otherwise (renderer/splat_footprint.h), so a subtree is on screen when its reach widened by
// them is. Screen edges are kept in 64 bits: width << F does not fit 32 bits at F = 24.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>

#include "renderer/camera.h"

namespace octopoint {

enum class Clip { kOutside, kInside, kStraddling };

class SubtreeClip {
 public:
  // `splat`: the footprint the decoder draws (one pixel per leaf by default).
  explicit SubtreeClip(const FrameSetup& setup, const SplatFootprint& splat = SplatFootprint{})
      : x_end_(std::int64_t{setup.width} << setup.fraction_bits),
        y_end_(std::int64_t{setup.height} << setup.fraction_bits),
        low_x_(splat.offset_x),
        low_y_(splat.offset_y),
        high_x_(std::int64_t{splat.offset_x} + splat.span_x),
        high_y_(std::int64_t{splat.offset_y} + splat.span_y) {
    std::int64_t x = 0, y = 0;
    for (int l = setup.depth - 1; l >= 0; --l) {
      std::int64_t widest_x = 0, widest_y = 0;
      for (const Vec3& d : setup.child_offset[static_cast<std::size_t>(l)]) {
        widest_x = std::max<std::int64_t>(widest_x, std::llabs(d.x));
        widest_y = std::max<std::int64_t>(widest_y, std::llabs(d.y));
      }
      reach_x_[static_cast<std::size_t>(l)] = x += widest_x;
      reach_y_[static_cast<std::size_t>(l)] = y += widest_y;
    }
  }

  Clip classify(int level, const Vec3& centre) const {
    const std::int64_t rx = reach_x_[static_cast<std::size_t>(level)];
    const std::int64_t ry = reach_y_[static_cast<std::size_t>(level)];
    const std::int64_t left = centre.x - rx + low_x_, right = centre.x + rx + high_x_;
    const std::int64_t top = centre.y - ry + low_y_, bottom = centre.y + ry + high_y_;
    if (right < 0 || left >= x_end_ || bottom < 0 || top >= y_end_) return Clip::kOutside;
    if (left >= 0 && right < x_end_ && top >= 0 && bottom < y_end_) return Clip::kInside;
    return Clip::kStraddling;
  }

 private:
  std::int64_t x_end_, y_end_;
  std::int64_t low_x_, low_y_, high_x_, high_y_;
  std::array<std::int64_t, kMaxRenderDepth> reach_x_{}, reach_y_{};
};

}  // namespace octopoint
