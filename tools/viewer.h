// The window of octopoint-view: an SDL2 window that drives the dual-resolution renderer (arrow
// keys turn the view, the style keys restyle it) and shows its newest frame with an overlay.

#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "interactive/scene_walk.h"
#include "octopoint/http.h"
#include "octopoint/interactive.h"
#include "octopoint/model.h"
#include "octopoint/progressive.h"
#include "octopoint/smooth.h"
#include "octopoint/styles.h"
#include "tools/model_source.h"
#include "tools/scan_eye.h"
#include "tools/view_keys.h"
#include "tools/view_overlay.h"
#include "tools/view_window.h"
#include "tools/walk_collision.h"

namespace octopoint {

// The frame's sides, in frame pixels (a window pixel is --scale of them).
constexpr int kMaxFrameSide = 4096;
constexpr int kMinFrameSide = 16;

// octopoint-view's command line.
struct ViewerOptions {
  ModelSourceOptions source;  // the point budget applies with --url only
  int width = 640;
  int height = 480;
  int scale = 1;
  int degrees_per_second = 90;
  // Walk mode (docs/perspective.md, "The viewer's walk mode"): --eye and --look in the scan's
  // units, as octopoint-render takes them; --fov; --walk-speed in scan units per second; --near
  // in scan units.
  std::optional<ScanPoint> eye;
  std::optional<Look> look;
  std::optional<Angle> fov;
  std::optional<double> walk_speed;
  // --eye-radius and --eye-height (docs/perspective.md, "Collision"): walk mode's collision.
  CollisionOptions collision;
  std::optional<double> near;
  std::string city;   // --city SCENE.json: walk a scene of many models (docs/city.md)
  std::string cells;  // --cells CELLS: with --city, its visibility cells
};

// What the viewer's walk mode needs of the model: where its cube lies in the scan, the eye to
// start from (with --eye), the speed in Q.24 cube edges per second and the near plane in Q.24 cube
// edges (modelNearPlane, tools/scan_eye.h). A cli::Error, one line, for options it cannot take.
struct WalkStart {
  std::optional<ScanCube> cube;  // none: walk mode shows no scan units (a model of format 1..3)
  std::optional<WalkEye> eye;
  Angle fov = Angle::fromDegrees(60);
  std::int64_t speed = 0;
  WalkBody body;  // collision (on until n turns it off): the radius, and the eye height for gravity
  std::int64_t near = 0;  // 0: no model (--url)
};
WalkStart walkStart(const ViewerOptions& options, const ModelView* model);
// The same for a scene (--city): in scene edges, --eye required (a scene has no orbit view).
WalkStart cityWalkStart(const ViewerOptions& options);

// A short number for the overlay, "%.4g" (the save line gives them exactly).
std::string shortNumber(double value);

class Viewer {
 public:
  // Shows `model`; or, when `model` is null, the chunked model `stream` brings in; or, when both
  // are null, walks `scene` (which must outlive the viewer).
  Viewer(const ViewerOptions& options, const WalkStart& walk, const ModelView* model,
         net::ModelStream* stream, SceneWalk* scene = nullptr);
  // From the stream's thread: more of the model arrived.
  void contentChanged();
  // Shows the window until the user quits.
  void run();
  // The key table; `viewer` may be null when only the help text is wanted.
  static KeyBindings keyTable(Viewer* viewer);

 private:
  void handle(const WindowEvent& event);
  void handleKey(const WindowEvent& event);
  void send(ViewEventKind kind, std::int64_t now_us) { renderer_->handle({now_us, kind}); }
  bool walking() const { return renderer_->status().walk; }
  // Tab: orbit <-> walk; every navigation key is let go first (a key's meaning changes).
  void toggleWalk(std::int64_t now_us);
  void releaseAll(std::int64_t now_us);
  void drag(const WindowEvent& event);
  void resizeFrame(int window_width, int window_height);
  // Puts the newest frame on the screen when it, the window or the overlay's text changed.
  void show();
  void save();
  void defaultOverlay(OverlayLines& lines) const;
  // The overlay's word on collision: on (with gravity) or off, and the key that turns it.
  std::string collisionText() const;
  void walkOverlay(OverlayLines& lines) const;
  // The eye and look of a walk frame as octopoint-render options (exact: --eye X,Y,Z --look ...).
  std::string walkOptions(const WalkEye& walker) const;
  void streamOverlay(OverlayLines& lines);
  // Tells the stream which view to fetch for: the one on screen, as it changes.
  void followView();
  // The style keys: the next style, or the light turned by a step (docs/styles.md).
  void nextStyle();
  void moveLight(int azimuth_steps, int elevation_steps);
  void applyStyle(const StyleOptions& options);
  void resolveStyled(const Framebuffer& frame, const FrameInfo& info, std::span<std::uint8_t> rgb);
  // `m`: box or smooth splats (docs/splats.md).
  void nextSplatMode();
  // Draws the frame `info` describes smoothly into blend_frame_ and resolves it in the style into
  // `rgb`; false where smooth splats do not apply (hole filling, walking, no depth drawn).
  bool resolveSmooth(const FrameInfo& info, std::span<std::uint8_t> rgb);
  // The same for a streamed model: the chunks held now, drawn smoothly at the depth the view
  // needs (ProgressiveModel::drawSmooth), as octopoint-render --url --splats smooth draws them.
  bool resolveStreamSmooth(const FrameInfo& info, std::span<std::uint8_t> rgb);
  // Sizes blend_frame_ and smooth_ to the frame on screen (allocates on a new size only).
  void fitBlend(int width, int height);

  const ViewerOptions options_;
  const WalkStart walk_;
  const ModelView* model_;
  net::ModelStream* stream_;
  SceneWalk* scene_;
  const SteadyClock clock_;
  std::atomic<std::uint64_t> stream_content_{0};  // chunks accepted (contentChanged)
  ViewWindow window_;  // before renderer_: its threads wake the window until they are joined
  std::unique_ptr<DualResolutionRenderer> renderer_;
  KeyBindings keys_;
  Overlay overlay_;
  std::optional<FrameStyler> styler_;  // none for a stream: the styles need a model with normals
  SplatMode splats_ = SplatMode::kBox;
  // Smooth splats are drawn here, on the window's thread, at the size of the frame on screen:
  // the render threads draw box frames, and the blend draws the frame on screen again, in the
  // style's payload (docs/splats.md).
  std::optional<Framebuffer> blend_frame_;
  std::optional<SmoothSplats> smooth_;
  PaletteRgb palette_{};
  ProgressiveFrame stream_snapshot_;  // the chunks held, for a streamed model's smooth frame
  bool smooth_shown_ = false;         // the frame on screen was blended
  // Turns a frame into RGB888 for the screen and for `s` (default: its palette colours).
  std::function<void(const Framebuffer&, const FrameInfo&, std::span<std::uint8_t>)> resolve_;

  bool quit_ = false;
  bool resolve_again_ = false;  // the frame on screen must be turned into RGB again
  bool compose_again_ = true;   // the window must be drawn again
  std::optional<std::pair<int, int>> pending_window_size_;
  FrameInfo shown_info_;  // of the frame on screen (generation 0: none yet)
  cv::Mat frame_rgb_;     // the frame on screen in RGB, frame size
  cv::Mat scaled_rgb_;    // the same scaled by --scale
  cv::Mat window_rgb_;    // what the window shows, window size
  OverlayLines shown_lines_;
  std::uint64_t frames_shown_ = 0;
  RateCounter drawn_rate_;
  RateCounter shown_rate_;
  int saved_ = 0;
  std::optional<FrameInfo> followed_;  // the frame whose view the stream fetches for
  // The drag under way: its motion so far (window pixels) and the turn already sent for it.
  std::int64_t drag_x_ = 0, drag_y_ = 0;
  std::int64_t drag_yaw_sent_ = 0, drag_pitch_sent_ = 0;
};

}  // namespace octopoint
