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

#include <optional>
#include <span>

#include "renderer/camera.h"
#include "renderer/model.h"

namespace octopoint {

// The depth to draw among `stored_depths` (strictly ascending, each 1..format::kMaxDepth) for
// `camera`, by the rule above; nullopt when the camera is refused at every one of them.
std::optional<int> autoDepth(std::span<const int> stored_depths, const Camera& camera);

// The depth a model would need for this camera if it stored every depth 1..format::kMaxDepth:
// the coarsest whose leaf footprint is at most one pixel (what a preparer should store as the
// finest depth). nullopt when the camera is refused at every depth.
std::optional<int> neededDepth(const Camera& camera);

// The level of `model` that autoDepth picks; nullptr when the camera is refused at every depth.
const LevelView* autoLevel(const ModelView& model, const Camera& camera);

}  // namespace octopoint
