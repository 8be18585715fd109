#include "codegen/sample_reach.h"

#include <algorithm>
#include <array>
#include <vector>

#include "codegen/voxelizer.h"

namespace octopoint::prepare {
namespace {

// A level seen along one axis: which cells (2^shift cells per voxel edge) some voxel covers.
class AxisView {
 public:
  AxisView(std::span<const std::uint64_t> keys, int depth, std::size_t axis, int shift)
      : side_(std::size_t{1} << (depth + shift)), covered_(side_ * side_, 0) {
    const std::size_t u_axis = axis == 0 ? 1 : 0, v_axis = axis == 2 ? 1 : 2;
    const std::size_t cells = std::size_t{1} << shift;
    for (const std::uint64_t key : keys) {
      const std::array<std::uint32_t, 3> at = mortonDecode(key, depth);
      for (std::size_t dv = 0; dv < cells; ++dv) {
        std::uint8_t* row = &covered_[(at[v_axis] * cells + dv) * side_ + at[u_axis] * cells];
        std::fill(row, row + cells, std::uint8_t{1});
      }
    }
  }
  std::size_t side() const { return side_; }
  bool covered(std::size_t u, std::size_t v) const { return covered_[v * side_ + u] != 0; }

 private:
  std::size_t side_;
  std::vector<std::uint8_t> covered_;
};

// Per cell, the Chebyshev distance to the nearest covered cell, capped at `cap` (separable: the
// distance along each row, then the least max(|dv|, row distance) over the rows within the cap).
std::vector<std::uint8_t> distanceToCovered(const AxisView& view, int cap) {
  const std::size_t side = view.side();
  const auto capped = static_cast<std::uint8_t>(cap);
  std::vector<std::uint8_t> along_row(side * side, capped);
  for (std::size_t v = 0; v < side; ++v) {
    std::uint8_t* row = &along_row[v * side];
    std::uint8_t run = capped;
    for (std::size_t u = 0; u < side; ++u) {
      run = view.covered(u, v) ? 0 : static_cast<std::uint8_t>(std::min(cap, run + 1));
      row[u] = run;
    }
    run = capped;
    for (std::size_t u = side; u-- > 0;) {
      run = row[u] == 0 ? 0 : static_cast<std::uint8_t>(std::min(cap, run + 1));
      row[u] = std::min(row[u], run);
    }
  }
  std::vector<std::uint8_t> distance(side * side, capped);
  for (std::size_t v = 0; v < side; ++v) {
    for (std::size_t u = 0; u < side; ++u) {
      std::uint8_t best = along_row[v * side + u];
      for (int dv = 1; dv < best; ++dv) {
        const auto step = static_cast<std::uint8_t>(dv);
        if (v >= static_cast<std::size_t>(dv))
          best = std::min(best, std::max(step, along_row[(v - step) * side + u]));
        if (v + static_cast<std::size_t>(dv) < side)
          best = std::min(best, std::max(step, along_row[(v + step) * side + u]));
      }
      distance[v * side + u] = best;
    }
  }
  return distance;
}

}  // namespace

std::int32_t measureSampleReach(std::span<const std::uint64_t> keys, int depth,
                                std::span<const std::uint64_t> coarse_keys, int coarse_depth) {
  if (depth > kMaxMeasuredDepth || coarse_depth >= depth) return 16;
  // Judged in the view that sees the most of the coarse surface: the one the surface faces. The
  // other two see it edge-on, where a coarse voxel's cube fills what the scan never sampled (the
  // walls between a roof and the ground below).
  std::uint64_t best_surface = 0;
  std::array<std::uint64_t, kMaxSampleGap + 1> best_missed{};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const AxisView fine(keys, depth, axis, 1);
    const AxisView coarse(coarse_keys, coarse_depth, axis, 0);
    const std::vector<std::uint8_t> distance = distanceToCovered(fine, 2 * kMaxSampleGap);
    const int scale = depth + 1 - coarse_depth;  // fine cells per coarse cell: 2^scale
    std::uint64_t surface = 0;
    std::array<std::uint64_t, kMaxSampleGap + 1> missed{};
    for (std::size_t cv = 1; cv + 1 < coarse.side(); ++cv) {
      for (std::size_t cu = 1; cu + 1 < coarse.side(); ++cu) {
        bool inside = true;
        for (std::size_t dv = 0; dv < 3 && inside; ++dv)
          for (std::size_t du = 0; du < 3 && inside; ++du)
            inside = coarse.covered(cu + du - 1, cv + dv - 1);
        if (!inside) continue;
        for (std::size_t v = cv << scale; v < (cv + 1) << scale; ++v) {
          for (std::size_t u = cu << scale; u < (cu + 1) << scale; ++u) {
            ++surface;
            // A reach of R footprints covers the cells within R - 1 of a leaf's own.
            const int d = distance[v * fine.side() + u];
            for (int reach = 1; reach <= kMaxSampleGap && reach - 1 < d; ++reach)
              ++missed[static_cast<std::size_t>(reach)];
          }
        }
      }
    }
    if (surface > best_surface) {
      best_surface = surface;
      best_missed = missed;
    }
  }
  for (int reach = 1; reach <= kMaxSampleGap; ++reach) {
    if (best_missed[static_cast<std::size_t>(reach)] * 1000 <= best_surface * kHoleShareLimitPerMille)
      return 16 * reach;
  }
  return 16 * kMaxSampleGap;
}

}  // namespace octopoint::prepare
