#pragma once
// Depth by projected size (`--depth auto`, docs/splats.md): which of a model's stored depths to
// draw for a camera (its framebuffer size, zoom and rotation), so that a frame's cost follows the
// pixels it covers rather than the model.
//
// The rule, exactly: let W(d) be the footprint of a leaf of depth d, the larger of its projected
// extents along screen x and y (FrameSetup::splat.extent_x/extent_y, Q(32-F).F at
// F = kDefaultFractionBits; W = voxel edge in pixels times the largest row sum
// |r_0| + |r_1| + |r_2| of the rotation's first two rows). Depth auto draws the COARSEST stored
// depth with W(d) <= 1 pixel: no depth coarser than it fits a voxel into a pixel, and one finer
// would put up to eight leaves on a pixel. With consecutive stored depths W halves per depth, so
// the drawn footprint lies in (1/2, 1] pixel: voxels are not much smaller than a pixel. When even
// the finest stored depth has W > 1 pixel, the finest is drawn with footprint splats of that
// footprint; when even the coarsest has W <= 1/2 pixel, the coarsest is drawn. Depths at which
// the camera is refused (coordinates over 32 bits) are passed over. Integer only.
//
// Only depths the scan samples densely are candidates (denseDepthCount): a model prepared with an
// explicit --depths list may store depths finer than its scan's point spacing, and drawn, such a
// depth shows that spacing as speckle (one-pixel voxels over the background) for more cost than
// the densely sampled depth drawn with splats. autoLevel and the progressive model cut there.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "renderer/camera.h"
#include "renderer/model.h"

namespace octopoint {

// A surface sampled densely fills about four times as many voxels at each finer depth (eight for
// a volume); a depth with fewer than kDenseGrowth times its coarser neighbour's voxels is finer
// than the scan's point spacing. The preparer's rule (octopoint-prepare keeps no such depth unless
// told to) and the renderer's are this one.
inline constexpr std::uint64_t kDenseGrowth = 3;

// For the voxel counts of ascending stored depths, how many leading depths are densely sampled: up
// to (excluding) the first whose count is below kDenseGrowth times the previous one's; at least one
// when there is any.
std::size_t denseDepthCount(std::span<const std::uint64_t> voxels_per_depth);

// The depth to draw among `stored_depths` (strictly ascending, each 1..format::kMaxDepth) for
// `camera`, by the rule above; nullopt when the camera is refused at every one of them.
std::optional<int> autoDepth(std::span<const int> stored_depths, const Camera& camera);

// The depth a model would need for this camera if it stored every depth 1..format::kMaxDepth:
// the coarsest whose leaf footprint is at most one pixel (what a preparer should store as the
// finest depth). nullopt when the camera is refused at every depth.
std::optional<int> neededDepth(const Camera& camera);

// The level of `model` that autoDepth picks among its densely sampled depths; nullptr when the camera is refused at every depth.
const LevelView* autoLevel(const ModelView& model, const Camera& camera);

}  // namespace octopoint
