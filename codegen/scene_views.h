#pragma once
// What a scene file asks of the preparer, in the renderer's terms: the cameras that sample the
// scene's views, and the depths to emit when the scene says "depths": "auto".

#include <string>
#include <vector>

#include "codegen/scene.h"
#include "octopoint/camera.h"

namespace octopoint::prepare {

// What visibility pruning would draw for a scene: sampled views, and views x frame pixels (each
// view clears and scans its whole frame). Counted in double so that no count can wrap.
struct SceneWork {
  double yaw_samples = 1;  // or the number of explicit viewpoints
  double pitch_samples = 1;
  double zoom_samples = 1;
  double views = 1;
  double view_pixels = 0;
};
SceneWork sceneWork(const Scene& scene);

// The bounds on that work, whatever the scan: a full sphere at the default 2 degree step is 16,471
// views (1.3e9 view pixels at 320x240); these leave room for a zoom range on top and refuse what
// would run for hours or fill the memory (a 0.1 degree step over the sphere asks for 6.5 million).
inline constexpr double kMaxSceneViews = 200'000;
inline constexpr double kMaxSceneViewPixels = 17'179'869'184.0;  // 2^34

// Empty when the scene's work is within the bounds, else one sentence saying how much it asks and
// how to shrink it (parseScene refuses such a scene with it).
std::string sceneWorkProblem(const Scene& scene);

// The cameras visibility pruning draws from. Yaw and pitch ranges are sampled on an even grid that
// includes both ends, with at most `angle_step_deg` between neighbours (explicit viewpoints are
// taken as they are); the zoom range is sampled geometrically, ends included, with at most a
// factor `zoom_step` between neighbours. Every angle/zoom pair becomes one camera of the scene's
// framebuffer size, converted exactly as octopoint-render converts its flags.
std::vector<Camera> sceneCameras(const Scene& scene);

// One camera from floating-point degrees and zoom, rounded like octopoint-render's flags: angles
// to the nearest millidegree, zoom to the nearest Q16.16 step.
Camera cameraFor(double yaw_deg, double pitch_deg, double roll_deg, double zoom, int width,
                 int height);

struct DepthChoice {
  std::vector<int> depths;  // ascending
  std::string reason;       // one sentence for the preparer's report
};

// What the scene's views need (codegen/depth_range.h, neededDepthRange over sceneCameras): from
// one depth coarser than the coarsest depth auto would draw at any view, to the finest.
// octopoint-prepare also cuts them where the scan stops sampling densely.
// With eyes, also the depths detail by distance draws for them (eyeDepths), in one consecutive
// range of at most format::kMaxLevels depths, the finest kept.
DepthChoice chooseDepths(const Scene& scene);

// The depths a scene's eyes may draw by detail by distance: from the depth whose voxel spans at
// most a pixel two cube edges away at the widest field of view (the far side of the cube from an
// eye at or in it), format::kMaxLevels depths (octopoint-prepare cuts them where the scan stops
// sampling densely). Empty without eyes.
std::vector<int> eyeDepths(const Scene& scene);

}  // namespace octopoint::prepare
