// octopoint-view's walk mode (tools/viewer.h): its start options, Tab, the mouse drag that turns
// the eye, and what the overlay and `p` say of the eye.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli/error.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "renderer/perspective.h"
#include "tools/viewer.h"

namespace octopoint {

namespace {

// The start eye, the speed and the collision body from the options, in walk.cube's units (set by
// the caller with the field of view and the near plane).
void startWalk(const ViewerOptions& options, WalkStart& walk) {
  if (options.eye) {
    const Look look = options.look.value_or(Look{});
    // Refuses, in one line, an eye or a field of view the camera cannot draw.
    const PerspectiveView view = scanEyeView(*walk.cube, *options.eye, look, walk.fov, walk.near,
                                             options.width, options.height, "--eye");
    walk.eye = WalkEye{view.camera.eye, look.yaw, look.pitch, look.roll};
  }
  if (options.walk_speed) {
    const double edges = *options.walk_speed / walk.cube->edge;
    const double q24 = std::round(edges * static_cast<double>(kPerspectiveUnit));
    if (!(q24 >= static_cast<double>(kMinWalkSpeed) && q24 <= static_cast<double>(kMaxWalkSpeed))) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "--walk-speed: %s scan units a second is %.3g cube edges (of %s) a second; "
                    "walk mode takes 1/1024 to 64",
                    cli::realText(*options.walk_speed).c_str(), edges,
                    cli::realText(walk.cube->edge).c_str());
      throw cli::Error(text);
    }
    walk.speed = static_cast<std::int64_t>(q24);
  }
  walk.body = walkBodyOf(*walk.cube, options.collision);
}

}  // namespace

WalkStart walkStart(const ViewerOptions& options, const ModelView* model) {
  WalkStart walk;
  if (options.look && !options.eye) throw cli::Error("--look needs --eye");
  const bool walk_options =
      options.eye || options.fov || options.walk_speed || options.near || options.collision.any();
  if (model == nullptr) {
    if (walk_options) {
      throw cli::Error("--eye, --fov, --walk-speed, --near and the collision options need a model");
    }
    return walk;
  }
  walk.fov = options.fov.value_or(Angle::fromDegrees(60));
  walk.near = modelNearPlane(*model, options.near, "--near");
  walk.cube = scanCube(model->cubePlacement());
  if (walk.cube) {
    startWalk(options, walk);
    return walk;
  }
  if (options.eye || options.walk_speed) {
    throw cli::Error(std::string(options.eye ? "--eye" : "--walk-speed") +
                     " needs where the model's cube lies in the scan, which format version " +
                     std::to_string(model->formatVersion()) +
                     " does not record: prepare the scan again with octopoint-prepare");
  }
  if (options.collision.eye_radius || options.collision.eye_height) {
    throw cli::Error(
        "--eye-radius and --eye-height need where the model's cube lies in the scan, "
        "which format version " +
        std::to_string(model->formatVersion()) + " does not record");
  }
  return walk;
}

WalkStart cityWalkStart(const ViewerOptions& options) {
  if (!options.eye) {
    throw cli::Error(
        "--city needs --eye X,Y,Z: where the walk starts, in scene edges (a scene has no orbit "
        "view; docs/city.md)");
  }
  WalkStart walk;
  walk.fov = options.fov.value_or(Angle::fromDegrees(60));
  walk.cube = kSceneUnits;
  // The near plane in Q.24 scene edges: at least one unit.
  walk.near = options.near ? std::max<std::int64_t>(
                                 1, std::llround(std::ldexp(*options.near, kPerspectiveUnitBits)))
                           : PerspectiveCamera{}.near;
  startWalk(options, walk);
  return walk;
}

void Viewer::toggleWalk(std::int64_t now_us) {
  if (!renderer_->canWalk()) {
    cli::printError("octopoint-view", "walk mode: this model cannot be walked through");
    return;
  }
  releaseAll(now_us);
  send(ViewEventKind::kToggleWalk, now_us);
}

// The eye turns by the angle the drag spans on screen (the field of view per frame height), right
// and up as the mouse moves right and up; sums since the drag began, so no rounding adds up.
void Viewer::drag(const WindowEvent& event) {
  const std::int64_t now_us = clock_.nowMicroseconds();
  if (!walking()) return;
  switch (event.kind) {
    case WindowEvent::Kind::kDragStart:
      drag_x_ = drag_y_ = drag_yaw_sent_ = drag_pitch_sent_ = 0;
      renderer_->handle({now_us, ViewEventKind::kPress, NavigationKey::kDrag});
      return;
    case WindowEvent::Kind::kDragEnd:
      renderer_->handle({now_us, ViewEventKind::kRelease, NavigationKey::kDrag});
      return;
    default:
      break;
  }
  drag_x_ += event.dx;
  drag_y_ += event.dy;
  const std::int64_t frame_height = shown_info_.height > 0 ? shown_info_.height : options_.height;
  const std::int64_t pixels = frame_height * options_.scale;
  const std::int64_t fov = walk_.fov.turns16();
  const std::int64_t yaw = drag_x_ * fov / pixels, pitch = -drag_y_ * fov / pixels;
  ViewEvent turn;
  turn.time_us = now_us;
  turn.kind = ViewEventKind::kTurn;
  turn.turn_yaw = static_cast<std::int32_t>(yaw - drag_yaw_sent_);
  turn.turn_pitch = static_cast<std::int32_t>(pitch - drag_pitch_sent_);
  drag_yaw_sent_ = yaw;
  drag_pitch_sent_ = pitch;
  if (turn.turn_yaw != 0 || turn.turn_pitch != 0) renderer_->handle(turn);
}

void Viewer::walkOverlay(OverlayLines& lines) const {
  if (!shown_info_.view.walk) return;
  const WalkEye& walker = shown_info_.view.walker;
  std::string look = degreesText(walker.yaw) + "," + degreesText(walker.pitch);
  if (walker.roll != Angle{}) look.append(",").append(degreesText(walker.roll));
  const double speed_edges =
      static_cast<double>(renderer_->status().walk_speed) / static_cast<double>(kPerspectiveUnit);
  if (walk_.cube) {
    const ScanPoint eye = scanPointOf(*walk_.cube, walker.eye);
    lines.push_back("eye " + shortNumber(eye[0]) + "," + shortNumber(eye[1]) + "," +
                    shortNumber(eye[2]) + "  look " + look);
    const char* units = scene_ != nullptr ? " scene edges/s" : " units/s";
    lines.push_back("speed " + shortNumber(speed_edges * walk_.cube->edge) + units +
                    collisionText());
  } else {  // a model that records no placement: cube edges about its centre
    const auto edges = [](std::int64_t q24) {
      return shortNumber(static_cast<double>(q24) / static_cast<double>(kPerspectiveUnit));
    };
    lines.push_back("eye " + edges(walker.eye.x) + "," + edges(walker.eye.y) + "," +
                    edges(walker.eye.z) + " cube edges  look " + look);
    lines.push_back("speed " + shortNumber(speed_edges) + " cube edges/s" + collisionText());
  }
}

std::string Viewer::collisionText() const {
  if (!renderer_->status().walk_collision) return "  collision off (n)";
  return walk_.body.eye_height != 0 ? "  collision on, gravity (n)" : "  collision on (n)";
}

std::string Viewer::walkOptions(const WalkEye& walker) const {
  if (!walk_.cube) return " (walk mode; the model records no placement for --eye)";
  // degreesText: what --look reads back as the very same angles.
  std::string city;
  if (scene_ != nullptr) city = " --city " + options_.city;
  if (!options_.cells.empty()) city += " --cells " + options_.cells;
  return city + " --eye " + eyeText(*walk_.cube, walker.eye) + " --look " +
         degreesText(walker.yaw) + "," + degreesText(walker.pitch) + "," +
         degreesText(walker.roll) + " --fov " + degreesText(walk_.fov);
}

}  // namespace octopoint
