#pragma once
// octopoint/interactive.h: The dual-resolution render threads and the events that drive them.
// The manual of the whole library is octopoint/octopoint.h.

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "octopoint/fixed.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/render.h"

// The time source of the interactive renderer (docs/design.md section 5), injectable so that
// scripted tests run on a clock they set themselves. Time is an integer count of microseconds.

namespace octopoint {

class Clock {
 public:
  virtual ~Clock() = default;
  virtual std::int64_t nowMicroseconds() const = 0;
};

// Real time, monotonic.
class SteadyClock final : public Clock {
 public:
  std::int64_t nowMicroseconds() const override {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
};

// A clock that only moves when told to (scripted timelines, tests). A mutex rather than a 64-bit
// atomic: ARMv5 has no lock-free 64-bit atomics.
class ManualClock final : public Clock {
 public:
  std::int64_t nowMicroseconds() const override {
    const std::lock_guard lock(mutex_);
    return now_us_;
  }
  void set(std::int64_t now_us) {
    const std::lock_guard lock(mutex_);
    now_us_ = now_us;
  }

 private:
  mutable std::mutex mutex_;
  std::int64_t now_us_ = 0;
};

}  // namespace octopoint

// What drives the interactive renderer: timed view events from an event source, either the
// viewer's window (tools/view_window.cpp: SDL2 key presses and releases, wheel, resizes) or a
// scripted timeline (tests, benchmarks).

namespace octopoint {

// Keys that move the view while held. In orbit mode the four arrows turn the model at a fixed
// speed in degrees per second. In walk mode (ViewParameters::walk) the same four move the eye
// forward, back, left and right, kRise and kSink move it up and down (ignored in orbit mode), at
// the walk speed in cube edges per second; kDrag is the mouse button held while dragging to turn
// the eye (kTurn events): it moves nothing by itself, but like a held key it keeps the fine frame
// back until it is let go.
enum class NavigationKey : std::uint8_t {
  kYawLeft,    // walk: step left
  kYawRight,   // walk: step right
  kPitchUp,    // walk: forward
  kPitchDown,  // walk: back
  kRise,
  kSink,
  kDrag,
};
inline constexpr int kNavigationKeyCount = 7;
inline constexpr int kOrbitNavigationKeyCount = 4;  // kYawLeft..kPitchDown move the orbit view

enum class ViewEventKind : std::uint8_t {
  kPress,            // a navigation key goes down (repeats of a held key are ignored)
  kRelease,          // a navigation key goes up
  kTick,             // the frame tick (every kTickPeriodMicroseconds): the fine frame may start
  kZoomIn,           // one zoom step in (walk mode: the walk speed one step of 5/4 faster)
  kZoomOut,          // one zoom step out (walk mode: slower)
  kToggleFill,       // hole filling on/off
  kReset,            // back to the initial view
  kToggleWalk,       // orbit mode <-> walk mode (only where the renderer canWalk())
  kTurn,             // walk mode: the eye turns by turn_yaw, turn_pitch (a mouse drag)
  kResize,           // the frame becomes width x height pixels (the window was resized)
  kToggleCollision,  // walk mode: collision on/off (where the config gives the eye a radius)
  kWalkNormals,      // walk frames carry normals from now on (`on`: config.payload, for a style)
                     // or not (colour only, as octopoint-render --eye draws them)
  kContentChanged,   // the model has more in it (a streamed chunk arrived): the fine frame is due
                     // again, without changing the view or aborting a fine frame under way
  kQuit,             // the source has ended
};

inline constexpr std::int64_t kTickPeriodMicroseconds = 100'000;

struct ViewEvent {
  std::int64_t time_us = 0;  // on the renderer's clock
  ViewEventKind kind = ViewEventKind::kTick;
  NavigationKey key = NavigationKey::kYawLeft;  // for kPress and kRelease
  std::int32_t width = 0;                       // for kResize: the new frame size
  std::int32_t height = 0;
  std::int32_t turn_yaw = 0;    // for kTurn: in 1/65536 turn, > 0 to the right
  std::int32_t turn_pitch = 0;  // > 0 up
  bool on = false;              // for kWalkNormals
};

class EventSource {
 public:
  virtual ~EventSource() = default;
  // The next event, waiting at most `max_wait_ms` for it; nullopt when none came in that time.
  // After kQuit the source is finished.
  [[nodiscard]] virtual std::optional<ViewEvent> next(std::int32_t max_wait_ms) = 0;
};

// A scripted list of events played on a ManualClock: next() sets the clock to the event's time
// and returns it at once, with a kTick inserted at every multiple of kTickPeriodMicroseconds from
// 0 to `end_us` (an event at the same time as a tick comes first), then kQuit at `end_us`.
class ScriptedTimeline final : public EventSource {
 public:
  ScriptedTimeline(std::vector<ViewEvent> events, std::int64_t end_us, ManualClock& clock);
  [[nodiscard]] std::optional<ViewEvent> next(std::int32_t max_wait_ms) override;

 private:
  std::vector<ViewEvent> events_;
  std::size_t next_ = 0;
  ManualClock& clock_;
};

}  // namespace octopoint

// Dual-resolution interactive rendering (docs/design.md section 5): two render threads behind one
// view.
//
// Levels: built from a whole model, H draws the depth-auto level of each view
// (renderer/level_of_detail.h) and L the stored depth one coarser (the same when H's is the
// coarsest), whose voxels are twice as wide, so its footprint splats are twice as large. Built
// from two fixed levels, each thread draws its own.
// - L (coarse) renders the coarse level continuously while a navigation key is held, and once
//   after a step change (zoom, reset, fill toggle). The view at a frame is a function of time
//   (held keys turn it at `degrees_per_second` since their press), so the rotation does not
//   depend on the frame rate.
// - H (fine) renders the fine level at the first tick (ViewEvent kTick, every 100 ms) at which no
//   key is held and the fine frame of the current view is not yet on screen. A key press aborts
//   it through the render API's abort flag (polled by the decoder at tree level 3).
// - Only complete frames are shown: each thread draws into its own back buffer and hands it over
//   by swapping pointers under the mutex; the display swaps the newest hand-over into its front
//   buffer. Four buffers, allocated at construction; no thread ever writes the front buffer.
//   An aborted frame is never handed over, nor a frame older than the one on screen (a fine
//   frame of a view that has changed since H started, or a coarse frame that ends after the fine
//   frame of the same view).
// - The frame follows the window: a kResize event changes the size of the frames drawn from then
//   on (a new view: H is aborted, L draws once). A buffer is reallocated by the thread that owns it
//   when it next draws into it at a new size (a back buffer belongs to its thread between hand-
//   overs, so nobody else can be reading it), and so is each thread's hole filler: after a
//   resize each of the four buffers and two fillers is reallocated at most once, and drawing at a
//   settled size never allocates. A frame already drawn at the old size may still be handed over
//   (it is complete); FrameInfo says each frame's size.
// - Idle threads sleep on condition variables; nothing polls.
//
// Threads: std::thread with a `stopping_` flag under the same mutex as the rest of the state,
// not std::jthread/std::stop_token. The waits are condition-variable waits on that mutex anyway,
// so the flag costs nothing, and std::stop_token's shared state relies on atomic read-modify-
// write operations, which the device (ARMv5) does not have lock-free. The per-frame abort is a
// std::atomic<bool> (the render API polls it without a lock) used with plain loads and stores
// only, which are lock-free everywhere; it is reset by H itself under the mutex, so a stop_token
// (which can be requested only once) would not fit it either.

namespace octopoint {

class PerspectiveRenderer;  // renderer/perspective_renderer.h: walk mode's frames
class CollisionWorld;       // renderer/collision.h: what walk mode's eye collides with
class ModelCollision;       // renderer/collision.h: a whole model as one

struct WalkCollision;    // interactive/view_motion.h
struct PerspectiveView;  // renderer/perspective.h: a walk frame's view

enum class FrameSource : std::uint8_t { kCoarse, kFine };  // drawn by L or by H

// Walk mode's eye (renderer/perspective.h's PerspectiveCamera): where it stands, in Q.24 cube
// edges about the cube's centre in the model's axes (x right, y down, z away), and where it looks.
struct WalkEye {
  Point3<std::int64_t> eye{0, 0, -2 * (std::int64_t{1} << 24)};  // Q.24: two edges before the cube
  Angle yaw;    // turns the view right; 0 looks along +z
  Angle pitch;  // turns it up
  Angle roll;
  bool operator==(const WalkEye&) const = default;
};

struct ViewParameters {
  Angle yaw;
  Angle pitch;
  Q16 zoom = Q16::fromRaw(Q16::kOneRaw);  // Q16.16
  bool fill = false;  // hole filling: footprint splats leave none to fill (the f key turns it on)
  // Walk mode: the frame is the perspective view from `walker` (detail by distance, occlusion
  // culling; docs/perspective.md), and yaw, pitch, zoom and fill wait for orbit mode.
  bool walk = false;
  WalkEye walker;
  // Walk frames carry normals (kWalkNormals: the display shows a style); colour-only otherwise.
  bool walk_normals = false;
  bool operator==(const ViewParameters&) const = default;
};

// Draws a walk frame of a model that is not one ModelView (a chunked model streaming in:
// tools/viewer.cpp with --url) into a cleared colour frame: `view` is the frame's
// (DualResolutionRenderer::walkView), the coarse frame (`source` kCoarse) a stored depth coarser
// where it can. Returns false when `abort` stopped it; sets `finest_depth` to the finest depth it
// drew (0: nothing), which hole filling bridges by.
using WalkDrawFunction =
    std::function<bool(FrameSource source, const PerspectiveView& view, Framebuffer& frame,
                       const std::atomic<bool>* abort, int* finest_depth)>;

struct InteractiveConfig {
  std::int32_t width = 320;  // the initial frame size (kResize changes it), 1..kMaxViewportSide
  std::int32_t height = 240;
  std::int32_t degrees_per_second = 90;
  Variant variant = defaultVariant();
  ViewParameters initial_view;
  // Walk mode: the field of view, the speed the eye moves at (Q.24 cube edges per second,
  // 1..kMaxWalkSpeed; the wheel changes it by steps of 5/4), and, for the eye entering walk mode
  // from orbit mode, the eye of that orbit view in perspective (orbitPerspective).
  Angle fov = Angle::fromDegrees(60);
  std::int64_t walk_speed = std::int64_t{1} << 22;  // a quarter cube edge a second
  // Walk mode's collision (docs/perspective.md, "Collision"): the eye's radius (Q.24 cube edges,
  // 1..one cube edge; 0: no collision) and, for gravity, its height above the ground (Q.24, above
  // the radius; 0: none). With a radius, collision starts on; kToggleCollision turns it off and
  // on again. It collides with the model's finest level.
  std::int64_t walk_radius = 0;
  std::int64_t walk_eye_height = 0;
  // Walk mode's near plane, Q.24 cube edges; 0: half the voxel edge of the model's finest depth
  // (nearPlaneForDepth, renderer/perspective.h).
  std::int64_t near = 0;
  // Called from a render thread, without any lock held, after each frame it hands over: lets a
  // display sleep until there is something to show (the viewer posts a window event). Must not
  // call back into the renderer.
  std::function<void()> frame_ready;
  // What the frames carry besides depth and colour: PixelPayload::kColourNormal lets the display
  // draw them in any style (octopoint/styles.h); it needs a model with normals.
  PixelPayload payload = PixelPayload::kColour;
  // For a renderer of whole views (ViewDrawFunction): draws its walk frames, so that it can walk
  // (canWalk); must be safe to call from both render threads at once. Walk mode's near plane is
  // then `near` (0: PerspectiveCamera's default).
  WalkDrawFunction walk_draw;
  // With walk_draw: what walk mode's eye collides with (a scene's instances,
  // renderer/scene_collision.h; the caller's, outliving the renderer), with walk_radius as for a
  // model. nullptr: no collision.
  const CollisionWorld* walk_world = nullptr;
  // There is no orbit view (a scene: octopoint-view --city): the renderer stays in walk mode and
  // kToggleWalk does nothing; initial_view.walk must be set.
  bool walk_only = false;
};

struct FrameInfo {
  FrameSource source = FrameSource::kCoarse;
  std::uint64_t generation = 0;    // 1, 2, ... in the order frames were handed over
  std::uint64_t view_version = 0;  // bumped by every event that changes the view
  std::int64_t view_time_us = 0;   // the clock time the view was taken at
  ViewParameters view;
  std::int32_t width = 0;  // the frame's size (the size in force when it was started)
  std::int32_t height = 0;
  std::int64_t render_us = 0;  // real time spent drawing (decode + fill), for the overlay
  int depth = 0;               // the depth drawn (0: none, the camera was refused)
  std::uint32_t checksum = 0;  // frameChecksum of the finished frame
};

struct RendererStatus {
  std::uint64_t coarse_shown = 0;  // frames handed over, per thread
  std::uint64_t fine_shown = 0;
  std::uint64_t buffers_allocated = 0;  // frame buffers and hole fillers (re)allocated by resizes
  std::uint64_t fine_started = 0;
  std::uint64_t fine_aborted = 0;
  std::uint64_t stale_dropped = 0;  // complete frames not handed over: a newer one was out
  std::uint64_t view_version = 0;   // of the current view (the one the next fine frame shows)
  bool coarse_busy = false;
  bool fine_busy = false;
  FrameInfo latest;             // the newest frame handed over (generation 0: none yet)
  bool walk = false;            // the current view is walk mode's
  std::int64_t walk_speed = 0;  // Q.24 cube edges per second
  bool walk_collision = false;  // walk mode's eye collides with the model
};

// The walk speed's bounds, Q.24 cube edges per second: 1/1024 to 64 cube edges a second (a held
// key then stays within int64 for 2^32 s).
inline constexpr std::int64_t kMinWalkSpeed = std::int64_t{1} << 14;
inline constexpr std::int64_t kMaxWalkSpeed = std::int64_t{1} << 30;

// Draws `level` with `setup` into a cleared frame; the default is renderLevel with the configured
// variant. Tests inject a slower one.
using RenderFunction = std::function<bool(const LevelView& level, const FrameSetup& setup,
                                          Framebuffer& frame, const std::atomic<bool>* abort)>;

// Draws a whole view into a cleared frame, for models that are not one ModelView (a chunked model
// streaming in: tools/view_main.cpp with --url): the fine frame (`source` kFine) at the depth the
// view needs, the coarse one at a coarser depth. Returns false when `abort` stopped it; sets
// `depth` to the depth drawn (0: nothing).
using ViewDrawFunction =
    std::function<bool(FrameSource source, const Camera& camera, Framebuffer& frame,
                       const std::atomic<bool>* abort, int* depth)>;

// A cheap integrity stamp of a frame's colours and depths.
std::uint32_t frameChecksum(const Framebuffer& frame);

class DualResolutionRenderer {
 public:
  // The levels (of one validated model) and `clock` must outlive the renderer. Starts both
  // threads; H draws the initial view at once.
  DualResolutionRenderer(const LevelView& coarse, const LevelView& fine, const Clock& clock,
                         const InteractiveConfig& config, RenderFunction render = {});
  // The model and `clock` must outlive the renderer. H draws each view at depth auto, L one stored
  // depth coarser (see the header comment).
  DualResolutionRenderer(const ModelView& model, const Clock& clock,
                         const InteractiveConfig& config, RenderFunction render = {});
  // Whatever `draw_view` draws (see ViewDrawFunction), which must be safe to call from both render
  // threads at once. A kContentChanged event makes the fine frame due again.
  DualResolutionRenderer(ViewDrawFunction draw_view, const Clock& clock,
                         const InteractiveConfig& config);
  ~DualResolutionRenderer();  // stops both threads (aborting H) and joins them
  DualResolutionRenderer(const DualResolutionRenderer&) = delete;
  DualResolutionRenderer& operator=(const DualResolutionRenderer&) = delete;

  // Applies one event from the event source (kQuit is the caller's business).
  void handle(const ViewEvent& event);

  // Whether kToggleWalk can enter walk mode: a renderer built from a whole model, or given
  // config.walk_draw.
  bool canWalk() const { return model_ != nullptr || config_.walk_draw != nullptr; }

  // The perspective view the walk frame `info` describes was drawn with, for the display to style
  // it (FrameStyler::beginPerspectiveFrame); false when `info` is not a walk frame or its camera
  // was refused (the frame is empty).
  [[nodiscard]] bool walkView(const FrameInfo& info, PerspectiveView* view) const;

  // For the display, from one thread only: makes the newest complete frame the front buffer and
  // returns it (nullptr before the first frame). The front buffer is not touched by anyone until
  // the next call.
  [[nodiscard]] const Framebuffer* acquireLatest(FrameInfo* info);

  [[nodiscard]] RendererStatus status() const;
  // Waits (sleeping) until `predicate(status())` holds or `timeout` passes; returns whether it
  // held.
  [[nodiscard]] bool waitUntil(const std::function<bool(const RendererStatus&)>& predicate,
                               std::chrono::milliseconds timeout) const;

 private:
  DualResolutionRenderer(const ModelView* model, const LevelView* coarse, const LevelView* fine,
                         ViewDrawFunction draw_view, const Clock& clock,
                         const InteractiveConfig& config, RenderFunction render);

  struct Slot {
    Framebuffer frame;
    FrameInfo info;
  };
  struct HeldKey {
    bool held = false;
    std::int64_t since_us = 0;
  };
  // What a render thread owns besides its back buffer: the hole filler, as wide as its frames.
  // And walk mode's renderer (its indexes built once; its occlusion tiles once per size).
  struct Worker {
    HoleFiller filler;
    std::int32_t filler_width;
    std::unique_ptr<PerspectiveRenderer> perspective;  // when built from a model
  };

  void coarseLoop();
  void fineLoop();
  bool anyKeyHeld() const;     // the mouse button of a drag included
  bool movingKeyHeld() const;  // a key whose motion goes on with time (not the drag)
  ViewParameters viewAt(std::int64_t time_us) const;  // base view plus the held keys' motion
  WalkCollision walkCollision() const;  // what the walk collides with now (nothing when off)
  // Makes the held keys' motion up to `time_us` part of the base view (they move on from there):
  // before what changes how they move (a turn, the speed, the mode).
  void foldMotion(std::int64_t time_us);
  void toggleWalk(std::int64_t time_us);
  // Draws a walk mode frame into `slot` (unlocked).
  [[nodiscard]] bool drawWalk(Slot& slot, Worker& worker, const std::atomic<bool>* abort);
  void changeView();  // a new view: aborts H, the fine frame is due again
  // Starts a frame in `slot` (locked): the current view, its version, time and size.
  void beginFrame(Slot& slot, FrameSource source);
  // Makes the slot's frame and the worker's filler the slot's size (unlocked: both belong to the
  // calling thread); returns how many it reallocated.
  static int fitBuffers(Slot& slot, Worker& worker);
  // Draws a frame into `slot` (unlocked: the slot belongs to the calling thread).
  [[nodiscard]] bool draw(Slot& slot, Worker& worker, const std::atomic<bool>* abort);
  // The level a frame of `source` draws for `camera`; nullptr when the camera is refused.
  const LevelView* levelFor(FrameSource source, const Camera& camera) const;
  // Hands `slot` over unless a newer frame is out (locked); returns whether it did.
  [[nodiscard]] bool handOver(std::unique_ptr<Slot>& slot);
  // Calls config_.frame_ready with the mutex released for the call.
  void notifyFrameReady(std::unique_lock<std::mutex>& lock);

  const ModelView* model_ = nullptr;  // when built from a model: levels by projected size
  const LevelView* coarse_level_ = nullptr;
  const LevelView* fine_level_ = nullptr;
  ViewDrawFunction draw_view_;  // when built from one: draws whole views
  const Clock& clock_;
  const InteractiveConfig config_;
  RenderFunction render_;
  Worker coarse_worker_;
  Worker fine_worker_;

  mutable std::mutex mutex_;
  std::condition_variable coarse_wake_;
  std::condition_variable fine_wake_;
  mutable std::condition_variable status_changed_;
  bool stopping_ = false;
  std::array<HeldKey, kNavigationKeyCount> held_{};
  ViewParameters base_view_;
  std::int64_t walk_speed_;  // Q.24 cube edges per second
  // With config_.walk_radius: what the walk collides with, the whole model's finest level (when
  // it can be indexed) or config_.walk_world.
  std::unique_ptr<const ModelCollision> collision_;
  const CollisionWorld* collision_world_ = nullptr;
  bool collide_ = false;  // collision on (toggled)
  std::int32_t width_;    // the size of the frames drawn from now on
  std::int32_t height_;
  std::uint64_t view_version_ = 1;
  bool coarse_once_ = false;    // one coarse frame after a step change
  bool fine_due_ = true;        // the fine frame of the current view is not on screen yet
  bool fine_requested_ = true;  // H should start (set by a tick)
  std::uint64_t fine_busy_version_ = 0;
  std::uint64_t content_version_ = 0;  // bumped by kContentChanged
  std::atomic<bool> fine_abort_{false};
  std::unique_ptr<Slot> coarse_back_, fine_back_, handed_over_, front_;
  bool handed_over_is_new_ = false;
  std::uint64_t generation_ = 0;
  RendererStatus status_;

  std::thread coarse_thread_;
  std::thread fine_thread_;
};

}  // namespace octopoint
