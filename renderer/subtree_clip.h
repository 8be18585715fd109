#pragma once
// Hierarchical clipping (fixed_clipped, fixed_fast): whether all leaves of a subtree land on
// screen, all off screen, or some of each, decided once per node instead of once per leaf.
//
// Leaves of a node at tree level l lie within reach[l] = sum over l' >= l of max_k |offset[l'][k]|
// of its centre, per axis (Q(32-F).F). Screen edges are kept in 64 bits: width << F does not fit 32
// bits at F = 24.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>

#include "renderer/camera.h"

namespace octopoint {

enum class Clip { kOutside, kInside, kStraddling };

class SubtreeClip {
 public:
  explicit SubtreeClip(const FrameSetup& setup)
      : x_end_(std::int64_t{setup.width} << setup.fraction_bits),
        y_end_(std::int64_t{setup.height} << setup.fraction_bits) {
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
    if (centre.x + rx < 0 || centre.x - rx >= x_end_ || centre.y + ry < 0 || centre.y - ry >= y_end_) {
      return Clip::kOutside;
    }
    if (centre.x - rx >= 0 && centre.x + rx < x_end_ && centre.y - ry >= 0 && centre.y + ry < y_end_) {
      return Clip::kInside;
    }
    return Clip::kStraddling;
  }

 private:
  std::int64_t x_end_, y_end_;
  std::array<std::int64_t, format::kMaxDepth> reach_x_{}, reach_y_{};
};

}  // namespace octopoint
