#include "codegen/scene_views.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

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

std::vector<int> eyeDepths(const Scene& scene) {
  if (scene.eyes.empty()) return {};
  double widest = 0;  // the largest field of view, in radians: its voxels are the smallest
  for (const SceneEye& eye : scene.eyes) {
    widest = std::max(widest, eye.fov.turns16() * (2 * std::numbers::pi / Angle::kUnitsPerTurn));
  }
  const double focal = scene.height / 2.0 / std::tan(widest / 2);
  // A voxel of depth d spans focal * 2^-d / z pixels at z cube edges: at most one pixel from two
  // edges on (the far side of the cube from an eye at or in it).
  const int coarsest =
      std::clamp(static_cast<int>(std::ceil(std::log2(focal / 2))), 1, format::kMaxDepth);
  std::vector<int> depths;
  for (int d = coarsest; d <= format::kMaxDepth && d < coarsest + format::kMaxLevels; ++d)
    depths.push_back(d);
  return depths;
}

DepthChoice chooseDepths(const Scene& scene) {
  DepthChoice choice;
  std::vector<Camera> cameras;
  if (scene.orthographic_views) cameras = sceneCameras(scene);
  choice.depths = neededDepthRange(cameras);
  const std::vector<int> for_eyes = eyeDepths(scene);
  if (!for_eyes.empty()) {
    // Both kinds of view: one consecutive range over both, its finest kMaxLevels depths.
    int low = for_eyes.front(), high = for_eyes.back();
    if (!choice.depths.empty()) {
      low = std::min(low, choice.depths.front());
      high = std::max(high, choice.depths.back());
    }
    low = std::max(low, high - format::kMaxLevels + 1);
    choice.depths.clear();
    for (int d = low; d <= high; ++d) choice.depths.push_back(d);
  }
  if (choice.depths.empty()) choice.depths = {1};  // every view refused: pruning reports it
  std::string reason = "depths auto: " + describeDepths(choice.depths) + ", what the scene's ";
  char views[320] = "";
  if (!cameras.empty()) {
    std::snprintf(views, sizeof views,
                  "%zu views need by projected size on %dx%d at zoom %g..%g (the coarsest depth "
                  "whose voxel edge is at most one pixel, per view; one coarser for moving views)",
                  cameras.size(), scene.width, scene.height, scene.zoom.low, scene.zoom.high);
    reason += views;
  }
  if (!for_eyes.empty()) {
    std::snprintf(views, sizeof views,
                  "%s%zu eyes need on %dx%d (from the depth whose voxel spans at most a pixel 2 "
                  "cube edges away)",
                  cameras.empty() ? "" : " and its ", scene.eyes.size(), scene.width, scene.height);
    reason += views;
  }
  choice.reason = reason + ", cut where the scan stops sampling densely";
  return choice;
}

}  // namespace octopoint::prepare
