#include "tools/scene_render.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "cli/error.h"
#include "cli/output_file.h"
#include "cli/text.h"
#include "octopoint/framebuffer.h"
#include "renderer/scene_cells.h"
#include "renderer/scene_collision.h"
#include "renderer/scene_renderer.h"
#include "tools/camera_path.h"
#include "tools/png_file.h"
#include "tools/scene_file.h"
#include "tools/walk_collision.h"

namespace octopoint {
namespace {

// The eye in scene edges to the camera's Q.24 scene edges; a cli::Error naming `where` when it
// lies beyond kMaxEyeDistance scene edges of the origin on some axis.
ModelPoint sceneEye(const ScanPoint& eye, const std::string& where) {
  std::int64_t q[3];
  for (std::size_t a = 0; a < 3; ++a) {
    const double x = eye[a];
    if (!(std::fabs(x) <= static_cast<double>(kMaxEyeDistance))) {
      throw cli::Error(where + ": the eye " + scanPointText(eye) + " lies more than " +
                       std::to_string(kMaxEyeDistance) +
                       " scene edges from the scene's origin on some axis");
    }
    q[a] = std::llround(std::ldexp(x, kPerspectiveUnitBits));
  }
  return {q[0], q[1], q[2]};
}

PerspectiveView cityView(const ScanPoint& eye, const Look& look, Angle fov, const Camera& size,
                         const std::string& where) {
  PerspectiveCamera camera;
  camera.eye = sceneEye(eye, where);
  camera.yaw = look.yaw;
  camera.pitch = look.pitch;
  camera.roll = look.roll;
  camera.fov = fov;
  camera.width = size.width;
  camera.height = size.height;
  PerspectiveView view;
  if (const PerspectiveError error = buildPerspectiveView(camera, kDefaultFractionBits, &view);
      error != PerspectiveError::kNone) {
    throw cli::Error(where + ": " + describe(error));
  }
  return view;
}

class CityFrames {
 public:
  CityFrames(const LoadedScene& scene, const std::string& cells) : scene_(scene) {
    SceneError error;
    renderer_.emplace(scene.models, scene.instances, &error);
    if (error != SceneError::kNone) throw cli::Error(scene.label + ": " + describe(error));
    if (cells.empty()) return;
    table_.emplace(loadCellTable(cells, scene));
    cells_.emplace(*table_);
  }

  cv::Mat draw(const PerspectiveView& view, Rgb background, SceneDrawStats* stats) {
    if (frame_.width() != view.camera.width || frame_.height() != view.camera.height)
      frame_ = Framebuffer(view.camera.width, view.camera.height);
    frame_.clear();
    if (cells_) cells_->apply(*renderer_, view.camera.eye);
    static_cast<void>(renderer_->draw(view, frame_, stats));  // no abort flag: it completes
    cv::Mat rgb(view.camera.height, view.camera.width, CV_8UC3);
    // Every model holds the scene's palette (tools/scene_file.h): the first one's resolves.
    static_cast<void>(
        resolveToRgb(frame_, *scene_.models.front(), background, {rgb.data, rgb.total() * 3}));
    cv::Mat bgr;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    return bgr;
  }

 private:
  const LoadedScene& scene_;
  std::optional<SceneRenderer> renderer_;
  std::optional<CellTable> table_;
  std::optional<SceneCells> cells_;  // only the eye's cell's set is drawn
  Framebuffer frame_{1, 1};
};

// The points the scene holds at full detail: each instance's model's finest depth, and the bytes
// of the distinct models.
std::string sizeText(const LoadedScene& scene) {
  std::uint64_t points = 0;
  for (const SceneInstance& instance : scene.instances)
    points += scene.models[instance.model]->finestLevel().leaves.size();
  return std::to_string(scene.models.size()) + " models (" + std::to_string(scene.model_bytes) +
         " bytes), " + std::to_string(scene.instances.size()) + " instances, " +
         std::to_string(points) + " points at full detail";
}

std::string statsText(const SceneDrawStats& stats) {
  return std::to_string(stats.instances_drawn) + " instances drawn (" +
         std::to_string(stats.outside_frustum) + " outside the view, " +
         std::to_string(stats.beyond_reach) + " beyond reach, " + std::to_string(stats.occluded) +
         " hidden by nearer ones), " + std::to_string(stats.points.leaves) + " points";
}

Angle fovOf(const PerspectiveOptions& options, const std::optional<double>& path_fov) {
  if (options.fov) return *options.fov;
  if (path_fov) return Angle::fromMilliDegrees(std::llround(*path_fov * 1000));
  return Angle::fromDegrees(kDefaultFieldOfViewDegrees);
}

// --collide: the path's eyes walked with collision against the scene's instances from frame to
// frame (renderer/scene_collision.h); one line says how often something stopped the eye.
void collideCityPoses(const LoadedScene& scene, const PerspectiveOptions& options,
                      std::vector<PathPose>& poses) {
  const WalkBody body = walkBodyOf(kSceneUnits, options.collision);
  SceneError error;
  const SceneCollision world(scene.models, scene.instances, &error);
  if (error != SceneError::kNone) throw cli::Error(scene.label + ": " + describe(error));
  if (const std::optional<std::size_t> model = world.unindexedModel()) {
    throw cli::Error("--collide: " + scene.label + ": model " + std::to_string(*model) +
                     "'s finest level is too large to walk");
  }
  std::vector<ScanPoint> eyes;
  for (const PathPose& pose : poses) eyes.push_back(pose.eye);
  const CollidedEyes collided = collideEyes(world, kSceneUnits, body, eyes, "--collide");
  for (std::size_t i = 0; i < poses.size(); ++i) poses[i].eye = collided.eyes[i];
  std::printf("%s (scene edges)\n",
              collisionSummary(kSceneUnits, body, collided.stopped, poses.size()).c_str());
}

void drawCityEye(const PerspectiveOptions& options, const CityJob& job, const LoadedScene& scene) {
  const PerspectiveView view = cityView(*options.eye, options.look.value_or(Look{}),
                                        fovOf(options, std::nullopt), job.camera, "--eye");
  cli::checkOutputFile(job.output);
  CityFrames frames(scene, job.cells);
  SceneDrawStats stats;
  writePng(job.output, frames.draw(view, job.background, &stats));
  std::printf("%s: %s: %s -> %s (%dx%d)\n", scene.label.c_str(), sizeText(scene).c_str(),
              statsText(stats).c_str(), job.output.c_str(), job.camera.width, job.camera.height);
}

void drawCityPath(const PerspectiveOptions& options, const CityJob& job, const LoadedScene& scene) {
  const CameraPath path = loadCameraPath(options.path);
  const std::int64_t pixels = std::int64_t{options.frames} * job.camera.width * job.camera.height;
  if (pixels > kMaxPathPixels) {
    throw cli::Error("--frames " + std::to_string(options.frames) + " makes " +
                     std::to_string(pixels) + " pixels of PNGs, at most " +
                     std::to_string(kMaxPathPixels));
  }
  const Angle fov = fovOf(options, path.fov_degrees);
  std::vector<PerspectiveView> views;
  std::vector<PathPose> poses = samplePath(path, options.frames);
  if (options.collision.collide) collideCityPoses(scene, options, poses);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    views.push_back(
        cityView(poses[i].eye, poses[i].look, fov, job.camera,
                 "--path " + cli::displayPath(options.path) + ": frame " + std::to_string(i)));
  }
  std::string prefix = job.output;
  if (prefix.size() > 4 && prefix.ends_with(".png")) prefix.resize(prefix.size() - 4);
  const auto name = [&](std::size_t i) {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%04zu.png", i);
    return prefix + suffix;
  };
  cli::checkOutputFile(name(0));
  CityFrames frames(scene, job.cells);
  SceneDrawStats all;
  std::vector<std::string> written;
  try {
    for (std::size_t i = 0; i < views.size(); ++i) {
      SceneDrawStats stats;
      const cv::Mat image = frames.draw(views[i], job.background, &stats);
      written.push_back(name(i));
      writePng(name(i), image);
      all.instances_drawn += stats.instances_drawn;
      all.outside_frustum += stats.outside_frustum;
      all.beyond_reach += stats.beyond_reach;
      all.occluded += stats.occluded;
      all.points.leaves += stats.points.leaves;
    }
  } catch (...) {
    std::error_code ignored;
    for (const std::string& file : written) std::filesystem::remove(file, ignored);
    throw;
  }
  std::printf("%s: %s, %d frames along %s: %s in all -> %s .. %s (%dx%d)\n", scene.label.c_str(),
              sizeText(scene).c_str(), options.frames, cli::displayPath(options.path).c_str(),
              statsText(all).c_str(), name(0).c_str(), name(views.size() - 1).c_str(),
              job.camera.width, job.camera.height);
}

}  // namespace

void checkCityOptions(const PerspectiveOptions& options, bool orbit_camera, bool other_source,
                      bool depth, bool fill, bool sheet, bool style) {
  if (other_source)
    throw cli::Error("--city draws a scene: --model, --file and --url do not apply");
  if (options.orbit)
    throw cli::Error("--city: place the eye with --eye or --path, not --perspective");
  if (!options.eye && options.path.empty())
    throw cli::Error("--city needs --eye X,Y,Z (scene edges) or --path PATH.json --frames N");
  if (orbit_camera) {
    throw cli::Error(
        "--city places the eye in the scene: --yaw, --pitch, --roll, --zoom and --pan "
        "do not apply (turn it with --look or the path's keys)");
  }
  if (depth || fill || sheet || style) {
    throw cli::Error(
        "--city draws each instance at the depth its distance asks for, in colour: "
        "--depth, --fill, --sheet and --style do not apply");
  }
}

void runCity(const PerspectiveOptions& options, const CityJob& job) {
  const std::unique_ptr<LoadedScene> scene = loadScene(job.scene);
  if (options.eye) {
    drawCityEye(options, job, *scene);
  } else {
    drawCityPath(options, job, *scene);
  }
}

}  // namespace octopoint
