// octopoint-view's window: the key table, the event loop, the frame on screen with its overlay,
// the style keys and `s` (tools/viewer.h); walk mode is in tools/viewer_walk.cpp.

#include "tools/viewer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "cli/error.h"
#include "cli/output_file.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "octopoint/progressive.h"
#include "renderer/perspective.h"
#include "tools/view_stream.h"

namespace octopoint {
namespace {

constexpr const char* kWindowTitle = "octopoint-view";
constexpr Rgb kBackground{236, 236, 240};

double degreesOf(Angle angle) { return angle.turns16() * 360.0 / Angle::kUnitsPerTurn; }
// -180..180: the light's angles are signed.
double signedDegreesOf(Angle angle) {
  const double degrees = degreesOf(angle);
  return degrees > 180 ? degrees - 360 : degrees;
}
double zoomOf(Q16 zoom) { return static_cast<double>(zoom.raw()) / Q16::kOneRaw; }

// The camera a frame was drawn with (its view and size).
Camera cameraOf(const FrameInfo& info) {
  Camera camera;
  camera.yaw = info.view.yaw;
  camera.pitch = info.view.pitch;
  camera.zoom = info.view.zoom;
  camera.width = info.width;
  camera.height = info.height;
  return camera;
}

InteractiveConfig interactiveConfig(const ViewerOptions& options, const WalkStart& walk,
                                    ViewWindow& window) {
  InteractiveConfig config;
  config.width = options.width;
  config.height = options.height;
  config.degrees_per_second = options.degrees_per_second;
  config.fov = walk.fov;
  if (walk.speed > 0) config.walk_speed = walk.speed;
  config.walk_radius = walk.body.radius;
  config.walk_eye_height = walk.body.eye_height;
  config.near = walk.near;
  if (walk.eye) {
    config.initial_view.walk = true;
    config.initial_view.walker = *walk.eye;
  }
  config.frame_ready = [&window] { window.wake(); };
  return config;
}

// A model with normals is drawn with them, so that the style keys work on every frame.
InteractiveConfig interactiveConfig(const ViewerOptions& options, const WalkStart& walk,
                                    ViewWindow& window, const ModelView& model) {
  InteractiveConfig config = interactiveConfig(options, walk, window);
  if (model.hasNormals()) config.payload = PixelPayload::kColourNormal;
  return config;
}

// A streamed model walks too (tools/view_stream.h); its frames carry colours only.
InteractiveConfig streamConfig(const ViewerOptions& options, const WalkStart& walk,
                               ViewWindow& window, net::ModelStream& stream,
                               const std::atomic<std::uint64_t>& content) {
  InteractiveConfig config = interactiveConfig(options, walk, window);
  config.walk_draw = streamWalkDrawer(stream, content);
  return config;
}

// A scene walks only (interactive/scene_walk.h); its frames carry colours only.
InteractiveConfig sceneConfig(const ViewerOptions& options, const WalkStart& walk,
                              ViewWindow& window, SceneWalk& scene) {
  return scene.configure(interactiveConfig(options, walk, window));
}

constexpr int kLightStepDegrees = 15;

}  // namespace

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

Viewer::Viewer(const ViewerOptions& options, const WalkStart& walk, const ModelView* model,
               net::ModelStream* stream, SceneWalk* scene)
    : options_(options),
      walk_(walk),
      model_(model),
      stream_(stream),
      scene_(scene),
      window_(kWindowTitle, options.width * options.scale, options.height * options.scale,
              kMinFrameSide * options.scale, kMinFrameSide * options.scale),
      renderer_(
          model != nullptr ? std::make_unique<DualResolutionRenderer>(
                                 *model, clock_, interactiveConfig(options, walk, window_, *model))
          : stream != nullptr
              ? std::make_unique<DualResolutionRenderer>(
                    streamDrawer(*stream, options.source.point_budget), clock_,
                    streamConfig(options, walk, window_, *stream, stream_content_))
              : std::make_unique<DualResolutionRenderer>(
                    SceneWalk::noOrbitView(), clock_, sceneConfig(options, walk, window_, *scene))),
      keys_(keyTable(this)),
      resolve_(
          [this](const Framebuffer& frame, const FrameInfo& info, std::span<std::uint8_t> rgb) {
            if (model_ != nullptr) {
              resolveStyled(frame, info, rgb);
              return;
            }
            if (scene_ != nullptr) {  // every model of a scene holds its palette
              static_cast<void>(resolveToRgb(frame, scene_->firstModel(), kBackground, rgb));
              return;
            }
            // The palette never changes once the head is in: resolved without the stream's lock.
            if (const ProgressiveModel* chunked = stream_->model(); chunked != nullptr) {
              smooth_shown_ = splats_ == SplatMode::kSmooth && resolveStreamSmooth(info, rgb);
              if (smooth_shown_) return;
              // The window's pixels are sized to the frame: resolveToRgb cannot refuse them.
              static_cast<void>(resolveToRgb(frame, chunked->baseModel(), kBackground, rgb));
              return;
            }
            for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
              rgb[i] = kBackground.r, rgb[i + 1] = kBackground.g, rgb[i + 2] = kBackground.b;
            }
          }) {
  if (model_ != nullptr) {
    palette_ = paletteOf(*model_);
    StyleOptions style;
    style.background = kBackground;
    // The colour style needs no normals: setOptions cannot refuse it.
    static_cast<void>(styler_.emplace(*model_).setOptions(style));
  }
  stream_snapshot_.setPointBudget(options.source.point_budget);
  overlay_.add([this](OverlayLines& lines) { defaultOverlay(lines); });
  overlay_.add([this](OverlayLines& lines) { walkOverlay(lines); });
  if (stream_ != nullptr) overlay_.add([this](OverlayLines& lines) { streamOverlay(lines); });
}

void Viewer::contentChanged() {
  stream_content_.fetch_add(1);  // before the renderer hears of it: its walk frames reassemble
  renderer_->handle({clock_.nowMicroseconds(), ViewEventKind::kContentChanged});
  window_.wake();  // the overlay's byte count moved too
}

void Viewer::followView() {
  if (stream_ == nullptr) return;
  const FrameInfo latest = renderer_->status().latest;
  if (latest.generation == 0) return;
  const bool same = followed_ && followed_->view == latest.view &&
                    followed_->width == latest.width && followed_->height == latest.height;
  if (same) return;
  followed_ = latest;
  PerspectiveView walk_view;
  if (latest.view.walk) {
    if (renderer_->walkView(latest, &walk_view)) stream_->setView(walk_view);
  } else {
    stream_->setView(cameraOf(latest));
  }
}

void Viewer::streamOverlay(OverlayLines& lines) {
  const net::StreamStatus status = stream_->status();
  char line[160];
  if (!status.head_known) {
    std::snprintf(line, sizeof line, "waiting for the head: %llu bytes%s%s",
                  static_cast<unsigned long long>(status.bytes_received),
                  status.error.empty() ? "" : "  ", status.error.c_str());
  } else {
    std::snprintf(line, sizeof line, "%llu of %llu kB received  %u chunks pending%s",
                  static_cast<unsigned long long>(status.bytes_received / 1000),
                  static_cast<unsigned long long>(status.file_bytes / 1000), status.chunks_pending,
                  status.view_complete ? "  view complete" : "");
  }
  lines.emplace_back(line);
}

void Viewer::applyStyle(const StyleOptions& options) {
  if (const StyleError error = styler_->setOptions(options); error != StyleError::kNone) {
    const std::string message = std::string(styleName(options.style)) + ": " + describe(error);
    cli::printError("octopoint-view", message.c_str());
    return;
  }
  // Walk frames carry normals only for a style (DualResolutionRenderer::drawWalk says why).
  ViewEvent normals;
  normals.time_us = clock_.nowMicroseconds();
  normals.kind = ViewEventKind::kWalkNormals;
  normals.on = options.style != Style::kColour;
  renderer_->handle(normals);
  resolve_again_ = true;
}

void Viewer::nextStyle() {
  if (!styler_) {
    cli::printError(
        "octopoint-view",
        "styles: a streamed model has no normals; open a model file or an embedded model");
    return;
  }
  StyleOptions options = styler_->options();
  options.style = octopoint::nextStyle(options.style);
  applyStyle(options);
}

void Viewer::moveLight(int azimuth_steps, int elevation_steps) {
  if (!styler_) return;
  StyleOptions options = styler_->options();
  const auto step = [](Angle angle, int steps) {
    const int degrees = std::clamp(
        static_cast<int>(std::lround(signedDegreesOf(angle))) + steps * kLightStepDegrees, -90, 90);
    return Angle::fromDegrees(degrees);
  };
  options.light.azimuth = step(options.light.azimuth, azimuth_steps);
  options.light.elevation = step(options.light.elevation, elevation_steps);
  applyStyle(options);
}

void Viewer::nextSplatMode() {
  splats_ = splats_ == SplatMode::kBox ? SplatMode::kSmooth : SplatMode::kBox;
  resolve_again_ = true;
}

bool Viewer::resolveSmooth(const FrameInfo& info, std::span<std::uint8_t> rgb) {
  const LevelView* level = info.depth > 0 ? model_->levelOfDepth(info.depth) : nullptr;
  FrameSetup setup;
  if (level == nullptr || info.view.walk || info.view.fill ||
      buildFrameSetup(cameraOf(info), info.depth, kDefaultFractionBits, &setup) !=
          CameraError::kNone) {
    return false;
  }
  fitBlend(info.width, info.height);
  blend_frame_->clear(styler_->payload());
  if (!renderSmooth(InteractiveConfig{}.variant, *level, setup, *blend_frame_, *smooth_, palette_))
    return false;
  styler_->beginFrame(setup);
  return styler_->resolve(*blend_frame_, rgb, smooth_->pixelBlend()) == StyleError::kNone;
}

void Viewer::fitBlend(int width, int height) {
  if (blend_frame_ && blend_frame_->width() == width && blend_frame_->height() == height) return;
  blend_frame_.emplace(width, height);
  if (model_ != nullptr) {
    smooth_.emplace(width, height, *model_);  // with normals where the model has them
  } else {
    smooth_.emplace(width, height);
  }
}

bool Viewer::resolveStreamSmooth(const FrameInfo& info, std::span<std::uint8_t> rgb) {
  if (info.view.walk || info.view.fill || info.depth == 0) return false;
  fitBlend(info.width, info.height);
  blend_frame_->clear();
  // A snapshot of the chunks held now, as a render thread takes one: drawn without the lock.
  const ProgressiveModel* model = stream_->snapshot(stream_snapshot_);
  if (model == nullptr) return false;
  palette_ = paletteOf(model->baseModel());
  return model->drawSmooth(stream_snapshot_, cameraOf(info), InteractiveConfig{}.variant,
                           *blend_frame_, *smooth_, palette_) &&
         smooth_->resolveToRgb(*blend_frame_, palette_, kBackground, rgb);
}

void Viewer::resolveStyled(const Framebuffer& frame, const FrameInfo& info,
                           std::span<std::uint8_t> rgb) {
  smooth_shown_ = splats_ == SplatMode::kSmooth && resolveSmooth(info, rgb);
  if (smooth_shown_) return;
  if (styler_->options().style != Style::kColour && info.depth > 0) {
    // A walk frame is styled as octopoint-render --eye --style styles it: with its perspective
    // view's rotation and focal length; an orbit frame with its orthographic setup.
    FrameSetup setup;
    PerspectiveView view;
    bool styled = false;
    if (info.view.walk && renderer_->walkView(info, &view)) {
      styler_->beginPerspectiveFrame(view.world_to_camera, view.focal_q16);
      styled = true;
    } else if (!info.view.walk && buildFrameSetup(cameraOf(info), info.depth, kDefaultFractionBits,
                                                  &setup) == CameraError::kNone) {
      styler_->beginFrame(setup);
      styled = true;
    }
    if (styled && styler_->resolve(frame, rgb) == StyleError::kNone) return;
  }
  // The window's pixels are sized to the frame: resolveToRgb cannot refuse them.
  static_cast<void>(resolveToRgb(frame, *model_, kBackground, rgb));
}

KeyBindings Viewer::keyTable(Viewer* viewer) {
  KeyBindings keys;
  keys.press({SDLK_TAB}, "Tab", "switch between orbit mode and walk mode",
             [viewer](std::int64_t now) { viewer->toggleWalk(now); });
  keys.hold({SDLK_LEFT, SDLK_a}, "Left a", "hold to turn left; walk: to step left",
            NavigationKey::kYawLeft);
  keys.hold({SDLK_RIGHT, SDLK_d}, "Right d", "hold to turn right; walk: to step right",
            NavigationKey::kYawRight);
  keys.hold({SDLK_UP, SDLK_w}, "Up w", "hold to tilt up; walk: to walk forward",
            NavigationKey::kPitchUp);
  keys.hold({SDLK_DOWN}, "Down s", "hold to tilt down; walk: to walk back (s: walk mode only)",
            NavigationKey::kPitchDown);
  keys.walkHold({SDLK_e, SDLK_PAGEUP}, "e PgUp", "walk: hold to rise", NavigationKey::kRise);
  keys.walkHold({SDLK_PAGEDOWN}, "q PgDn", "walk: hold to sink (q: walk mode only)",
                NavigationKey::kSink);
  keys.describe("drag", "walk: drag with the left mouse button to turn the eye");
  constexpr bool kRepeats = true;
  keys.press(
      {SDLK_PLUS, SDLK_EQUALS, SDLK_KP_PLUS}, "+ -",
      "zoom in and out (held: again and again); walk: faster and slower, by 5/4",
      [viewer](std::int64_t now) { viewer->send(ViewEventKind::kZoomIn, now); }, kRepeats);
  keys.press(
      {SDLK_MINUS, SDLK_UNDERSCORE, SDLK_KP_MINUS}, "", "",
      [viewer](std::int64_t now) { viewer->send(ViewEventKind::kZoomOut, now); }, kRepeats);
  keys.describe("wheel", "zoom in (away from you) and out, one step of 5/4 per notch; walk: speed");
  keys.press({SDLK_f}, "f", "hole filling on and off",
             [viewer](std::int64_t now) { viewer->send(ViewEventKind::kToggleFill, now); });
  keys.press({SDLK_m}, "m",
             "box or smooth splats (magnified voxels blended, in every style; filling off)",
             [viewer](std::int64_t) { viewer->nextSplatMode(); });
  keys.press({SDLK_r}, "r", "back to the initial view",
             [viewer](std::int64_t now) { viewer->send(ViewEventKind::kReset, now); });
  keys.walkHold({SDLK_s}, "s p",
                "save the frame as octopoint-view-N.png in the current directory (walk: p)",
                NavigationKey::kPitchDown, [viewer](std::int64_t) { viewer->save(); });
  keys.press({SDLK_p}, "", "", [viewer](std::int64_t) { viewer->save(); });
  keys.press({SDLK_n}, "n", "walk: collision on and off (on at start: the eye stops at the model)",
             [viewer](std::int64_t now) { viewer->send(ViewEventKind::kToggleCollision, now); });
  keys.press({SDLK_c}, "c",
             "next style: colour, shaded, lines, toon, outlined (a model with normals)",
             [viewer](std::int64_t) { viewer->nextStyle(); });
  keys.press(
      {SDLK_j}, "j l i k", "move the light left, right, up, down by 15 degrees (shaded, toon)",
      [viewer](std::int64_t) { viewer->moveLight(-1, 0); }, kRepeats);
  keys.press(
      {SDLK_l}, "", "", [viewer](std::int64_t) { viewer->moveLight(1, 0); }, kRepeats);
  keys.press(
      {SDLK_i}, "", "", [viewer](std::int64_t) { viewer->moveLight(0, 1); }, kRepeats);
  keys.press(
      {SDLK_k}, "", "", [viewer](std::int64_t) { viewer->moveLight(0, -1); }, kRepeats);
  keys.walkHold({SDLK_q}, "Esc q", "quit (walk: Esc)", NavigationKey::kSink,
                [viewer](std::int64_t) { viewer->quit_ = true; });
  keys.press({SDLK_ESCAPE}, "", "", [viewer](std::int64_t) { viewer->quit_ = true; });
  return keys;
}

void Viewer::run() {
  std::int64_t next_tick_us = clock_.nowMicroseconds();
  while (!quit_) {
    const std::int64_t now_us = clock_.nowMicroseconds();
    if (now_us >= next_tick_us) {
      send(ViewEventKind::kTick, now_us);
      next_tick_us +=
          kTickPeriodMicroseconds * ((now_us - next_tick_us) / kTickPeriodMicroseconds + 1);
    }
    // One event (sleeping until the next tick at most), then all that are already queued.
    const int wait_ms = static_cast<int>((next_tick_us - now_us + 999) / 1000);
    for (std::optional<WindowEvent> event = window_.next(wait_ms); event && !quit_;
         event = window_.next(0)) {
      handle(*event);
    }
    if (pending_window_size_) {  // a drag resizes many times: only the last size is drawn
      resizeFrame(pending_window_size_->first, pending_window_size_->second);
      pending_window_size_.reset();
    }
    if (!quit_) {
      show();
      followView();
    }
  }
}

void Viewer::handle(const WindowEvent& event) {
  const std::int64_t now_us = clock_.nowMicroseconds();
  switch (event.kind) {
    case WindowEvent::Kind::kKeyDown:
    case WindowEvent::Kind::kKeyUp:
      handleKey(event);
      break;
    case WindowEvent::Kind::kWheel:
      for (int step = 0; step < std::abs(event.wheel_steps); ++step) {
        send(event.wheel_steps > 0 ? ViewEventKind::kZoomIn : ViewEventKind::kZoomOut, now_us);
      }
      break;
    case WindowEvent::Kind::kResized:
      pending_window_size_ = {event.width, event.height};
      break;
    case WindowEvent::Kind::kExposed:
      compose_again_ = true;
      break;
    case WindowEvent::Kind::kDragStart:
    case WindowEvent::Kind::kDrag:
    case WindowEvent::Kind::kDragEnd:
      drag(event);
      break;
    case WindowEvent::Kind::kFocusLost:  // their releases will go elsewhere: let them go now
      releaseAll(now_us);
      break;
    case WindowEvent::Kind::kWake:  // a new frame: show() takes it
      break;
    case WindowEvent::Kind::kClose:
      quit_ = true;
      break;
  }
}

void Viewer::handleKey(const WindowEvent& event) {
  const KeyBinding* binding = keys_.find(event.key);
  if (binding == nullptr) return;
  const std::int64_t now_us = clock_.nowMicroseconds();
  const bool down = event.kind == WindowEvent::Kind::kKeyDown;
  const std::optional<NavigationKey> navigation =
      binding->walk_navigation && walking() ? binding->walk_navigation : binding->navigation;
  if (navigation) {
    if (event.repeat) return;  // still held: the renderer turns the view by time, not by repeats
    renderer_->handle(
        {now_us, down ? ViewEventKind::kPress : ViewEventKind::kRelease, *navigation});
  } else if (binding->action && down && (!event.repeat || binding->repeats)) {
    binding->action(now_us);
  }
}

void Viewer::releaseAll(std::int64_t now_us) {
  for (int key = 0; key < kNavigationKeyCount; ++key) {
    renderer_->handle({now_us, ViewEventKind::kRelease, static_cast<NavigationKey>(key)});
  }
}

void Viewer::resizeFrame(int window_width, int window_height) {
  ViewEvent event;
  event.time_us = clock_.nowMicroseconds();
  event.kind = ViewEventKind::kResize;
  event.width = std::clamp(window_width / options_.scale, 1, kMaxFrameSide);
  event.height = std::clamp(window_height / options_.scale, 1, kMaxFrameSide);
  renderer_->handle(event);
  compose_again_ = true;
}

void Viewer::show() {
  FrameInfo info;
  const Framebuffer* frame = renderer_->acquireLatest(&info);
  const std::int64_t now_us = clock_.nowMicroseconds();
  if (frame == nullptr) return;
  const bool new_frame = info.generation != shown_info_.generation;
  if (new_frame || resolve_again_) {
    frame_rgb_.create(frame->height(), frame->width(), CV_8UC3);  // allocates on a new size only
    resolve_(*frame, info, {frame_rgb_.data, frame_rgb_.total() * 3});
    resolve_again_ = false;
    compose_again_ = true;
  }
  if (new_frame) ++frames_shown_;
  shown_info_ = info;
  drawn_rate_.record(now_us, renderer_->status().latest.generation);
  shown_rate_.record(now_us, frames_shown_);
  OverlayLines lines = overlay_.lines();
  if (!compose_again_ && lines == shown_lines_) return;

  const cv::Mat* scaled = &frame_rgb_;
  if (options_.scale > 1) {
    cv::resize(frame_rgb_, scaled_rgb_, {}, options_.scale, options_.scale, cv::INTER_NEAREST);
    scaled = &scaled_rgb_;
  }
  window_rgb_.create(window_.height(), window_.width(), CV_8UC3);
  const cv::Rect covered(0, 0, std::min(scaled->cols, window_rgb_.cols),
                         std::min(scaled->rows, window_rgb_.rows));
  if (covered.size() != window_rgb_.size()) {  // a frame drawn before the latest resize
    window_rgb_.setTo(cv::Scalar(kBackground.r, kBackground.g, kBackground.b));
  }
  (*scaled)(covered).copyTo(window_rgb_(covered));
  Overlay::draw(window_rgb_, lines);
  window_.present(
      window_rgb_.data, window_rgb_.cols, window_rgb_.rows, window_rgb_.step,
      std::uint32_t{kBackground.r} << 16 | std::uint32_t{kBackground.g} << 8 | kBackground.b);
  shown_lines_ = std::move(lines);
  compose_again_ = false;
}

void Viewer::defaultOverlay(OverlayLines& lines) const {
  const FrameInfo& info = shown_info_;
  char line[128];
  if (info.view.walk) {
    std::snprintf(line, sizeof line, "%s %lld.%01lld ms  walk  %dx%d  fov %s",
                  info.source == FrameSource::kFine ? "H" : "L",
                  static_cast<long long>(info.render_us / 1000),
                  static_cast<long long>(info.render_us / 100 % 10), info.width, info.height,
                  shortNumber(degreesOf(walk_.fov)).c_str());
  } else {
    std::snprintf(line, sizeof line, "%s %lld.%01lld ms  depth %d  %dx%d  zoom %.2f%s",
                  info.source == FrameSource::kFine ? "H" : "L",
                  static_cast<long long>(info.render_us / 1000),
                  static_cast<long long>(info.render_us / 100 % 10), info.depth, info.width,
                  info.height, zoomOf(info.view.zoom), info.view.fill ? "  fill" : "");
  }
  lines.emplace_back(line);
  if (splats_ == SplatMode::kSmooth) {
    lines.emplace_back(smooth_shown_ ? "smooth splats"
                                     : "smooth splats: off with filling or walking");
  }
  if (styler_ && styler_->options().style != Style::kColour) {
    const StyleOptions& style = styler_->options();
    std::snprintf(line, sizeof line, "%s  light %.0f,%.0f",
                  std::string(styleName(style.style)).c_str(), signedDegreesOf(style.light.azimuth),
                  signedDegreesOf(style.light.elevation));
    lines.emplace_back(line);
  }
  std::snprintf(line, sizeof line, "%llu fps drawn, %llu shown",
                static_cast<unsigned long long>(drawn_rate_.perSecond()),
                static_cast<unsigned long long>(shown_rate_.perSecond()));
  lines.emplace_back(line);
}

// The output-file rule of every tool (cli/output_file.h): whole or nothing, and an existing name
// that is not a regular file is refused, not replaced. A failure is reported and the viewer goes
// on.
void Viewer::save() {
  if (shown_info_.generation == 0) return;
  const std::string name = "octopoint-view-" + std::to_string(++saved_) + ".png";
  try {
    cv::Mat bgr;
    cv::cvtColor(frame_rgb_, bgr, cv::COLOR_RGB2BGR);
    std::vector<std::uint8_t> png;
    if (!cv::imencode(".png", bgr, png)) throw cli::Error(name + ": cannot encode the PNG");
    cli::writeFileAtomically(name, {reinterpret_cast<const char*>(png.data()), png.size()});
  } catch (const std::exception& error) {
    cli::printError("octopoint-view", error.what());
    return;
  }
  const FrameInfo& info = shown_info_;
  std::string style;
  if (styler_ && styler_->options().style != Style::kColour) {
    char text[96];
    std::snprintf(text, sizeof text, " --style %s --light %.0f,%.0f",
                  std::string(styleName(styler_->options().style)).c_str(),
                  signedDegreesOf(styler_->options().light.azimuth),
                  signedDegreesOf(styler_->options().light.elevation));
    style = text;
  }
  if (info.view.walk) {
    std::printf("saved %s (%s): --size %dx%d%s%s%s\n", name.c_str(),
                info.source == FrameSource::kFine ? "H" : "L", info.width, info.height,
                walkOptions(info.view.walker).c_str(), info.view.fill ? " --fill" : "",
                style.c_str());
    std::fflush(stdout);
    return;
  }
  const char* splats = smooth_shown_ ? " --splats smooth" : "";
  std::printf("saved %s (%s): --size %dx%d --yaw %.2f --pitch %.2f --zoom %.4f --depth %d%s%s%s\n",
              name.c_str(), info.source == FrameSource::kFine ? "H" : "L", info.width, info.height,
              degreesOf(info.view.yaw), degreesOf(info.view.pitch), zoomOf(info.view.zoom),
              info.depth, info.view.fill ? " --fill" : "", style.c_str(), splats);
  std::fflush(stdout);
}

}  // namespace octopoint
