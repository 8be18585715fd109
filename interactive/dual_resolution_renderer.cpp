#include <algorithm>
#include <cassert>
#include <span>

#include "fixedpoint/trig.h"
#include "interactive/view_motion.h"
#include "octopoint/camera.h"
#include "octopoint/interactive.h"
#include "renderer/collision.h"
#include "renderer/level_of_detail.h"
#include "renderer/perspective.h"
#include "renderer/perspective_depth.h"
#include "renderer/perspective_renderer.h"

namespace octopoint {
namespace {

// Zoom steps of 5/4 (Q16.16), kept within what a 320..8192 pixel frame can address.
constexpr std::int64_t kZoomStepNumerator = 5;
constexpr std::int64_t kZoomStepDenominator = 4;
constexpr std::int32_t kMinZoomRaw = Q16::kOneRaw / 8;
constexpr std::int32_t kMaxZoomRaw = Q16::kOneRaw * 16;

Q16 zoomStep(Q16 zoom, bool in) {
  const std::int64_t raw =
      in ? std::int64_t{zoom.raw()} * kZoomStepNumerator / kZoomStepDenominator
         : std::int64_t{zoom.raw()} * kZoomStepDenominator / kZoomStepNumerator;
  return Q16::fromRaw(
      static_cast<std::int32_t>(std::clamp<std::int64_t>(raw, kMinZoomRaw, kMaxZoomRaw)));
}

std::int64_t steadyMicroseconds() { return SteadyClock().nowMicroseconds(); }

}  // namespace

std::uint32_t frameChecksum(const Framebuffer& frame) {
  // Sum of position-weighted words: any changed, moved or swapped pixel changes it (mod 2^32).
  const std::span<const std::uint32_t> pixels = frame.pixels();
  std::uint32_t sum = 0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    sum += pixels[i] * (2 * static_cast<std::uint32_t>(i) + 1);
  }
  return sum;
}

DualResolutionRenderer::DualResolutionRenderer(const LevelView& coarse, const LevelView& fine,
                                               const Clock& clock, const InteractiveConfig& config,
                                               RenderFunction render)
    : DualResolutionRenderer(nullptr, &coarse, &fine, {}, clock, config, std::move(render)) {}

DualResolutionRenderer::DualResolutionRenderer(const ModelView& model, const Clock& clock,
                                               const InteractiveConfig& config,
                                               RenderFunction render)
    : DualResolutionRenderer(&model, nullptr, nullptr, {}, clock, config, std::move(render)) {}

DualResolutionRenderer::DualResolutionRenderer(ViewDrawFunction draw_view, const Clock& clock,
                                               const InteractiveConfig& config)
    : DualResolutionRenderer(nullptr, nullptr, nullptr, std::move(draw_view), clock, config, {}) {}

DualResolutionRenderer::DualResolutionRenderer(const ModelView* model, const LevelView* coarse,
                                               const LevelView* fine, ViewDrawFunction draw_view,
                                               const Clock& clock, const InteractiveConfig& config,
                                               RenderFunction render)
    : model_(model),
      coarse_level_(coarse),
      fine_level_(fine),
      draw_view_(std::move(draw_view)),
      clock_(clock),
      config_(config),
      render_(std::move(render)),
      coarse_worker_{HoleFiller(config.width), config.width, nullptr},
      fine_worker_{HoleFiller(config.width), config.width, nullptr},
      base_view_(config.initial_view),
      walk_speed_(std::clamp(config.walk_speed, kMinWalkSpeed, kMaxWalkSpeed)),
      width_(config.width),
      height_(config.height) {
  status_.view_version = view_version_;
  if (model_ != nullptr) {
    coarse_worker_.perspective = std::make_unique<PerspectiveRenderer>(*model_);
    fine_worker_.perspective = std::make_unique<PerspectiveRenderer>(*model_);
    if (config.walk_radius > 0) {
      if (std::optional<CollisionModel> collision = CollisionModel::of(*model_)) {
        collision_ = std::make_unique<const ModelCollision>(std::move(*collision));
        collision_world_ = collision_.get();
        collide_ = true;
      }
    }
  } else if (!config.walk_draw) {
    base_view_.walk = false;  // walk mode needs the whole model, or a walk drawer
  } else if (config.walk_world != nullptr && config.walk_radius > 0) {
    collision_world_ = config.walk_world;
    collide_ = true;
  }
  status_.walk = base_view_.walk;
  status_.walk_speed = walk_speed_;
  status_.walk_collision = collide_;
  if (!render_) {
    const Variant variant = config.variant;
    render_ = [variant](const LevelView& level, const FrameSetup& setup, Framebuffer& frame,
                        const std::atomic<bool>* abort) {
      return renderLevel(variant, level, setup, frame, abort);
    };
  }
  for (std::unique_ptr<Slot>* slot : {&coarse_back_, &fine_back_, &handed_over_, &front_}) {
    *slot = std::make_unique<Slot>(Slot{Framebuffer(config.width, config.height), FrameInfo{}});
  }
  coarse_thread_ = std::thread([this] { coarseLoop(); });
  fine_thread_ = std::thread([this] { fineLoop(); });
}

DualResolutionRenderer::~DualResolutionRenderer() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    fine_abort_.store(true, std::memory_order_relaxed);
  }
  coarse_wake_.notify_all();
  fine_wake_.notify_all();
  coarse_thread_.join();
  fine_thread_.join();
}

bool DualResolutionRenderer::anyKeyHeld() const {
  return std::any_of(held_.begin(), held_.end(), [](const HeldKey& key) { return key.held; });
}

bool DualResolutionRenderer::movingKeyHeld() const {
  for (int k = 0; k < kNavigationKeyCount; ++k) {
    if (held_[static_cast<std::size_t>(k)].held &&
        static_cast<NavigationKey>(k) != NavigationKey::kDrag)
      return true;
  }
  return false;
}

void DualResolutionRenderer::foldMotion(std::int64_t time_us) {
  base_view_ = viewAt(time_us);
  for (HeldKey& key : held_) key.since_us = std::max(key.since_us, time_us);
}

void DualResolutionRenderer::toggleWalk(std::int64_t time_us) {
  foldMotion(time_us);
  if (!base_view_.walk) {
    // The eye enters where the orbit view's perspective puts it (a model too small on screen to
    // put it within the camera's reach keeps the last walk eye).
    Camera camera;
    camera.yaw = base_view_.yaw;
    camera.pitch = base_view_.pitch;
    camera.zoom = base_view_.zoom;
    camera.width = width_;
    camera.height = height_;
    PerspectiveView view;
    if (orbitPerspective(camera, config_.fov, kDefaultFractionBits, &view) ==
        PerspectiveError::kNone) {
      base_view_.walker = {view.camera.eye, view.camera.yaw, view.camera.pitch, view.camera.roll};
    }
  } else {
    // Up and down mean nothing in orbit mode.
    held_[static_cast<std::size_t>(NavigationKey::kRise)].held = false;
    held_[static_cast<std::size_t>(NavigationKey::kSink)].held = false;
  }
  base_view_.walk = !base_view_.walk;
  status_.walk = base_view_.walk;
}

WalkCollision DualResolutionRenderer::walkCollision() const {
  if (!collide_) return {};
  return {collision_world_, {config_.walk_radius, config_.walk_eye_height}};
}

ViewParameters DualResolutionRenderer::viewAt(std::int64_t time_us) const {
  ViewParameters view = base_view_;
  for (int k = 0; k < kNavigationKeyCount; ++k) {
    const HeldKey& key = held_[static_cast<std::size_t>(k)];
    if (key.held) {
      view = moved(view, static_cast<NavigationKey>(k),
                   std::max<std::int64_t>(0, time_us - key.since_us), config_.degrees_per_second,
                   walk_speed_, walkCollision());
    }
  }
  return view;
}

void DualResolutionRenderer::changeView() {
  status_.view_version = ++view_version_;
  fine_due_ = true;
  fine_requested_ = false;
  fine_abort_.store(true, std::memory_order_relaxed);
  status_changed_.notify_all();
}

void DualResolutionRenderer::handle(const ViewEvent& event) {
  {
    const std::lock_guard lock(mutex_);
    switch (event.kind) {
      case ViewEventKind::kPress: {
        HeldKey& key = held_[static_cast<std::size_t>(event.key)];
        if (key.held) return;  // keyboard auto-repeat
        const bool walk_only =
            event.key == NavigationKey::kRise || event.key == NavigationKey::kSink;
        if (walk_only && !base_view_.walk) return;
        key = {true, event.time_us};
        changeView();
        break;
      }
      case ViewEventKind::kRelease: {
        HeldKey& key = held_[static_cast<std::size_t>(event.key)];
        if (!key.held) return;
        base_view_ =
            moved(base_view_, event.key, std::max<std::int64_t>(0, event.time_us - key.since_us),
                  config_.degrees_per_second, walk_speed_, walkCollision());
        key.held = false;
        changeView();
        break;
      }
      case ViewEventKind::kTick:
        if (!anyKeyHeld() && fine_due_ && fine_busy_version_ != view_version_) {
          fine_requested_ = true;
          fine_wake_.notify_one();
        }
        return;
      case ViewEventKind::kZoomIn:
      case ViewEventKind::kZoomOut:
        if (base_view_.walk) {  // the walk speed, which changes no frame
          foldMotion(event.time_us);
          const bool faster = event.kind == ViewEventKind::kZoomIn;
          walk_speed_ = std::clamp(faster ? walk_speed_ * kZoomStepNumerator / kZoomStepDenominator
                                          : walk_speed_ * kZoomStepDenominator / kZoomStepNumerator,
                                   kMinWalkSpeed, kMaxWalkSpeed);
          status_.walk_speed = walk_speed_;
          status_changed_.notify_all();
          return;
        }
        base_view_.zoom = zoomStep(base_view_.zoom, event.kind == ViewEventKind::kZoomIn);
        coarse_once_ = true;
        changeView();
        break;
      case ViewEventKind::kToggleFill:
        base_view_.fill = !base_view_.fill;
        coarse_once_ = true;
        changeView();
        break;
      case ViewEventKind::kReset: {
        const bool walk_normals = base_view_.walk_normals;  // the style stays
        base_view_ = config_.initial_view;
        base_view_.walk_normals = walk_normals;
        base_view_.walk = base_view_.walk && canWalk();
        status_.walk = base_view_.walk;
        for (HeldKey& key : held_) key.since_us = event.time_us;  // held keys turn on from here
        coarse_once_ = true;
        changeView();
        break;
      }
      case ViewEventKind::kWalkNormals:
        if (base_view_.walk_normals == event.on) return;
        base_view_.walk_normals = event.on;
        coarse_once_ = true;
        changeView();
        break;
      case ViewEventKind::kToggleWalk:
        if (!canWalk() || config_.walk_only) return;
        toggleWalk(event.time_us);
        coarse_once_ = true;
        changeView();
        break;
      case ViewEventKind::kTurn:
        if (!base_view_.walk) return;
        foldMotion(event.time_us);
        base_view_.walker.yaw = base_view_.walker.yaw + Angle::fromTurns16(event.turn_yaw);
        base_view_.walker.pitch = turnedPitch(base_view_.walker.pitch, event.turn_pitch);
        coarse_once_ = true;
        changeView();
        break;
      case ViewEventKind::kResize: {
        const std::int32_t width = std::clamp(event.width, 1, kMaxViewportSide);
        const std::int32_t height = std::clamp(event.height, 1, kMaxViewportSide);
        if (width == width_ && height == height_) return;
        width_ = width;
        height_ = height;
        coarse_once_ = true;
        changeView();
        break;
      }
      case ViewEventKind::kToggleCollision:
        if (collision_world_ == nullptr) return;
        foldMotion(event.time_us);  // the walk so far as it was made
        collide_ = !collide_;
        status_.walk_collision = collide_;
        status_changed_.notify_all();
        return;
      case ViewEventKind::kContentChanged:
        ++content_version_;  // fineLoop keeps the fine frame due when this moved while it drew
        fine_due_ = true;
        return;
      case ViewEventKind::kQuit:
        return;
    }
  }
  coarse_wake_.notify_one();
}

const LevelView* DualResolutionRenderer::levelFor(FrameSource source, const Camera& camera) const {
  if (model_ == nullptr) return source == FrameSource::kFine ? fine_level_ : coarse_level_;
  const LevelView* fine = autoLevel(*model_, camera);
  if (fine == nullptr || source == FrameSource::kFine) return fine;
  const LevelView* coarser = fine;  // the stored level just before it, if any
  for (int i = 0; i < model_->levelCount(); ++i) {
    if (&model_->level(i) == fine && i > 0) coarser = &model_->level(i - 1);
  }
  return coarser;
}

void DualResolutionRenderer::beginFrame(Slot& slot, FrameSource source) {
  slot.info = FrameInfo{};
  slot.info.source = source;
  slot.info.view_time_us = clock_.nowMicroseconds();
  slot.info.view = viewAt(slot.info.view_time_us);
  slot.info.view_version = view_version_;
  slot.info.width = width_;
  slot.info.height = height_;
}

int DualResolutionRenderer::fitBuffers(Slot& slot, Worker& worker) {
  int allocated = 0;
  if (slot.frame.width() != slot.info.width || slot.frame.height() != slot.info.height) {
    slot.frame = Framebuffer(slot.info.width, slot.info.height);
    ++allocated;
  }
  if (worker.filler_width != slot.info.width) {
    worker.filler = HoleFiller(slot.info.width);
    worker.filler_width = slot.info.width;
    ++allocated;
  }
  return allocated;
}

bool DualResolutionRenderer::draw(Slot& slot, Worker& worker, const std::atomic<bool>* abort) {
  const std::int64_t start_us = steadyMicroseconds();
  Camera camera;
  camera.yaw = slot.info.view.yaw;
  camera.pitch = slot.info.view.pitch;
  camera.zoom = slot.info.view.zoom;
  camera.width = slot.info.width;
  camera.height = slot.info.height;
  if (slot.info.view.walk) return drawWalk(slot, worker, abort);
  FrameSetup setup;
  slot.frame.clear(config_.payload);
  if (draw_view_) {
    if (!draw_view_(slot.info.source, camera, slot.frame, abort, &slot.info.depth)) return false;
    if (slot.info.view.fill && slot.info.depth > 0 &&
        buildFrameSetup(camera, slot.info.depth, kDefaultFractionBits, &setup) ==
            CameraError::kNone &&
        worker.filler.fill(slot.frame, bridgeDepthLimit(setup)).refused) {
      return false;  // cannot happen: fitBuffers made the filler as wide as the frame
    }
    slot.info.checksum = frameChecksum(slot.frame);
    slot.info.render_us = steadyMicroseconds() - start_us;
    return true;
  }
  // The zoom is clamped, so the camera always fits; a refused camera would leave the frame empty.
  const LevelView* level = levelFor(slot.info.source, camera);
  // The level's splats as wide as its samples lie apart (the reach its model stores; levels given
  // without their model draw one footprint).
  const std::int32_t reach = model_ != nullptr && level != nullptr
                                 ? model_->sampleReachOfDepth(level->depth)
                                 : kOneSampleReach;
  if (level != nullptr && buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup,
                                          reach) == CameraError::kNone) {
    slot.info.depth = level->depth;
    if (!render_(*level, setup, slot.frame, abort)) return false;
    // A refused fill cannot happen (fitBuffers made the filler as wide as the frame).
    if (slot.info.view.fill && worker.filler.fill(slot.frame, bridgeDepthLimit(setup)).refused) {
      return false;
    }
  }
  slot.info.checksum = frameChecksum(slot.frame);
  slot.info.render_us = steadyMicroseconds() - start_us;
  return true;
}

bool DualResolutionRenderer::walkView(const FrameInfo& info, PerspectiveView* view) const {
  if (!info.view.walk) return false;
  PerspectiveCamera camera;
  camera.eye = info.view.walker.eye;
  camera.yaw = info.view.walker.yaw;
  camera.pitch = info.view.walker.pitch;
  camera.roll = info.view.walker.roll;
  camera.fov = config_.fov;
  if (config_.near > 0) {
    camera.near = config_.near;
  } else if (model_ != nullptr) {
    camera.near = nearPlaneForDepth(model_->finestLevel().depth);
  }
  camera.width = info.width;
  camera.height = info.height;
  return buildPerspectiveView(camera, kDefaultFractionBits, view) == PerspectiveError::kNone;
}

bool DualResolutionRenderer::drawWalk(Slot& slot, Worker& worker, const std::atomic<bool>* abort) {
  const std::int64_t start_us = steadyMicroseconds();
  // With normals (config_.payload) only for a style: a kColourNormal frame's coarser depth code
  // (renderer/perspective_depth.h) lets other leaves win some pixels, and octopoint-render --eye
  // draws its colour frame without normals.
  slot.frame.clear(slot.info.view.walk_normals ? config_.payload : PixelPayload::kColour);
  PerspectiveView view;
  // The eye is kept within reach and the size within bounds; a refused camera leaves it empty.
  if (worker.perspective == nullptr && config_.walk_draw && walkView(slot.info, &view)) {
    int finest = 0;
    if (!config_.walk_draw(slot.info.source, view, slot.frame, abort, &finest)) return false;
    slot.info.depth = finest;
    // A refused fill cannot happen (fitBuffers made the filler as wide as the frame).
    if (finest > 0 && slot.info.view.fill &&
        worker.filler.fill(slot.frame, perspectiveBridge(view, finest)).refused) {
      return false;
    }
  } else if (worker.perspective != nullptr && walkView(slot.info, &view)) {
    PerspectiveRenderer::Options options;  // detail by distance, culled: octopoint-render --eye's
    options.coarser = slot.info.source == FrameSource::kCoarse ? 1 : 0;
    const std::span<const int> depths = worker.perspective->detailDepths();
    if (depths.empty()) {
      slot.info.depth = 0;
    } else {
      if (!worker.perspective->draw(view, options, slot.frame, nullptr, abort)) return false;
      slot.info.depth = depths.back();
      // The fill's bridge takes the finest depth the frame drew: a coarse frame's is one coarser.
      const std::size_t finest =
          depths.size() - 1 -
          std::min(static_cast<std::size_t>(options.coarser), depths.size() - 1);
      // A refused fill cannot happen (fitBuffers made the filler as wide as the frame).
      if (slot.info.view.fill &&
          worker.filler.fill(slot.frame, perspectiveBridge(view, depths[finest])).refused) {
        return false;
      }
    }
  }
  slot.info.checksum = frameChecksum(slot.frame);
  slot.info.render_us = steadyMicroseconds() - start_us;
  return true;
}

bool DualResolutionRenderer::handOver(std::unique_ptr<Slot>& slot) {
  const FrameInfo& latest = status_.latest;
  const FrameInfo& info = slot->info;
  const bool newer =
      latest.generation == 0 || info.view_version > latest.view_version ||
      (info.view_version == latest.view_version &&
       !(latest.source == FrameSource::kFine && info.source == FrameSource::kCoarse));
  if (!newer) {
    ++status_.stale_dropped;
    return false;
  }
  slot->info.generation = ++generation_;
  status_.latest = slot->info;
  ++(info.source == FrameSource::kFine ? status_.fine_shown : status_.coarse_shown);
  std::swap(slot, handed_over_);
  handed_over_is_new_ = true;
  return true;
}

void DualResolutionRenderer::notifyFrameReady(std::unique_lock<std::mutex>& lock) {
  if (!config_.frame_ready) return;
  lock.unlock();  // the callback may take the display's own locks (SDL_PushEvent does)
  config_.frame_ready();
  lock.lock();
}

void DualResolutionRenderer::coarseLoop() {
  std::unique_lock lock(mutex_);
  while (true) {
    coarse_wake_.wait(lock, [this] { return stopping_ || movingKeyHeld() || coarse_once_; });
    if (stopping_) return;
    coarse_once_ = false;
    Slot& slot = *coarse_back_;
    beginFrame(slot, FrameSource::kCoarse);
    status_.coarse_busy = true;
    lock.unlock();
    const int allocated = fitBuffers(slot, coarse_worker_);
    // L is never aborted (its frames are short): what it drew is handed over as it is.
    static_cast<void>(draw(slot, coarse_worker_, nullptr));
    lock.lock();
    status_.coarse_busy = false;
    status_.buffers_allocated += static_cast<std::uint64_t>(allocated);
    const bool handed_over = handOver(coarse_back_);
    status_changed_.notify_all();
    if (handed_over) notifyFrameReady(lock);
  }
}

void DualResolutionRenderer::fineLoop() {
  std::unique_lock lock(mutex_);
  while (true) {
    fine_wake_.wait(lock, [this] { return stopping_ || fine_requested_; });
    if (stopping_) return;
    fine_requested_ = false;
    fine_abort_.store(false, std::memory_order_relaxed);  // under the mutex: a press sets it again
    Slot& slot = *fine_back_;
    beginFrame(slot, FrameSource::kFine);
    fine_busy_version_ = view_version_;
    const std::uint64_t content_version = content_version_;
    ++status_.fine_started;
    status_.fine_busy = true;
    status_changed_.notify_all();
    lock.unlock();
    const int allocated = fitBuffers(slot, fine_worker_);
    const bool complete = draw(slot, fine_worker_, &fine_abort_);
    lock.lock();
    status_.fine_busy = false;
    status_.buffers_allocated += static_cast<std::uint64_t>(allocated);
    fine_busy_version_ = 0;
    bool handed_over = false;
    if (!complete) {
      ++status_.fine_aborted;
    } else if (slot.info.view_version != view_version_) {
      ++status_.stale_dropped;  // finished just as the view changed
    } else {
      fine_due_ = content_version_ != content_version;  // more arrived while it drew: again
      handed_over = handOver(fine_back_);
    }
    status_changed_.notify_all();
    if (handed_over) notifyFrameReady(lock);
  }
}

const Framebuffer* DualResolutionRenderer::acquireLatest(FrameInfo* info) {
  const std::lock_guard lock(mutex_);
  if (handed_over_is_new_) {
    std::swap(handed_over_, front_);
    handed_over_is_new_ = false;
  }
  if (front_->info.generation == 0) return nullptr;
  if (info != nullptr) *info = front_->info;
  return &front_->frame;
}

RendererStatus DualResolutionRenderer::status() const {
  const std::lock_guard lock(mutex_);
  return status_;
}

bool DualResolutionRenderer::waitUntil(const std::function<bool(const RendererStatus&)>& predicate,
                                       std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return status_changed_.wait_for(lock, timeout, [&] { return predicate(status_); });
}

}  // namespace octopoint
