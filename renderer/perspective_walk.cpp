#include "renderer/perspective_walk.h"

#include <algorithm>
#include <cassert>

namespace octopoint {

namespace {

constexpr std::int64_t kOneQ30 = std::int64_t{1} << 30;

// The largest q = r / z (Q.30, below 1) for which every box of reach r at depth z that meets the
// frustum is within `max_error` (Q(32-F).F) of its affine map. Such a box's centre has
// |c.x| <= s * (z + r) + r with s the larger side slope, so its bound f * r^2 * (m + z) /
// (z^2 * (z - r)) is at most g(q) = f * q^2 * (s * (1 + q) + q + 1) / (1 - q), which grows with q:
// bisection on q, every step rounded up.
std::int64_t largestAffineRatio(const PerspectiveView& view, std::int64_t slope_q30,
                                std::int64_t max_error) {
  const int f = view.fraction_bits;
  const std::int64_t limit_q16 = f >= 16 ? max_error >> (f - 16) : max_error << (16 - f);
  const auto within = [&](std::int64_t q) {
    const std::optional<std::int64_t> sides = mulShiftRound(slope_q30, kOneQ30 + q, 30);
    if (!sides) return false;
    const std::int64_t spread = *sides + q + kOneQ30 + 1;  // Q.30
    const std::optional<std::int64_t> q2 = mulShiftRound(q, q, 30);
    if (!q2) return false;
    const std::optional<std::int64_t> a = mulShiftRound(view.focal_q16, *q2 + 1, 30);
    if (!a) return false;
    const std::optional<std::int64_t> b = mulShiftRound(*a + 1, spread, 30);
    if (!b) return false;
    const std::optional<std::int64_t> g = divShiftRound(*b + 1, kOneQ30 - q, 30);
    return g && *g + 1 <= limit_q16;
  };
  std::int64_t low = 0, high = kOneQ30 - 1;  // within(low) holds (g(0) = 0 <= limit)
  while (low < high) {
    const std::int64_t mid = low + (high - low + 1) / 2;
    if (within(mid)) {
      low = mid;
    } else {
      high = mid - 1;
    }
  }
  return low;
}

}  // namespace

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
  const std::int64_t ratio =
      largestAffineRatio(view, std::max(tables.slope_x_q30, tables.slope_y_q30), max_error);
  for (int level = 0; level <= depth; ++level) {
    const std::int64_t reach = tables.reach[static_cast<std::size_t>(level)];
    // z >= r / q, rounded up; no depth at all when even the smallest ratio fails.
    tables.affine_depth[static_cast<std::size_t>(level)] =
        ratio == 0 ? INT64_MAX : divShiftRound(reach, ratio, 30).value_or(INT64_MAX - 1) + 1;
  }
  return tables;
}

namespace {

// The pixels [first, last] whose centres lie within [p - half, p + half] on one axis (Q(32-F).F),
// clipped to [0, size); the pixel p >> F alone when no centre does.
struct PixelSpan {
  std::int64_t first, last;
};
PixelSpan pixelSpan(std::int64_t p, std::int64_t half, int fraction_bits, std::int32_t size) {
  const std::int64_t one = std::int64_t{1} << fraction_bits, mid = one >> 1;
  std::int64_t first = (p - half - mid + one - 1) >> fraction_bits;
  std::int64_t last = (p + half - mid) >> fraction_bits;
  if (last < first) first = last = p >> fraction_bits;
  return {std::max<std::int64_t>(first, 0), std::min<std::int64_t>(last, size - 1)};
}

}  // namespace

bool drawPerspective(const LevelView& level, const PerspectiveView& view,
                     const PerspectiveWalkTables& tables, FrameView& frame,
                     const std::atomic<bool>* abort) {
  const int fraction_bits = view.fraction_bits;
  // How far a leaf may lie from its exact position (the affine map's error, the additions'
  // rounding): its neighbour may lie as far the other way, so each widens its splat by that much.
  const std::int64_t padding = tables.max_error + tables.depth + 1;
  // The whole frame may be written: a perspective view has no cube-sized bound to give.
  std::uint32_t* const pixels = frame.pixelData();
  const std::size_t width = static_cast<std::size_t>(frame.width());
  const auto plot = [&](const PerspectiveLeaf& leaf) {
    const PixelSpan columns =
        pixelSpan(leaf.x, leaf.half_x + padding, fraction_bits, frame.width());
    const PixelSpan rows = pixelSpan(leaf.y, leaf.half_y + padding, fraction_bits, frame.height());
    if (columns.first > columns.last || rows.first > rows.last) return;  // off the screen
    const std::uint32_t key = static_cast<std::uint32_t>(
        std::min<std::int64_t>(leaf.z >> kPerspectiveDepthShift, FrameView::kMaxDepthKey));
    const std::uint32_t word = FrameView::pack(key, level.leaves[leaf.index]);
    for (std::int64_t y = rows.first; y <= rows.last; ++y) {
      std::uint32_t* row = pixels + static_cast<std::size_t>(y) * width;
      for (std::int64_t x = columns.first; x <= columns.last; ++x) {
        if (word < row[x]) row[x] = word;
      }
    }
  };
  PerspectiveWalk<decltype(plot)> walk(level, view, tables, plot, abort);
  return walk.run();
}

}  // namespace octopoint
