#pragma once
// octopoint-render's perspective views (docs/perspective.md, "Using it"): --perspective, the orbit
// camera of the orthographic view seen in perspective; --eye/--look, an eye placed in the scan's
// own units; --path/--frames, a camera path drawn to numbered PNGs and a video.

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "octopoint/styles.h"
#include "renderer/chunked_assembly.h"
#include "renderer/perspective.h"
#include "renderer/perspective_walk.h"
#include "tools/scan_eye.h"
#include "tools/walk_collision.h"

namespace octopoint {

inline constexpr int kDefaultFieldOfViewDegrees = 60;

struct PerspectiveOptions {
  bool orbit = false;            // --perspective
  std::optional<Angle> fov;      // --fov; none: kDefaultFieldOfViewDegrees (or the path's)
  std::optional<ScanPoint> eye;  // --eye
  std::optional<Look> look;      // --look
  std::string path;              // --path
  int frames = 0;                // --frames
  CollisionOptions collision;    // --collide, --eye-radius, --eye-height (with --path)
  std::optional<double> near;    // --near, scan units; none: modelNearPlane's default

  bool any() const { return orbit || eye || !path.empty(); }
  const char* mode() const { return orbit ? "--perspective" : eye ? "--eye" : "--path"; }
};

// Reads the option `args` is at into `options`: false when it is none of --perspective, --fov,
// --eye, --look, --path, --frames, --near, --collide, --eye-radius and --eye-height.
bool parsePerspectiveOption(cli::ArgumentReader& args, PerspectiveOptions& options);

// What else the command line asked for, for the checks between the options.
struct OtherOptions {
  bool orbit_camera = false;  // --yaw, --pitch, --roll, --zoom or --pan given
  bool sheet = false;
};
// Throws cli::Error, one line, for options that exclude or need each other.
void checkPerspectiveOptions(const PerspectiveOptions& options, const OtherOptions& other);

// orbitPerspective (renderer/perspective.h) for octopoint-render, with the near plane `near`
// (Q.24 cube edges): throws cli::Error, one line, when the camera is refused.
PerspectiveView orbitPerspectiveView(const Camera& camera, Angle fov,
                                     std::int64_t near = PerspectiveCamera{}.near);

// How a perspective frame is finished: hole filling with the perspective bridge rule
// (renderer/perspective_depth.h), and a style (null: colour, resolveToRgb).
struct PerspectiveFinish {
  bool fill = false;
  FrameStyler* styler = nullptr;  // options set; its background is the frame's
};

// Draws `model` with `view` on `background`, as BGR for OpenCV: its stored `depth`, or with 0
// each part at the depth its distance asks for (detail by distance); occlusion culling on.
// `stats` (may be null) learns what was drawn.
// `pixels_q8`: PerspectiveRenderer::Options::pixels_q8 (a point budget's coarser frames).
cv::Mat renderPerspective(const ModelView& model, int depth, const PerspectiveView& view,
                          Rgb background, PerspectiveDrawStats* stats = nullptr,
                          std::uint32_t pixels_q8 = kOnePixelQ8,
                          const PerspectiveFinish& finish = {});

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
  // A chunked model (a file, or streamed by --url): the parts each view is drawn from, held when
  // it is drawn (renderer/chunked_assembly.h); `model` then gives the cube's placement and the
  // palette. None: `model` itself.
  std::function<const HeldParts&(const PerspectiveView&)> parts;
  // --point-budget (0: none): each frame is drawn with the least voxel size on screen, from one
  // pixel up by steps of 2^(1/4), at which it hands at most this many points to the plot (the
  // coarsest when none does): coarser where voxels are smallest on screen, the far parts first.
  std::uint64_t point_budget = 0;
  PerspectiveFinish finish;  // --fill, --style
  // --sheet N (0: none): a contact sheet of N views instead (tools/perspective_sheet.h).
  int sheet = 0;
};

// Draws `parts` with `view` on `background` as renderPerspective draws one model: the parts one
// after another into one frame, each with the detail of parts.detailDepths().
// A chunked model has no normals: only `finish.fill` applies.
cv::Mat renderPerspectiveParts(const HeldParts& parts, int depth, const PerspectiveView& view,
                               Rgb background, PerspectiveDrawStats* stats = nullptr,
                               std::uint32_t pixels_q8 = kOnePixelQ8,
                               const PerspectiveFinish& finish = {});

// The frame of `view` as the job draws it (its parts, point budget, fill and style), as BGR.
cv::Mat renderPerspectiveView(const PerspectiveJob& job, const PerspectiveView& view,
                              PerspectiveDrawStats* stats = nullptr);

// The columns of a contact sheet of `count` views: --perspective turns the orbit camera's yaw and
// --eye the look's yaw by a turn / count a column; --path takes `count` evenly spaced frames.
std::vector<PerspectiveView> sheetViews(const PerspectiveOptions& options,
                                        const PerspectiveJob& job, int count);

// Draws and writes what `options` asks for, prints one line saying what; cli::Error, one line,
// leaving no file, when it cannot.
void runPerspective(const PerspectiveOptions& options, const PerspectiveJob& job);

}  // namespace octopoint
