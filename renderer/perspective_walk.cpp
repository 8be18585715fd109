#include "renderer/perspective_walk.h"

#include <algorithm>
#include <cassert>

namespace octopoint {

PerspectiveWalkTables perspectiveWalkTables(const PerspectiveView& view, int depth,
                                            std::int64_t max_error) {
  assert(depth >= 1 && depth <= kMaxRenderDepth && max_error >= 0);
  PerspectiveWalkTables tables;
  tables.depth = depth;
  tables.max_error = max_error;
  const auto& m = view.world_to_camera.m_q30;
  for (int level = 0; level < depth; ++level) {
    // A child of a node of `level` lies 2^-(level+2) cube edges = 2^(22-level) units from it along
    // each model axis: the rotated sum in Q1.30, shifted to units once.
    for (unsigned k = 0; k < 8; ++k) {
      const std::int64_t s[3] = {(k & 4) ? 1 : -1, (k & 2) ? 1 : -1, (k & 1) ? 1 : -1};
      std::int64_t c[3];
      for (int row = 0; row < 3; ++row) {
        c[row] = roundShiftRight(m[row][0] * s[0] + m[row][1] * s[1] + m[row][2] * s[2],
                                 30 - (kPerspectiveUnitBits - 2 - level));
      }
      tables.child_offset[static_cast<std::size_t>(level)][k] = {c[0], c[1], c[2]};
    }
  }
  for (int level = 0; level <= depth; ++level) {
    // Half a node's edge, rotated, plus the rounding its centre gathered on the way (half a unit
    // per level and the rotation's few Q30 ulp: one unit per level).
    const std::int64_t half = std::int64_t{1} << (kPerspectiveUnitBits - 1 - level);
    tables.reach[static_cast<std::size_t>(level)] = rotatedCubeReach(half) + depth;
  }
  tables.slope_x_q30 =
      divShiftRound(std::int64_t{view.camera.width} << 15, view.focal_q16, 30).value_or(INT64_MAX);
  tables.slope_y_q30 =
      divShiftRound(std::int64_t{view.camera.height} << 15, view.focal_q16, 30).value_or(INT64_MAX);
  return tables;
}

bool drawPerspective(const LevelView& level, const PerspectiveView& view,
                     const PerspectiveWalkTables& tables, FrameView& frame,
                     const std::atomic<bool>* abort) {
  const int fraction_bits = view.fraction_bits;
  const auto plot = [&](const PerspectiveLeaf& leaf) {
    const std::int64_t x = leaf.x >> fraction_bits, y = leaf.y >> fraction_bits;
    if (x < 0 || y < 0 || x >= frame.width() || y >= frame.height()) return;
    const std::uint32_t key = static_cast<std::uint32_t>(
        std::min<std::int64_t>(leaf.z >> kPerspectiveDepthShift, FrameView::kMaxDepthKey));
    frame.plot(static_cast<std::int32_t>(x), static_cast<std::int32_t>(y), key,
               level.leaves[leaf.index]);
  };
  PerspectiveWalk<decltype(plot)> walk(level, view, tables, plot, abort);
  return walk.run();
}

}  // namespace octopoint
