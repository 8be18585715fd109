#pragma once
// A scene file: the views an app will show a model from, and how to prepare the scan for them
// (docs/scene.md is the reference of the JSON format). The preparer keeps only what these views
// can show.

#include <optional>
#include <string>
#include <vector>

#include "cli/input_file.h"
#include "codegen/prepare.h"

namespace octopoint::prepare {

struct ViewAngles {
  double yaw_deg = 0;
  double pitch_deg = 0;
  double roll_deg = 0;
};

struct Range {
  double low = 0;
  double high = 0;
};

struct Scene {
  // Either ranges (sampled by the preparer) or an explicit list of viewpoints.
  std::optional<Range> yaw_deg;
  std::optional<Range> pitch_deg;
  double roll_deg = 0;
  std::vector<ViewAngles> viewpoints;
  Range zoom{1, 1};
  int width = 320;
  int height = 240;
  bool auto_depths = true;
  std::vector<int> depths;  // when !auto_depths
  bool greyscale = false;
  int palette_colours = 256;
  std::optional<CropBox> crop;
  std::optional<OutlierRemoval> outliers;
  ScanAxes axes = ScanAxes::kYDown;
  double metres_per_scan_unit = 1.0;
  bool prune = true;
  std::optional<NormalOptions> normals;  // "normals": estimate and store them (docs/styles.md)
  double angle_step_deg = 2.0;           // the largest step between sampled yaw or pitch angles
  double zoom_step = 1.25;               // the largest ratio between neighbouring sampled zooms
  // Perspective views: the "eyes", then each of the "paths" sampled at `path_frames` evenly spaced
  // times (as octopoint-render --path P --frames path_frames draws it).
  std::vector<SceneEye> eyes;
  int path_frames = 64;
  // Whether the orthographic views (yaw, pitch, roll, viewpoints, zoom) take part in pruning and
  // depth choice: always, unless the scene gives eyes or paths and none of those keys.
  bool orthographic_views = true;
};

// The most perspective views a scene may ask for (eyes plus path frames): each draws the whole
// model at every stored depth, about as much as an orthographic view.
inline constexpr std::size_t kMaxSceneEyes = 20'000;

// Scene files are regular files of at most 1 MiB (cli/input_file.h): a real one has a few lines.
inline constexpr cli::InputKind kSceneInput{"scene file", cli::kMiB};

// Reads and checks a scene file. Throws PrepareError with one line "PATH: key 'K': what" for a
// syntax error, an unknown key, a value of the wrong type or out of range.
Scene loadScene(const std::string& path);
// The same for scene text already in memory (`path` only names it in messages).
Scene parseScene(const std::string& text, const std::string& path);

}  // namespace octopoint::prepare
