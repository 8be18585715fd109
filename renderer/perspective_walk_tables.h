#pragma once
// The perspective walk's per-frame tables (renderer/perspective_walk.h): the child offsets in
// camera space, each level's reach, the frustum's slopes and the affine thresholds, and the
// frustum test that reads them; in a header of their own so that the walk's stays small.

#include <array>
#include <cstdint>
#include <optional>

#include "octopoint/camera.h"
#include "renderer/perspective.h"

namespace octopoint {

// Per-frame tables of the walk: each level's child offsets in camera space (the walk's units,
// Q.(24 + view.walk_bits) cube edges), each level's reach (Q.24),
// the frustum's side slopes. Built once per frame and level depth (about 1.6 KB).
struct PerspectiveWalkTables {
  std::array<std::array<CameraPoint, 8>, kMaxRenderDepth> child_offset{};  // Q.(24 + walk_bits)
  std::array<std::int64_t, kMaxRenderDepth + 1> reach{};  // a node of level l: Q.24 cube edges
  // The frustum's side planes, Q2.30 slopes: the screen spans x from -left * z to right * z and y
  // from -top * z to bottom * z (left = centre_x / f, right = (width - centre_x) / f, ...: the
  // pan moves the principal point, so they differ, and one is negative when it leaves the
  // screen); INT64_MAX where a slope does not fit (that side is not tested).
  std::int64_t left_q30 = 0, right_q30 = 0, top_q30 = 0, bottom_q30 = 0;
  // Their smallProductLimit: a depth below it times the slope is one product, so that the
  // frustum test compares instead of counting bits per node (counting was most of a product's cost
  // where the product itself is one instruction, callgrind; on a Cortex-M0+ each count is a
  // library call).
  std::int64_t left_limit = 0, right_limit = 0, top_limit = 0, bottom_limit = 0;
  // The largest |x / z| and |y / z| on the screen (for the affine error bound).
  std::int64_t slope_x_q30 = 0;
  std::int64_t slope_y_q30 = 0;
  std::int64_t max_error = 0;  // Q(32-F).F pixels
  // A node of level l whose camera-space depth is at least affine_depth[b][l] is within max_error
  // of its affine map wherever it meets the frustum (b = 0), or where its centre lies within
  // max(|c.x|, |c.y|) <= c.z / 2^(b - 1) of the view's axis (b = 1 .. kAffineBuckets - 1: the
  // error bound grows with that distance, so nearer the axis a subtree qualifies nearer the eye
  // and draws more leaves from one map); see perspectiveWalkTables. One comparison per node and
  // bucket instead of affineErrorBound's divisions.
  static constexpr int kAffineBuckets = 5;
  std::array<std::array<std::int64_t, kMaxRenderDepth + 1>, kAffineBuckets> affine_depth{};
  // How much larger than the affine map's voxel a voxel of a subtree drawn from it (a node of
  // level l, depth >= affine_depth[b][l]) may be on screen: z / (z - reach) at its worst, Q.16
  // rounded up, so that no subtree divides for it.
  std::array<std::array<std::int64_t, kMaxRenderDepth + 1>, kAffineBuckets> growth_q16{};
  int depth = 0;
  // The level's sample reach (Q4 footprints, kOneSampleReach..kMaxSampleReach; docs/splats.md,
  // "Samples coarser than the voxel"): every leaf's splat half extents are widened by it
  // (widenedHalfExtent), as buildFrameSetup widens the orthographic splat, so that a level whose
  // samples lie farther apart than its voxels draws whole.
  std::int32_t sample_reach = kOneSampleReach;
  // How far a widened splat may reach beyond the leaf's own voxel, in camera space (Q.24 cube
  // edges): the frustum and band tests widen every node's box by it, so that a leaf whose voxel
  // lies outside but whose splat reaches in is still drawn. 0 at one footprint.
  std::int64_t splat_margin = 0;
};

// Whether the box of centre `c` and half extent `reach` (camera units) lies wholly behind the near
// plane `near` or beyond one of the frustum's side planes; conservative by a unit (the products
// round to nearest). A side's extent at depth z is its slope times z: within the box widest at its
// far depth for a positive slope, at its nearest depth in front of the near plane for a negative.
inline bool outsideFrustumSides(const PerspectiveWalkTables& tables, const CameraPoint& c,
                                std::int64_t reach, std::int64_t near) {
  const std::int64_t far_z = c.z + reach;
  if (far_z < near) return true;
  const std::int64_t near_z = c.z - reach > near ? c.z - reach : near;
  // mulShiftRoundQuick(slope >= 0 ? far_z : near_z, slope, 30), the slope's bits counted once a
  // frame: the same bits.
  const auto extent = [&](std::int64_t slope_q30, std::int64_t limit) {
    return mulShiftRoundLimited(slope_q30 >= 0 ? far_z : near_z, slope_q30, limit, 30);
  };
  const std::optional<std::int64_t> left = extent(tables.left_q30, tables.left_limit);
  const std::optional<std::int64_t> right = extent(tables.right_q30, tables.right_limit);
  const std::optional<std::int64_t> top = extent(tables.top_q30, tables.top_limit);
  const std::optional<std::int64_t> bottom = extent(tables.bottom_q30, tables.bottom_limit);
  return (right && c.x - reach > *right + 1) || (left && c.x + reach < -*left - 1) ||
         (bottom && c.y - reach > *bottom + 1) || (top && c.y + reach < -*top - 1);
}

// PerspectiveWalkTables::splat_margin of a level of `depth` (1..kMaxRenderDepth) whose sample
// reach is `sample_reach` (Q4): 0 at one footprint.
std::int64_t perspectiveSplatMargin(int depth, std::int32_t sample_reach);

// `max_error` in Q(32-F).F pixels, >= 0; depth 1..kMaxRenderDepth; `sample_reach` the level's
// (Q4, kOneSampleReach..kMaxSampleReach; ModelView::sampleReach).
PerspectiveWalkTables perspectiveWalkTables(const PerspectiveView& view, int depth,
                                            std::int64_t max_error,
                                            std::int32_t sample_reach = kOneSampleReach);

}  // namespace octopoint
