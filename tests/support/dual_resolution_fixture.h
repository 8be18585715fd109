#pragma once
// The fixture of the dual-resolution tests (dual_resolution_test.cpp,
// dual_resolution_window_test.cpp, targets/armel/frame_allocation_test.cpp): the default model's
// coarsest and finest levels, a manual clock, "slow" fine renderers that are the real decoder
// repeated, the frame a view should give, drawn directly, and a user's turn of the view.
#include <gtest/gtest.h>
#include <time.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>

#include "octopoint/interactive.h"
#include "octopoint/models.h"
#include "renderer/perspective.h"

namespace octopoint::dual_resolution_testing {

using std::chrono::milliseconds;

// The perspective view a walk frame of `walker` is drawn with at the config's size and field of
// view (the camera's default near plane).
inline PerspectiveView walkViewOf(const InteractiveConfig& config, const WalkEye& walker) {
  PerspectiveCamera camera;
  camera.eye = walker.eye;
  camera.yaw = walker.yaw;
  camera.pitch = walker.pitch;
  camera.roll = walker.roll;
  camera.fov = config.fov;
  camera.width = config.width;
  camera.height = config.height;
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  return view;
}
inline constexpr milliseconds kPatience{20000};  // generous: ThreadSanitizer slows everything down

inline std::int64_t processCpuMicroseconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return std::int64_t{now.tv_sec} * 1'000'000 + now.tv_nsec / 1000;
}

inline std::int64_t realMicroseconds() { return SteadyClock().nowMicroseconds(); }

inline ViewEvent at(std::int64_t time_ms, ViewEventKind kind,
                    NavigationKey key = NavigationKey::kYawRight) {
  return {time_ms * 1000, kind, key};
}

// Ticks at `time_ms`, waits for the fine frame of the current view and returns its info (the
// walk tests: dual_resolution_walk_test.cpp, dual_resolution_collision_test.cpp).
inline FrameInfo fineFrame(DualResolutionRenderer& renderer, std::int64_t time_ms) {
  renderer.handle(at(time_ms, ViewEventKind::kTick));
  const std::uint64_t version = renderer.status().view_version;
  EXPECT_TRUE(renderer.waitUntil(
      [&](const RendererStatus& s) {
        return s.latest.source == FrameSource::kFine && s.latest.view_version == version;
      },
      kPatience));
  FrameInfo info;
  EXPECT_NE(renderer.acquireLatest(&info), nullptr);
  return info;
}

class DualResolution : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelIssue issue;
    model_ = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    ASSERT_TRUE(model_.has_value());
    ASSERT_GE(model_->levelCount(), 2);
    coarse_ = &model_->level(0);
    fine_ = &model_->finestLevel();
  }

  // The real decoder (the renderer's default variant), repeated until `budget` of real time has
  // passed (each pass polls `abort`).
  RenderFunction slowFine(milliseconds budget) const {
    return slowFine(std::make_shared<std::atomic<int>>(static_cast<int>(budget.count())));
  }

  // The same with a budget the test may change while the renderer runs (32 bits: ARMv5 has no
  // lock-free 64-bit atomics).
  RenderFunction slowFine(std::shared_ptr<const std::atomic<int>> budget_ms) const {
    const LevelView* fine = fine_;
    return [fine, budget_ms](const LevelView& level, const FrameSetup& setup, Framebuffer& frame,
                             const std::atomic<bool>* abort) {
      const std::int64_t end_us = realMicroseconds() + std::int64_t{budget_ms->load()} * 1000;
      do {
        if (!renderLevel(InteractiveConfig{}.variant, level, setup, frame, abort)) return false;
      } while (&level == fine && realMicroseconds() < end_us);
      return true;
    };
  }

  // Plays `timeline` up to (and including) the next event of `kind`.
  static ViewEvent playThrough(ScriptedTimeline& timeline, DualResolutionRenderer& renderer,
                               ViewEventKind kind) {
    while (true) {
      const ViewEvent event = *timeline.next(0);
      renderer.handle(event);
      if (event.kind == kind || event.kind == ViewEventKind::kQuit) return event;
    }
  }

  // The frame the renderer should show for `view` at `width` x `height`, drawn directly with the
  // renderer's default variant (with splats where voxels are larger than a pixel, `sample_reach`
  // footprints wide, Q4).
  Framebuffer directRender(const LevelView& level, const ViewParameters& view,
                           std::int32_t width = 320, std::int32_t height = 240,
                           std::int32_t sample_reach = kOneSampleReach) const {
    Camera camera;
    camera.yaw = view.yaw;
    camera.pitch = view.pitch;
    camera.zoom = view.zoom;
    camera.width = width;
    camera.height = height;
    FrameSetup setup;
    EXPECT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup, sample_reach),
              CameraError::kNone);
    Framebuffer frame(camera.width, camera.height);
    frame.clear();
    EXPECT_TRUE(renderLevel(InteractiveConfig{}.variant, level, setup, frame));  // as H draws
    if (view.fill) {
      EXPECT_FALSE(HoleFiller(frame.width()).fill(frame, bridgeDepthLimit(setup)).refused);
    }
    return frame;
  }

  std::optional<ModelView> model_;
  const LevelView* coarse_ = nullptr;
  const LevelView* fine_ = nullptr;
  ManualClock clock_;
};

// One turn of the view as a user makes it: a key held for a few coarse frames, let go, and the
// fine frame at the next tick; the display takes every new frame. play() allocates nothing itself
// (its wait predicates are built with the object), so an allocation test can count around it.
class Round {
 public:
  Round(DualResolutionRenderer& renderer, ManualClock& clock)
      : renderer_(renderer), clock_(clock) {}

  void play() {
    renderer_.handle({now_us_, ViewEventKind::kPress, NavigationKey::kYawRight});
    for (int frame = 0; frame < 3; ++frame) {
      now_us_ += 20'000;
      clock_.set(now_us_);
      seen_generation_ = renderer_.status().latest.generation;
      if (!renderer_.waitUntil(new_frame_, kPatience) ||
          renderer_.acquireLatest(nullptr) == nullptr)
        failed_ = true;
    }
    renderer_.handle({now_us_, ViewEventKind::kRelease, NavigationKey::kYawRight});
    now_us_ += kTickPeriodMicroseconds;
    clock_.set(now_us_);
    renderer_.handle({now_us_, ViewEventKind::kTick});
    version_ = renderer_.status().view_version;
    if (!renderer_.waitUntil(fine_shown_, kPatience) || renderer_.acquireLatest(nullptr) == nullptr)
      failed_ = true;
  }
  bool failed() const { return failed_; }

 private:
  DualResolutionRenderer& renderer_;
  ManualClock& clock_;
  std::int64_t now_us_ = 0;
  std::uint64_t seen_generation_ = 0;
  std::uint64_t version_ = 0;
  bool failed_ = false;
  const std::function<bool(const RendererStatus&)> new_frame_ = [this](const RendererStatus& s) {
    return s.latest.generation > seen_generation_;
  };
  const std::function<bool(const RendererStatus&)> fine_shown_ = [this](const RendererStatus& s) {
    return s.latest.source == FrameSource::kFine && s.latest.view_version == version_ &&
           !s.fine_busy && !s.coarse_busy;
  };
};

}  // namespace octopoint::dual_resolution_testing
