#include "renderer/perspective_detail.h"

#include <cassert>

#include "octopoint/fixed.h"

namespace octopoint {

PerspectiveDetail perspectiveDetail(const PerspectiveView& view, std::span<const int> depths,
                                    int coarser, std::uint32_t pixels_q8) {
  assert(pixels_q8 >= kOnePixelQ8 && pixels_q8 <= (std::uint32_t{1} << 24));
  assert(!depths.empty() && depths.size() <= format::kMaxLevels);
  assert(coarser >= 0 && coarser <= 8);
  PerspectiveDetail detail;
  detail.count = static_cast<int>(depths.size());
  for (std::size_t i = 0; i < depths.size(); ++i) {
    const int depth = depths[i];
    assert(depth >= 1 && depth <= kMaxRenderDepth && (i == 0 || depth > depths[i - 1]));
    detail.depth[i] = depth;
    // e <= p pixels <=> z * 2^16 * p >= f_q16 * 2^(24 - depth) <=> z >= f_q16 * 2^(16 - depth) /
    // p_q8 (Q.24; f below 2^32 in Q.16 and depth >= 1, so the product fits), rounded up: with
    // p = 1 exactly f_q16 * 2^(8 - depth), rounded up.
    // divideUnsigned: no division helper on a Cortex-M (include/octopoint/fixed.h).
    const auto scaled = static_cast<std::uint64_t>(view.focal_q16) << (16 - depth);
    detail.near_enough[i] =
        static_cast<std::int64_t>(divideUnsigned(scaled + pixels_q8 - 1, pixels_q8).quotient);
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
