#include "renderer/perspective_detail.h"

#include <cassert>

namespace octopoint {

PerspectiveDetail perspectiveDetail(const PerspectiveView& view, std::span<const int> depths,
                                    int coarser) {
  assert(!depths.empty() && depths.size() <= format::kMaxLevels);
  assert(coarser >= 0 && coarser <= 8);
  PerspectiveDetail detail;
  detail.count = static_cast<int>(depths.size());
  for (std::size_t i = 0; i < depths.size(); ++i) {
    const int depth = depths[i];
    assert(depth >= 1 && depth <= kMaxRenderDepth && (i == 0 || depth > depths[i - 1]));
    detail.depth[i] = depth;
    // e <= 1 pixel <=> z * 2^16 >= f_q16 * 2^(24 - depth) <=> z >= f_q16 * 2^(8 - depth) (Q.24;
    // f below 2^32 in Q.16, so the product fits).
    detail.near_enough[i] =
        depth <= 8 ? view.focal_q16 << (8 - depth)
                   : (view.focal_q16 + (std::int64_t{1} << (depth - 8)) - 1) >> (depth - 8);
  }
  detail.coarser = coarser;
  detail.finest = detail.count - 1;
  const int finest = depths.back();
  for (int level = 0; level <= kMaxRenderDepth; ++level) {
    // Half a node's edge, rotated, plus the rounding its centre gathers on the way down (one unit
    // per level, as perspectiveWalkTables counts it for the finest depth).
    const std::int64_t half = std::int64_t{1} << (kPerspectiveUnitBits - 1 - level);
    detail.reach[static_cast<std::size_t>(level)] = rotatedCubeReach(half) + finest;
  }
  return detail;
}

}  // namespace octopoint
