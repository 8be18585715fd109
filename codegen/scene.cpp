#include "codegen/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "cli/input_file.h"
#include "cli/real_numbers.h"
#include "cli/strict_json.h"
#include "cli/text.h"
#include "codegen/prepare_error.h"
#include "codegen/scene_views.h"
#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "tools/camera_path.h"

namespace octopoint::prepare {
namespace {

using nlohmann::json;

// The largest zoom the camera takes: Q16.16 with a 32-bit signed raw value.
constexpr double kMaxZoom = 32767;
constexpr int kMaxNeighbours = 100;

class SceneReader : public cli::JsonReader<PrepareError> {
 public:
  using JsonReader::JsonReader;

  int integer(const json& value, const std::string& key, int low, int high) const {
    if (!value.is_number_integer()) fail(key, "expected a whole number");
    if (value.is_number_unsigned() &&
        value.get<unsigned long long>() > static_cast<unsigned long long>(high)) {
      fail(key, format("%llu is outside %d..%d", value.get<unsigned long long>(), low, high));
    }
    const auto x = value.get<long long>();
    if (x < low || x > high) fail(key, format("%lld is outside %d..%d", x, low, high));
    return static_cast<int>(x);
  }

  // [low, high] with low <= high, both inside [min, max].
  Range range(const json& value, const std::string& key, double min, double max) const {
    if (!value.is_array() || value.size() != 2) fail(key, "expected [low, high]");
    Range r{number(value[0], key, min, max), number(value[1], key, min, max)};
    if (r.low > r.high)
      fail(key, "empty range: " + cli::realText(r.low) + " > " + cli::realText(r.high));
    return r;
  }

  template <typename... Args>
  static std::string format(const char* pattern, Args... args) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, args...);
    return text;
  }
};

std::array<double, 3> point(const SceneReader& reader, const json& value, const std::string& key) {
  if (!value.is_array() || value.size() != 3) reader.fail(key, "expected [x, y, z]");
  std::array<double, 3> p{};
  for (std::size_t i = 0; i < 3; ++i) {
    p[i] = reader.number(value[i], key, -kMaxCropCoordinate, kMaxCropCoordinate);
  }
  return p;
}

void readDepths(const SceneReader& reader, const json& value, Scene& scene) {
  if (value.is_string()) {
    if (value.get<std::string>() != "auto")
      reader.fail("depths", "expected \"auto\" or a list of depths");
    scene.auto_depths = true;
    return;
  }
  if (!value.is_array() || value.empty() ||
      value.size() > static_cast<std::size_t>(format::kMaxLevels)) {
    reader.fail("depths", "expected \"auto\" or a list of 1.." +
                              std::to_string(format::kMaxLevels) + " depths");
  }
  scene.auto_depths = false;
  for (const json& item : value) {
    const int depth = reader.integer(item, "depths", 1, format::kMaxDepth);
    if (!scene.depths.empty() && depth <= scene.depths.back())
      reader.fail("depths", "depths must be strictly ascending");
    scene.depths.push_back(depth);
  }
}

void readViewpoints(const SceneReader& reader, const json& value, Scene& scene) {
  if (!value.is_array() || value.empty())
    reader.fail("viewpoints", "expected a non-empty list of {yaw, pitch[, roll]}");
  for (const json& item : value) {
    reader.onlyKeys(item, "viewpoints", {"yaw", "pitch", "roll"});
    if (!item.contains("yaw") || !item.contains("pitch"))
      reader.fail("viewpoints", "each viewpoint needs yaw and pitch");
    ViewAngles view;
    view.yaw_deg = reader.number(item["yaw"], "viewpoints.yaw", -180, 180);
    view.pitch_deg = reader.number(item["pitch"], "viewpoints.pitch", -90, 90);
    if (item.contains("roll"))
      view.roll_deg = reader.number(item["roll"], "viewpoints.roll", -180, 180);
    scene.viewpoints.push_back(view);
  }
}

// The scene's JSON, strictly (cli/strict_json.h): a scene nests 3 deep ({"viewpoints": [{...}]}).
json parseJson(const std::string& text, const std::string& path) {
  try {
    return cli::parseStrictJson(text, path, "a scene file");
  } catch (const cli::Error& error) {
    throw PrepareError(error.what());
  }
}

// The views: viewpoints or yaw and pitch ranges, roll, zoom and the framebuffer's size.
void readViews(const SceneReader& reader, const json& root, Scene& scene) {
  if (root.contains("viewpoints")) {
    if (root.contains("yaw") || root.contains("pitch")) {
      reader.fail("viewpoints", "give either viewpoints or yaw and pitch ranges, not both");
    }
    readViewpoints(reader, root["viewpoints"], scene);
  } else {
    scene.yaw_deg =
        root.contains("yaw") ? reader.range(root["yaw"], "yaw", -180, 180) : Range{0, 0};
    scene.pitch_deg =
        root.contains("pitch") ? reader.range(root["pitch"], "pitch", -90, 90) : Range{0, 0};
  }
  if (root.contains("roll")) scene.roll_deg = reader.number(root["roll"], "roll", -180, 180);
  if (root.contains("zoom")) {
    const json& zoom = root["zoom"];
    scene.zoom = zoom.is_number() ? Range{zoom.get<double>(), zoom.get<double>()}
                                  : reader.range(zoom, "zoom", -kMaxZoom, kMaxZoom);
    if (!(scene.zoom.low > 0)) reader.fail("zoom", "zoom must be greater than 0");
    // Zooms are 16.16 fixed point: below 1/65536 a zoom would round to nothing.
    if (scene.zoom.low < 1.0 / 65536) {
      reader.fail("zoom", "zoom " + cli::realText(scene.zoom.low) +
                              " is too small: it must be at least 1/65536");
    }
    if (!(scene.zoom.high <= kMaxZoom)) reader.fail("zoom", "zoom must be at most 32767");
  }
  if (root.contains("framebuffer")) {
    const json& size = root["framebuffer"];
    if (!size.is_array() || size.size() != 2)
      reader.fail("framebuffer", "expected [width, height]");
    scene.width = reader.integer(size[0], "framebuffer", 1, kMaxViewportSide);
    scene.height = reader.integer(size[1], "framebuffer", 1, kMaxViewportSide);
  }
}

void readPalette(const SceneReader& reader, const json& palette, Scene& scene) {
  reader.onlyKeys(palette, "palette", {"mode", "colours"});
  if (palette.contains("mode")) {
    const json& mode = palette["mode"];
    if (mode == "greyscale")
      scene.greyscale = true;
    else if (mode == "colour")
      scene.greyscale = false;
    else
      reader.fail("palette.mode", "expected \"colour\" or \"greyscale\"");
  }
  if (palette.contains("colours"))
    scene.palette_colours = reader.integer(palette["colours"], "palette.colours", 1, 256);
}

void readCrop(const SceneReader& reader, const json& crop, Scene& scene) {
  reader.onlyKeys(crop, "crop", {"min", "max"});
  if (!crop.contains("min") || !crop.contains("max"))
    reader.fail("crop", "expected {\"min\": [x, y, z], \"max\": [x, y, z]}");
  CropBox box{point(reader, crop["min"], "crop.min"), point(reader, crop["max"], "crop.max")};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (!(box.low[axis] < box.high[axis]))
      reader.fail("crop", "empty box: each min must be below its max");
  }
  scene.crop = box;
}

void readOutliers(const SceneReader& reader, const json& outliers, Scene& scene) {
  reader.onlyKeys(outliers, "outliers", {"method", "neighbours", "stddev"});
  if (!outliers.contains("method") || outliers["method"] != "statistical") {
    reader.fail("outliers.method", "expected \"statistical\"");
  }
  OutlierRemoval removal;
  if (outliers.contains("neighbours"))
    removal.neighbours =
        reader.integer(outliers["neighbours"], "outliers.neighbours", 1, kMaxNeighbours);
  if (outliers.contains("stddev"))
    removal.stddev_factor = reader.number(outliers["stddev"], "outliers.stddev", 0, 100);
  scene.outliers = removal;
}

// The scan's axis convention and unit.
void readScanFrame(const SceneReader& reader, const json& root, Scene& scene) {
  if (root.contains("axes")) {
    const json& axes = root["axes"];
    if (axes == "y-down")
      scene.axes = ScanAxes::kYDown;
    else if (axes == "y-up")
      scene.axes = ScanAxes::kYUp;
    else
      reader.fail("axes", "expected \"y-down\" or \"y-up\"");
  }
  if (root.contains("scan_unit")) {
    const json& unit = root["scan_unit"];
    if (unit == "m")
      scene.metres_per_scan_unit = 1.0;
    else if (unit == "cm")
      scene.metres_per_scan_unit = 0.01;
    else if (unit == "mm")
      scene.metres_per_scan_unit = 0.001;
    else
      reader.fail("scan_unit", "expected \"m\", \"cm\" or \"mm\"");
  }
}

void readNormals(const SceneReader& reader, const json& normals, Scene& scene) {
  if (normals.is_boolean()) {
    if (normals.get<bool>()) scene.normals = NormalOptions{};
  } else if (normals.is_object()) {
    reader.onlyKeys(normals, "normals", {"neighbours"});
    NormalOptions options;
    if (normals.contains("neighbours")) {
      options.neighbours =
          reader.integer(normals["neighbours"], "normals.neighbours", 3, kMaxNeighbours);
    }
    scene.normals = options;
  } else {
    reader.fail("normals", "expected true, false or {\"neighbours\": N}");
  }
}

Angle degrees(double value) { return Angle::fromMilliDegrees(std::llround(value * 1000)); }

// "eyes": [{"eye": [x, y, z], "look": [yaw, pitch(, roll)], "fov": D}, ...], as --eye, --look and
// --fov take them.
void readEyes(const SceneReader& reader, const json& value, Scene& scene) {
  if (!value.is_array() || value.empty() || value.size() > kMaxSceneEyes) {
    reader.fail("eyes", "expected a list of 1 to " + std::to_string(kMaxSceneEyes) +
                            " {\"eye\": [x, y, z], \"look\": [yaw, pitch], \"fov\": D}");
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string where = "eyes[" + std::to_string(i) + "]";
    const json& item = value[i];
    reader.onlyKeys(item, where, {"eye", "look", "fov"});
    if (!item.contains("eye")) reader.fail(where, "has no \"eye\"");
    const json& eye = item["eye"];
    if (!eye.is_array() || eye.size() != 3) reader.fail(where + ".eye", "expected [x, y, z]");
    SceneEye view;
    for (std::size_t axis = 0; axis < 3; ++axis)
      view.eye[axis] =
          reader.number(eye[axis], where + ".eye", -kMaxEyeCoordinate, kMaxEyeCoordinate);
    if (item.contains("look")) {
      const json& look = item["look"];
      if (!look.is_array() || look.size() < 2 || look.size() > 3)
        reader.fail(where + ".look", "expected [yaw, pitch] or [yaw, pitch, roll] in degrees");
      std::array<Angle, 3> angles{};
      for (std::size_t k = 0; k < look.size(); ++k)
        angles[k] =
            degrees(reader.number(look[k], where + ".look", -cli::kMaxDegrees, cli::kMaxDegrees));
      view.look = {angles[0], angles[1], angles[2]};
    }
    if (item.contains("fov")) {
      view.fov = degrees(reader.number(item["fov"], where + ".fov", kMinFieldOfViewDegrees,
                                       kMaxFieldOfViewDegrees));
    }
    scene.eyes.push_back(view);
  }
}

// "paths": camera path files (tools/camera_path.h, what octopoint-render --path reads), relative to
// the scene file's folder, each sampled at path_frames times as --frames samples it.
void readPaths(const SceneReader& reader, const json& value, const std::string& scene_path,
               Scene& scene) {
  if (!value.is_array() || value.empty() || value.size() > kMaxSceneEyes)
    reader.fail("paths", "expected a non-empty list of camera path files");
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string where = "paths[" + std::to_string(i) + "]";
    if (!value[i].is_string() || value[i].get<std::string>().empty())
      reader.fail(where, "expected the name of a camera path file");
    std::filesystem::path file(value[i].get<std::string>());
    if (file.is_relative()) file = std::filesystem::path(scene_path).parent_path() / file;
    CameraPath camera_path;
    try {
      camera_path = loadCameraPath(file.string());
    } catch (const cli::Error& error) {
      reader.fail(where, error.what());
    }
    if (scene.eyes.size() + static_cast<std::size_t>(scene.path_frames) > kMaxSceneEyes) {
      reader.fail("paths", "the eyes and path frames come to more than " +
                               std::to_string(kMaxSceneEyes) + " views: lower path_frames");
    }
    const Angle fov =
        camera_path.fov_degrees ? degrees(*camera_path.fov_degrees) : Angle::fromDegrees(60);
    for (const PathPose& pose : samplePath(camera_path, scene.path_frames))
      scene.eyes.push_back({pose.eye, pose.look, fov});
  }
}

// Eyes and paths: perspective views (docs/scene.md); without any orthographic key they are the
// scene's only views.
void readPerspectiveViews(const SceneReader& reader, const json& root, const std::string& path,
                          Scene& scene) {
  if (root.contains("path_frames")) {
    if (!root.contains("paths")) reader.fail("path_frames", "needs \"paths\"");
    scene.path_frames = reader.integer(root["path_frames"], "path_frames", 1, kMaxPathFrames);
  }
  if (root.contains("eyes")) readEyes(reader, root["eyes"], scene);
  if (root.contains("paths")) readPaths(reader, root["paths"], path, scene);
  if (!scene.eyes.empty()) {
    scene.orthographic_views = false;
    for (const char* key : {"yaw", "pitch", "roll", "viewpoints", "zoom"})
      scene.orthographic_views = scene.orthographic_views || root.contains(key);
  }
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& path) {
  const SceneReader reader(path);
  const json root = parseJson(text, path);
  if (!root.is_object())
    throw PrepareError(cli::displayPath(path) + ": expected a JSON object at the top level");
  reader.onlyKeys(root, "",
                  {"yaw", "pitch", "roll", "viewpoints", "zoom", "framebuffer", "depths", "palette",
                   "crop", "outliers", "axes", "scan_unit", "prune", "angle_step", "zoom_step",
                   "normals", "eyes", "paths", "path_frames"});

  Scene scene;
  readViews(reader, root, scene);
  if (root.contains("depths")) readDepths(reader, root["depths"], scene);
  if (root.contains("palette")) readPalette(reader, root["palette"], scene);
  if (root.contains("crop")) readCrop(reader, root["crop"], scene);
  if (root.contains("outliers")) readOutliers(reader, root["outliers"], scene);
  readScanFrame(reader, root, scene);
  if (root.contains("prune")) {
    if (!root["prune"].is_boolean()) reader.fail("prune", "expected true or false");
    scene.prune = root["prune"].get<bool>();
  }
  if (root.contains("normals")) readNormals(reader, root["normals"], scene);
  if (root.contains("angle_step"))
    scene.angle_step_deg = reader.number(root["angle_step"], "angle_step", 0.01, 90);
  if (root.contains("zoom_step"))
    scene.zoom_step = reader.number(root["zoom_step"], "zoom_step", 1.01, 16);
  readPerspectiveViews(reader, root, path, scene);
  // Each eye draws its whole frame at every stored depth, as an orthographic view does.
  const double eye_pixels = static_cast<double>(scene.eyes.size()) * scene.width * scene.height;
  if (scene.prune && eye_pixels > kMaxSceneViewPixels) {
    char too_much[320];
    std::snprintf(too_much, sizeof too_much,
                  "%zu eyes and path frames of %dx%d pixels are %.3g view pixels; pruning draws "
                  "at most %.3g: fewer eyes or path_frames, or shrink the framebuffer",
                  scene.eyes.size(), scene.width, scene.height, eye_pixels, kMaxSceneViewPixels);
    reader.fail(root.contains("paths") ? "paths" : "eyes", too_much);
  }
  if (scene.prune && scene.orthographic_views) {
    const std::string too_much = sceneWorkProblem(scene);
    if (!too_much.empty()) throw PrepareError(cli::displayPath(path) + ": " + too_much);
  }
  return scene;
}

Scene loadScene(const std::string& path) {
  return parseScene(cli::readInputFile(path, kSceneInput), path);
}

}  // namespace octopoint::prepare
