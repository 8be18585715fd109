#pragma once
// A perspective leaf's splat extent (renderer/perspective_walk.h): the voxel's projected size
// under an affine map, widened by its level's sample reach.

#include <algorithm>
#include <cstdint>

#include "octopoint/camera.h"
#include "renderer/perspective.h"

namespace octopoint {

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

// A leaf's splat half extents (Q(32-F).F) widened by the sample reach `reach` (Q4) and rounded
// up, as buildFrameSetup does: the same half at one footprint. Half extents past 2^55 (a voxel at
// the eye, millions of pixels wide) are taken as 2^55, so that the product fits.
inline constexpr std::int64_t kWidestWidenedHalf = std::int64_t{1} << 55;
inline Point3<std::int64_t> widenedHalfExtent(const Point3<std::int64_t>& half,
                                              std::int32_t reach) {
  if (reach == kOneSampleReach) return half;
  const auto widen = [reach](std::int64_t h) {
    return (std::min(h, kWidestWidenedHalf) * reach + 15) >> 4;
  };
  return {widen(half.x), widen(half.y), half.z};
}

}  // namespace octopoint
