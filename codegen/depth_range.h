#pragma once
// Which depths a model stores (docs/splats.md): the range octopoint-prepare writes by default,
// what a scene's views need ("depths": "auto"), and where a scan stops sampling a depth densely.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "octopoint/camera.h"
#include "renderer/level_of_detail.h"

namespace octopoint::prepare {

// The default --depths: 6..10 serves screens from 176x208 zoomed out to 0.25 (depth 6: a 44-pixel
// cube, voxels under a pixel; the dual-resolution renderer's coarse frame one depth coarser) up to
// 1280x960 at zoom 1 (depth 10: a 0.94-pixel voxel edge, at any rotation), each cut short where
// the scan stops sampling densely (denseDepthCount); past the finest depth kept, the renderer
// splats.
inline constexpr int kDefaultCoarsestDepth = 6;
inline constexpr int kDefaultFinestDepth = 10;
std::vector<int> defaultDepths();

// The renderer's rule (renderer/level_of_detail.h, denseDepthCount): a depth with fewer than
// kDenseGrowth times its coarser neighbour's voxels is finer than the scan's point spacing, and
// draws with cracks between its voxels. For the voxel counts of consecutive ascending depths, how
// many leading depths to keep; always at least one.
inline constexpr std::size_t kDenseGrowth = static_cast<std::size_t>(octopoint::kDenseGrowth);
std::size_t denseDepthCount(std::span<const std::size_t> voxels_per_depth);

// The widest sample reach (Q4 footprints, codegen/sample_reach.h) with which the default cut keeps
// a depth past the voxel-count rule (docs/splats.md, "The default depth cut"): a depth whose
// splats must be wider than that is many voxels finer than the scan's samples, and adds bytes
// without detail.
inline constexpr std::int32_t kMaxKeptSampleReach = 16 * 4;

// The default cut (octopoint-prepare without --depths): for ascending `depths` with
// `voxels_per_depth` voxels (their Morton keys, ascending, given one depth at a time by
// `keys_of(i)`: asked for in order, at most once each, only for depths up to kMaxMeasuredDepth),
// how many leading depths to keep; at least one when there is any. A depth is kept when the one
// before it is and it either has kDenseGrowth times its voxels (denseDepthCount) or the sample
// reach it measures against the one before it (measureReach) is over one footprint, at most
// kMaxKeptSampleReach, and draws it whole in every view that sees much of it. So the renderer's
// depth auto (renderer/level_of_detail.h, denseDepthCount with the stored reaches) counts every
// kept depth as dense. With `kept_reaches`, the kept depths' reaches too: what
// measureSampleReaches gives for them, so that they need not be measured again.
std::size_t drawableDepthCount(
    std::span<const int> depths, std::span<const std::size_t> voxels_per_depth,
    const std::function<std::vector<std::uint64_t>(std::size_t)>& keys_of,
    std::vector<std::int32_t>* kept_reaches = nullptr);

// What the views `cameras` need (coarsest to finest, consecutive): from one depth coarser than the
// coarsest neededDepth (renderer/level_of_detail.h) of any camera (the dual-resolution renderer's
// coarse frame), to the finest neededDepth of any, at most format::kMaxLevels depths (the coarse
// end gives way). Empty when no camera is accepted.
std::vector<int> neededDepthRange(std::span<const Camera> cameras);

// "6..10" or "6" for a consecutive range, else the list "6,8".
std::string describeDepths(std::span<const int> depths);

}  // namespace octopoint::prepare
