#pragma once
// What a scene file asks of the preparer, in the renderer's terms: the cameras that sample the
// scene's views, and the depths to emit when the scene says "depths": "auto".

#include <string>
#include <vector>

#include "codegen/scene.h"
#include "renderer/camera.h"

namespace octopoint::prepare {

// The cameras visibility pruning draws from. Yaw and pitch ranges are sampled on an even grid that
// includes both ends, with at most `angle_step_deg` between neighbours (explicit viewpoints are
// taken as they are); the zoom range is sampled geometrically, ends included, with at most a
// factor `zoom_step` between neighbours. Every angle/zoom pair becomes one camera of the scene's
// framebuffer size, converted exactly as octopoint-render converts its flags.
std::vector<Camera> sceneCameras(const Scene& scene);

// One camera from floating-point degrees and zoom, rounded like octopoint-render's flags: angles
// to the nearest millidegree, zoom to the nearest Q16.16 step.
Camera cameraFor(double yaw_deg, double pitch_deg, double roll_deg, double zoom, int width, int height);

struct DepthChoice {
  std::vector<int> depths;  // ascending
  std::string reason;       // one sentence for the preparer's report
};

// What the scene's views need (codegen/depth_range.h, neededDepthRange over sceneCameras): from
// one depth coarser than the coarsest depth auto would draw at any view, to the finest.
// octopoint-prepare also cuts them where the scan stops sampling densely.
DepthChoice chooseDepths(const Scene& scene);

}  // namespace octopoint::prepare
