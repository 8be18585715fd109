#pragma once
// octopoint-render's perspective views (docs/perspective.md, "Using it"): --perspective, the orbit
// camera of the orthographic view seen in perspective; --eye/--look, an eye placed in the scan's
// own units; --path/--frames, a camera path drawn to numbered PNGs and a video.

#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "cli/arguments.h"
#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/perspective.h"
#include "renderer/perspective_walk.h"
#include "tools/scan_eye.h"

namespace octopoint {

inline constexpr int kDefaultFieldOfViewDegrees = 60;

struct PerspectiveOptions {
  bool orbit = false;            // --perspective
  std::optional<Angle> fov;      // --fov; none: kDefaultFieldOfViewDegrees (or the path's)
  std::optional<ScanPoint> eye;  // --eye
  std::optional<Look> look;      // --look
  std::string path;              // --path
  int frames = 0;                // --frames
  std::optional<double> near;    // --near, scan units; none: modelNearPlane's default

  bool any() const { return orbit || eye || !path.empty(); }
  const char* mode() const { return orbit ? "--perspective" : eye ? "--eye" : "--path"; }
};

// Reads the option `args` is at into `options`: false when it is none of --perspective, --fov,
// --eye, --look, --path, --frames and --near.
bool parsePerspectiveOption(cli::ArgumentReader& args, PerspectiveOptions& options);

// What else the command line asked for, for the checks between the options.
struct OtherOptions {
  bool orbit_camera = false;  // --yaw, --pitch, --roll, --zoom or --pan given
  bool url = false;
  bool fill = false;
  bool sheet = false;
  bool style = false;  // a style other than colour
};
// Throws cli::Error, one line, for options that exclude or need each other.
void checkPerspectiveOptions(const PerspectiveOptions& options, const OtherOptions& other);

// orbitPerspective (renderer/perspective.h) for octopoint-render, with the near plane `near`
// (Q.24 cube edges): throws cli::Error, one line, when the camera is refused.
PerspectiveView orbitPerspectiveView(const Camera& camera, Angle fov,
                                     std::int64_t near = PerspectiveCamera{}.near);

// Draws `model` with `view` on `background`, as BGR for OpenCV: its stored `depth`, or with 0
// each part at the depth its distance asks for (detail by distance); occlusion culling on.
// `stats` (may be null) learns what was drawn.
cv::Mat renderPerspective(const ModelView& model, int depth, const PerspectiveView& view,
                          Rgb background, PerspectiveDrawStats* stats = nullptr);

// What one run draws: the model and its label, the depth asked for and the level it chose (--depth;
// without it each part of the frame is drawn at the depth its distance asks for), the orthographic
// camera (its size, and for --perspective its turn, zoom and pan), where to write and on what
// background.
struct PerspectiveJob {
  const ModelView* model = nullptr;
  std::string label;
  std::optional<int> depth;
  const LevelView* chosen_level = nullptr;
  Camera camera;
  std::string output;
  Rgb background;
};

// Draws and writes what `options` asks for, prints one line saying what; cli::Error, one line,
// leaving no file, when it cannot.
void runPerspective(const PerspectiveOptions& options, const PerspectiveJob& job);

}  // namespace octopoint
