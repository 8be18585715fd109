#pragma once
// Samples coarser than the voxel (docs/splats.md, "Samples coarser than the voxel"): how far a
// level's splats must reach so that the scan's own sample spacing leaves no holes between its
// voxels. Airborne lidar samples on scan lines about a metre apart: a depth whose voxels are finer
// than that has rows of empty voxels between rows of occupied ones, and box splats one voxel wide
// draw them as a grid of empty lines.
//
// Measured the way a frame shows it: the level's voxels seen along each of the three axes, in
// cells of half a voxel edge, against the surface the next coarser level covers as it draws
// (its voxels widened by its own reach, less one coarse voxel around every cell it leaves empty:
// a coarse voxel's cube reaches past the surface's own edge by up to one). So a hole the scan
// really has (a shadow, a gap between objects) is judged at the coarser level's size and not
// blamed on the finer one; only what the finer level leaves open where the coarser one draws a
// surface counts. A splat widened to R voxel footprints (octopoint/camera.h, sample_reach 16 R)
// covers the cells within R - 1 half-voxels (Chebyshev distance) of a leaf's own two. The reach
// is the least R that leaves at most kHoleShareLimitPerMille of that surface uncovered, in the
// view that sees most of it (the one the surface faces: the other two see it edge-on, where the
// coarse voxels' cubes fill walls an airborne scan never samples). One footprint for a densely
// sampled level, so its frames stay what they were.

#include <cstdint>
#include <span>
#include <vector>

#include "codegen/level_voxels.h"

namespace octopoint::prepare {

inline constexpr int kMaxSampleGap = 8;  // reach up to 8 footprints: kMaxSampleReach
inline constexpr std::uint64_t kHoleShareLimitPerMille = 10;
// Views of 2^(depth + 1) cells a side: finer levels are not measured (reach one footprint).
inline constexpr int kMaxMeasuredDepth = 11;

// What measuring a level found: its reach, and whether that reach leaves at most
// kHoleShareLimitPerMille of the surface open in every view that sees much of it (the ones
// judged), not only in one. The default depth cut (codegen/depth_range.h) keeps a depth past the
// voxel-count rule only when it does: the default model's depth 9 (a Kinect scan) measures a reach
// of 2, whole seen from the front but not from above; an airborne scan's ground is seen broadly
// by one view only. False when no reach up to kMaxSampleGap makes any view whole (the reach is then
// kMaxSampleGap footprints).
struct MeasuredReach {
  std::int32_t reach = 16;
  bool whole_in_every_view = true;
};

// The reach (16, 32, .. 16 kMaxSampleGap: Q4 voxel footprints) the voxels `keys` (Morton keys of
// `depth`, codegen/voxelizer.h, ascending) need against the surface of `coarse_keys` (of
// `coarse_depth` < depth) drawn with `coarse_reach`; 16 (whole) when depth > kMaxMeasuredDepth.
MeasuredReach measureReach(std::span<const std::uint64_t> keys, int depth,
                           std::span<const std::uint64_t> coarse_keys, int coarse_depth,
                           std::int32_t coarse_reach);
std::int32_t measureSampleReach(std::span<const std::uint64_t> keys, int depth,
                                std::span<const std::uint64_t> coarse_keys, int coarse_depth,
                                std::int32_t coarse_reach);

// The reach of each of a model's levels (ascending depths), each against the one before it; the
// coarsest level's is one footprint (16).
std::vector<std::int32_t> measureSampleReaches(std::span<const LevelVoxels> levels);

// Measures the reach of each of `model`'s levels (as measureSampleReaches) and records it in the
// level (PreparedLevel::sample_reach), which the `.oct` file and the generated sources store;
// nothing when they are measured already (PreparedModel::sample_reaches_measured).
void recordSampleReaches(PreparedModel& model);

}  // namespace octopoint::prepare
