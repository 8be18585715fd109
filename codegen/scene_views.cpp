#include "codegen/scene_views.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "codegen/depth_range.h"
#include "octopoint/model.h"

namespace octopoint::prepare {
namespace {

// How many steps evenSamples takes: counted in double, so a tiny step cannot overflow an int
// before sceneWork() refuses it.
double evenSteps(double low, double high, double max_step) {
  return high <= low ? 0 : std::max(1.0, std::ceil((high - low) / max_step - 1e-9));
}

double geometricSteps(double low, double high, double max_ratio) {
  return high <= low ? 0
                     : std::max(1.0, std::ceil(std::log(high / low) / std::log(max_ratio) - 1e-9));
}

// Evenly spaced values from low to high, both included, at most `max_step` apart.
std::vector<double> evenSamples(double low, double high, double max_step) {
  if (high <= low) return {low};
  const int steps = static_cast<int>(evenSteps(low, high, max_step));
  std::vector<double> values;
  for (int i = 0; i <= steps; ++i) values.push_back(low + (high - low) * i / steps);
  return values;
}

// Geometrically spaced values from low to high, both included, at most a factor `max_ratio` apart.
std::vector<double> geometricSamples(double low, double high, double max_ratio) {
  if (high <= low) return {low};
  const int steps = static_cast<int>(geometricSteps(low, high, max_ratio));
  std::vector<double> values;
  for (int i = 0; i < steps; ++i)
    values.push_back(low * std::pow(high / low, static_cast<double>(i) / steps));
  values.push_back(high);  // exactly the end of the range, whatever pow would round to
  return values;
}

}  // namespace

Camera cameraFor(double yaw_deg, double pitch_deg, double roll_deg, double zoom, int width,
                 int height) {
  Camera camera;
  camera.yaw = Angle::fromMilliDegrees(std::llround(yaw_deg * 1000));
  camera.pitch = Angle::fromMilliDegrees(std::llround(pitch_deg * 1000));
  camera.roll = Angle::fromMilliDegrees(std::llround(roll_deg * 1000));
  camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(std::llround(zoom * Q16::kOneRaw)));
  camera.width = width;
  camera.height = height;
  return camera;
}

SceneWork sceneWork(const Scene& scene) {
  SceneWork work;
  if (scene.viewpoints.empty()) {
    work.yaw_samples = evenSteps(scene.yaw_deg->low, scene.yaw_deg->high, scene.angle_step_deg) + 1;
    work.pitch_samples =
        evenSteps(scene.pitch_deg->low, scene.pitch_deg->high, scene.angle_step_deg) + 1;
  } else {
    work.yaw_samples = static_cast<double>(scene.viewpoints.size());
  }
  work.zoom_samples = geometricSteps(scene.zoom.low, scene.zoom.high, scene.zoom_step) + 1;
  work.views = work.yaw_samples * work.pitch_samples * work.zoom_samples;
  work.view_pixels = work.views * scene.width * scene.height;
  return work;
}

std::string sceneWorkProblem(const Scene& scene) {
  const SceneWork work = sceneWork(scene);
  if (work.views <= kMaxSceneViews && work.view_pixels <= kMaxSceneViewPixels) return {};
  char samples[128];
  if (scene.viewpoints.empty()) {
    std::snprintf(samples, sizeof samples, "%.0f yaw x %.0f pitch x %.0f zoom samples",
                  work.yaw_samples, work.pitch_samples, work.zoom_samples);
  } else {
    std::snprintf(samples, sizeof samples, "%.0f viewpoints x %.0f zoom samples", work.yaw_samples,
                  work.zoom_samples);
  }
  char text[512];
  std::snprintf(
      text, sizeof text,
      "the scene asks for %.0f views (%s) of %dx%d pixels, %.3g view pixels; pruning draws at most "
      "%.0f views and %.3g view pixels: raise angle_step (now %g) or zoom_step (now %g), narrow "
      "the "
      "yaw, pitch or zoom range, or shrink the framebuffer",
      work.views, samples, scene.width, scene.height, work.view_pixels, kMaxSceneViews,
      kMaxSceneViewPixels, scene.angle_step_deg, scene.zoom_step);
  return text;
}

std::vector<Camera> sceneCameras(const Scene& scene) {
  std::vector<ViewAngles> angles = scene.viewpoints;
  if (angles.empty()) {
    for (double yaw : evenSamples(scene.yaw_deg->low, scene.yaw_deg->high, scene.angle_step_deg)) {
      for (double pitch :
           evenSamples(scene.pitch_deg->low, scene.pitch_deg->high, scene.angle_step_deg)) {
        angles.push_back({yaw, pitch, scene.roll_deg});
      }
    }
  }
  std::vector<Camera> cameras;
  for (double zoom : geometricSamples(scene.zoom.low, scene.zoom.high, scene.zoom_step)) {
    for (const ViewAngles& view : angles) {
      cameras.push_back(
          cameraFor(view.yaw_deg, view.pitch_deg, view.roll_deg, zoom, scene.width, scene.height));
    }
  }
  return cameras;
}

DepthChoice chooseDepths(const Scene& scene) {
  DepthChoice choice;
  const std::vector<Camera> cameras = sceneCameras(scene);
  choice.depths = neededDepthRange(cameras);
  if (choice.depths.empty()) choice.depths = {1};  // every view refused: pruning reports it
  char reason[320];
  std::snprintf(
      reason, sizeof reason,
      "depths auto: %s, what the scene's %zu views need by projected size on %dx%d at zoom %g..%g "
      "(the coarsest depth whose voxel edge is at most one pixel, per view; one coarser for "
      "moving views), cut where the scan stops sampling densely",
      describeDepths(choice.depths).c_str(), cameras.size(), scene.width, scene.height,
      scene.zoom.low, scene.zoom.high);
  choice.reason = reason;
  return choice;
}

}  // namespace octopoint::prepare
