#pragma once
// Samples coarser than the voxel (docs/splats.md, "Samples coarser than the voxel"): how far a
// level's splats must reach so that the scan's own sample spacing leaves no holes between its
// voxels. Airborne lidar samples on scan lines about a metre apart: a depth whose voxels are finer
// than that has rows of empty voxels between rows of occupied ones, and box splats one voxel wide
// draw them as a grid of empty lines.
//
// Measured the way a frame shows it: the level's voxels seen along each of the three axes, in
// cells of half a voxel edge, against the surface the coarsest level covers seen the same way
// (its cells whose eight neighbours are covered too: a coarse voxel's cube reaches past the
// surface's own edge by up to one). A splat widened to R voxel footprints (octopoint/camera.h,
// sample_reach 16 R) covers the cells within R - 1 half-voxels of a leaf's own two (Chebyshev
// distance). The reach is the least R that leaves at most kHoleShareLimitPerMille of that surface
// uncovered in every view: one footprint for a densely sampled level, so its frames stay what
// they were.

#include <cstdint>
#include <span>

namespace octopoint::prepare {

inline constexpr int kMaxSampleGap = 8;  // reach up to 8 footprints: kMaxSampleReach
inline constexpr std::uint64_t kHoleShareLimitPerMille = 5;
// Views of 2^(depth + 1) cells a side: finer levels are not measured (reach one footprint).
inline constexpr int kMaxMeasuredDepth = 11;

// The reach (16, 32, .. 16 kMaxSampleGap: Q4 voxel footprints) the voxels `keys` (Morton keys of
// `depth`, codegen/voxelizer.h, ascending) need against the surface of `coarse_keys` (of
// `coarse_depth` < depth); 16 when depth > kMaxMeasuredDepth.
std::int32_t measureSampleReach(std::span<const std::uint64_t> keys, int depth,
                                std::span<const std::uint64_t> coarse_keys, int coarse_depth);

}  // namespace octopoint::prepare
