#pragma once
// Visibility pruning, the paper's hidden-point removal: a voxel is kept only when it wins the
// z-test at some pixel from at least one of the scene's cameras. The check draws the level with
// the real decoder (renderer/decode_baseline.h) and the same FrameSetup as rendering, and records
// per pixel the nearest leaf with Framebuffer::plot's rule (the first strictly nearest wins). A
// leaf's screen position depends only on its own path in the tree, so removing losers leaves every
// winner where it was: at each of these cameras the pruned level draws the very same pixels.
// Where a view magnifies its voxels, every leaf a smooth frame (octopoint/smooth.h) blends into a
// pixel is kept too, so that the smooth frames are the same as well.

#include <cstdint>
#include <span>
#include <vector>

#include "octopoint/camera.h"

namespace octopoint::prepare {

// For the voxels `sorted_keys` (Morton keys at `depth`, ascending, as codegen/voxelizer.h makes
// them): 1 for each voxel visible from some camera, else 0, the splats widened by the level's
// stored `sample_reach` (Q4, kOneSampleReach..kMaxSampleReach) as the renderer widens them
// (buildFrameSetup). Uses up to two threads. Throws PrepareError when a camera is refused at this
// depth (a zoom too large to fit 32 bits).
std::vector<std::uint8_t> visibleVoxels(std::span<const std::uint64_t> sorted_keys, int depth,
                                        std::span<const Camera> cameras,
                                        std::int32_t sample_reach = kOneSampleReach);

}  // namespace octopoint::prepare
