#pragma once
// The perspective walk over one level (docs/perspective.md): down the tree in camera space, where
// the rotation keeps every step an addition; a subtree wholly outside the frustum or behind the
// near plane is passed over; a subtree whose affine map is within `max_error` of the projection
// (affineErrorBound) is drawn from that map with per-level screen vectors, additions only, as the
// orthographic decoders do; a leaf reached before any such subtree is projected exactly.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "renderer/bit_scan.h"
#include "renderer/perspective.h"

namespace octopoint {

// A leaf as the walk hands it over: its index in the level's leaf stream (and payload: palette
// index, and normal index << 8 when the level has normals and the walk reads them), its screen
// position in Q(32-F).F pixels (int64: a leaf may lie far off the screen) and its camera-space
// depth in Q.24 cube edges.
struct PerspectiveLeaf {
  std::size_t index = 0;
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
  // Half the voxel's projected extent per screen axis, Q(32-F).F: from the affine map of the
  // subtree it was drawn with, or at the leaf itself (0 when even that cannot be had).
  std::int64_t half_x = 0;
  std::int64_t half_y = 0;
};

// The sum of an affine map's axis vectors' magnitudes, per axis: the extent of the shadow of a
// cube of edge 1 (screen x and y in Q(32-F).F, depth in Q.24).
inline Point3<std::int64_t> cubeShadow(const AffineProjection& affine) {
  const auto& a = affine.axis;
  const auto sum = [](std::int64_t p, std::int64_t q, std::int64_t r) {
    return (p < 0 ? -p : p) + (q < 0 ? -q : q) + (r < 0 ? -r : r);
  };
  return {sum(a[0].x, a[1].x, a[2].x), sum(a[0].y, a[1].y, a[2].y), sum(a[0].z, a[1].z, a[2].z)};
}

// Half the projected extent of a voxel of `depth` under an affine map whose cube's shadow is
// `shadow`, per screen axis: the shadow over 2^(depth + 1), rounded up.
inline Point3<std::int64_t> voxelHalfExtent(const Point3<std::int64_t>& shadow, int depth) {
  const std::int64_t round_up = (std::int64_t{1} << (depth + 1)) - 1;
  return {(shadow.x + round_up) >> (depth + 1), (shadow.y + round_up) >> (depth + 1), 0};
}

// A subtree the walk draws from one affine map, announced to a sink that has enterAffine (and
// leaveAffine, called when its last leaf was handed over): every leaf it hands over meanwhile
// lies within `reach_x`, `reach_y` (Q(32-F).F) and `reach_z` (Q.24) of `centre`, and has the
// half extents `half_x`, `half_y`. A sink may then drop what it checks per leaf.
struct AffineSubtree {
  Point3<std::int64_t> centre;
  std::int64_t reach_x = 0, reach_y = 0, reach_z = 0;
  std::int64_t half_x = 0, half_y = 0;
};

// Per-frame tables of the walk: each level's child offsets in camera space, each level's reach,
// the frustum's side slopes. Built once per frame and level depth (about 1.6 KB).
struct PerspectiveWalkTables {
  std::array<std::array<CameraPoint, 8>, kMaxRenderDepth> child_offset{};
  std::array<std::int64_t, kMaxRenderDepth + 1> reach{};  // a node of level l: Q.24 cube edges
  std::int64_t slope_x_q30 = 0;  // (width / 2) / f: the frustum's side planes are x = +-slope * z
  std::int64_t slope_y_q30 = 0;
  std::int64_t max_error = 0;  // Q(32-F).F pixels
  // A node of level l whose camera-space depth is at least affine_depth[l] is within max_error of
  // its affine map wherever it meets the frustum (see perspectiveWalkTables): one comparison per
  // node instead of affineErrorBound's divisions.
  std::array<std::int64_t, kMaxRenderDepth + 1> affine_depth{};
  // How much larger than the affine map's voxel a voxel of a subtree drawn from it (a node of
  // level l, depth >= affine_depth[l]) may be on screen: z / (z - reach) at its worst, Q.16
  // rounded up, so that no subtree divides for it.
  std::array<std::int64_t, kMaxRenderDepth + 1> growth_q16{};
  int depth = 0;
};

// `max_error` in Q(32-F).F pixels, >= 0; depth 1..kMaxRenderDepth.
PerspectiveWalkTables perspectiveWalkTables(const PerspectiveView& view, int depth,
                                            std::int64_t max_error);

// Calls sink(const PerspectiveLeaf&) for every leaf in front of the near plane whose subtree
// meets the frustum, in stream order. Returns false when `abort` was set (checked per subtree).
template <typename Sink>
class PerspectiveWalk {
 public:
  PerspectiveWalk(const LevelView& level, const PerspectiveView& view,
                  const PerspectiveWalkTables& tables, Sink& sink,
                  const std::atomic<bool>* abort = nullptr)
      : view_(view), tables_(tables), sink_(sink), abort_(abort), node_(level.nodes.data()) {}

  bool run() {
    // The root's centre is the model's origin.
    visit(0, toCameraSpace(view_, ModelPoint{0, 0, 0}));
    return !aborted_;
  }

 private:
  void visit(int level, const CameraPoint& centre) {
    if (level == tables_.depth) {
      if (const std::optional<ScreenPoint> p = project(view_, centre)) {
        const std::optional<AffineProjection> affine = affineAt(view_, centre);
        const Point3<std::int64_t> half =
            affine ? voxelHalfExtent(cubeShadow(*affine), tables_.depth) : Point3<std::int64_t>{};
        sink_(PerspectiveLeaf{leaf_, p->x, p->y, p->z, half.x, half.y});
      }
      ++leaf_;
      return;
    }
    if (abort_ != nullptr && abort_->load(std::memory_order_relaxed)) aborted_ = true;
    const std::uint8_t mask = *node_++;
    const std::int64_t reach = tables_.reach[static_cast<std::size_t>(level)];
    if (aborted_ || outsideFrustum(centre, reach)) {
      skipChildren(level, mask);
      return;
    }
    if (centre.z >= tables_.affine_depth[static_cast<std::size_t>(level)] &&
        centre.z - reach >= view_.camera.near) {
      if (const std::optional<AffineProjection> affine = affineAt(view_, centre)) {
        drawAffine(level, mask, *affine);
        return;
      }
    }
    const auto& offsets = tables_.child_offset[static_cast<std::size_t>(level)];
    for (unsigned k = 0; k < 8; ++k) {
      if (mask & (1u << k)) {
        const CameraPoint& o = offsets[k];
        visit(level + 1, {centre.x + o.x, centre.y + o.y, centre.z + o.z});
      }
    }
  }

  // Wholly behind the near plane, or wholly beyond one of the four side planes: every point of
  // the box has x >= centre.x - reach and z <= centre.z + reach, so centre.x - reach >
  // slope * (centre.z + reach) puts it right of the plane x = slope * z whatever its z.
  bool outsideFrustum(const CameraPoint& c, std::int64_t reach) const {
    const std::int64_t far_z = c.z + reach;
    if (far_z < view_.camera.near) return true;
    const std::optional<std::int64_t> side_x = mulShiftRoundQuick(far_z, tables_.slope_x_q30, 30);
    const std::optional<std::int64_t> side_y = mulShiftRoundQuick(far_z, tables_.slope_y_q30, 30);
    // Rounded to nearest: one unit less keeps the test conservative.
    return (side_x && (c.x - reach > *side_x + 1 || c.x + reach < -*side_x - 1)) ||
           (side_y && (c.y - reach > *side_y + 1 || c.y + reach < -*side_y - 1));
  }

  void skipChildren(int level, std::uint8_t mask) {
    for (unsigned k = 0; k < 8; ++k) {
      if (mask & (1u << k)) skipNode(level + 1);
    }
  }
  void skipNode(int level) {
    if (level == tables_.depth) {
      ++leaf_;
      return;
    }
    skipChildren(level, *node_++);
  }

  // The subtree below a node of `level` whose children are `mask`, from the affine map at its
  // centre: per level m below, eight screen vectors, each the sum of the map's three axis vectors
  // with the child's signs times 2^-(m+2) (a child of a node of level m lies 2^-(m+2) cube edges
  // from it along each axis), rounded once; child 7 - k is child k mirrored (every sign flipped),
  // so four are made and four negated. No division.
  void drawAffine(int level, std::uint8_t mask, const AffineProjection& affine) {
    const auto& a = affine.axis;
    // Children 0 to 3 (x's sign -): -a0 -+ a1 -+ a2.
    const Point3<std::int64_t> down = sub(neg(a[0]), a[1]), up = add(neg(a[0]), a[1]);
    const Point3<std::int64_t> sums[4] = {sub(down, a[2]), add(down, a[2]), sub(up, a[2]),
                                          add(up, a[2])};
    for (int m = level; m < tables_.depth; ++m) {
      // roundShiftRight, with the half added once per level (the sums are far below 2^62).
      const int shift = m + 2;
      const std::int64_t half = std::int64_t{1} << (shift - 1);
      auto& offsets = screen_offset_[static_cast<std::size_t>(m)];
      for (unsigned k = 0; k < 4; ++k) {
        const std::int64_t x = (sums[k].x + half) >> shift, y = (sums[k].y + half) >> shift,
                           z = (sums[k].z + half) >> shift;
        offsets[k] = {x, y, z};
        offsets[7 - k] = {-x, -y, -z};
      }
    }
    // The map's voxel is the size at the centre's depth; nearer voxels of the subtree are larger,
    // by up to z / (z - reach) (growth_q16): widened by that much, the subtree's splats leave no
    // crack.
    const Point3<std::int64_t> shadow = cubeShadow(affine);
    const Point3<std::int64_t> half = voxelHalfExtent(shadow, tables_.depth);
    const std::int64_t growth_q16 = tables_.growth_q16[static_cast<std::size_t>(level)];
    half_ = {(half.x * growth_q16 >> 16) + 1, (half.y * growth_q16 >> 16) + 1, 0};
    const Point3<std::int64_t> centre{affine.centre.x, affine.centre.y, affine.centre.z};
    if constexpr (requires { sink_.enterAffine(AffineSubtree{}); }) {
      // Every leaf of the subtree lies within the sum of the levels' largest vectors of its
      // centre: the cube's shadow over 2^(m+2) for m from `level`, each rounded (half a unit,
      // counted as one).
      const std::int64_t levels = tables_.depth - level;
      sink_.enterAffine(AffineSubtree{centre, (shadow.x >> (level + 1)) + levels,
                                      (shadow.y >> (level + 1)) + levels,
                                      (shadow.z >> (level + 1)) + levels, half_.x, half_.y});
    }
    visitAffine(level, mask, centre);
    if constexpr (requires { sink_.leaveAffine(); }) sink_.leaveAffine();
  }
  // A node of a subtree drawn from its affine map, at `p`, its children `mask`: set-bit
  // iteration over them, and a leaf parent hands its leaves over in one loop (no call per leaf).
  void visitAffine(int level, unsigned mask, const Point3<std::int64_t>& p) {
    const auto& offsets = screen_offset_[static_cast<std::size_t>(level)];
    if (level + 1 == tables_.depth) {
      for (unsigned bits = mask; bits != 0; bits &= bits - 1) {
        const Point3<std::int64_t>& d = offsets[lowestChild(bits)];
        sink_(PerspectiveLeaf{leaf_++, p.x + d.x, p.y + d.y, p.z + d.z, half_.x, half_.y});
      }
      return;
    }
    for (unsigned bits = mask; bits != 0; bits &= bits - 1) {
      const unsigned child_mask = *node_++;
      visitAffine(level + 1, child_mask, add(p, offsets[lowestChild(bits)]));
    }
  }
  static Point3<std::int64_t> add(const Point3<std::int64_t>& a, const Point3<std::int64_t>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  static Point3<std::int64_t> sub(const Point3<std::int64_t>& a, const Point3<std::int64_t>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  static Point3<std::int64_t> neg(const Point3<std::int64_t>& a) { return {-a.x, -a.y, -a.z}; }

  const PerspectiveView& view_;
  const PerspectiveWalkTables& tables_;
  Sink& sink_;
  const std::atomic<bool>* abort_;
  const std::uint8_t* node_;
  std::size_t leaf_ = 0;
  bool aborted_ = false;
  // The screen vectors of the subtree drawn from its affine map: Q(32-F).F, depth in Q.24.
  std::array<std::array<Point3<std::int64_t>, 8>, kMaxRenderDepth> screen_offset_{};
  Point3<std::int64_t> half_{};  // voxelHalfExtent of that subtree, widened for its nearest voxels
};

}  // namespace octopoint

namespace octopoint {

// The depth key a perspective leaf writes: camera-space z in units of 2^-14 cube edge (z >> 10),
// which keeps every z the eye can see (below 2^33.5 units) within FrameView::kMaxDepthKey.
inline constexpr int kPerspectiveDepthShift = 10;

// Draws `level` into `frame` (cleared by the caller): each leaf covers the pixels whose centres lie
// within its voxel's projected extent (padded by the rounding), or its one pixel where that
// extent holds no pixel centre; its position is within `max_error` plus depth / 2 units in the
// last place of its exact projection. False when aborted.
bool drawPerspective(const LevelView& level, const PerspectiveView& view,
                     const PerspectiveWalkTables& tables, FrameView& frame,
                     const std::atomic<bool>* abort = nullptr);

}  // namespace octopoint
