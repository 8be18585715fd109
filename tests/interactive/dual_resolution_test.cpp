// The dual-resolution render threads, driven headless by scripted timelines on a manual clock.
// Real threads and the real decoder; "slow" renderers are the real one repeated or delayed.
#include <random>
#include <thread>

#include "renderer/level_of_detail.h"
#include "tests/support/dual_resolution_fixture.h"

namespace octopoint::dual_resolution_testing {
namespace {

TEST_F(DualResolution, PressReleasePressWithin300MsAbortsTheFineFrameAndShowsACoarseOne) {
  DualResolutionRenderer renderer(*coarse_, *fine_, clock_, InteractiveConfig{},
                                  slowFine(milliseconds(250)));
  ASSERT_TRUE(renderer.waitUntil(
      [](const RendererStatus& s) { return s.fine_shown == 1 && !s.fine_busy; }, kPatience))
      << "the initial fine frame";
  ScriptedTimeline timeline({at(0, ViewEventKind::kPress), at(50, ViewEventKind::kRelease),
                             at(150, ViewEventKind::kPress), at(200, ViewEventKind::kRelease)},
                            400'000, clock_);
  playThrough(timeline, renderer, ViewEventKind::kRelease);  // t = 50
  playThrough(timeline, renderer, ViewEventKind::kTick);     // t = 100: H starts
  ASSERT_TRUE(renderer.waitUntil(
      [](const RendererStatus& s) { return s.fine_started == 2 && s.fine_busy; }, kPatience));
  const ViewEvent press = playThrough(timeline, renderer, ViewEventKind::kPress);  // t = 150
  ASSERT_EQ(press.time_us, 150'000);
  const std::uint64_t pressed_version = renderer.status().view_version;
  ASSERT_TRUE(renderer.waitUntil(
      [&](const RendererStatus& s) {
        return s.fine_aborted == 1 && s.latest.source == FrameSource::kCoarse &&
               s.latest.view_version == pressed_version;
      },
      kPatience));
  EXPECT_EQ(renderer.status().fine_shown, 1u) << "the aborted fine frame must never be shown";

  // After the last release, the next tick brings the fine frame: complete, the same as drawn
  // directly.
  playThrough(timeline, renderer, ViewEventKind::kRelease);  // t = 200
  playThrough(timeline, renderer, ViewEventKind::kTick);     // t = 200, after the release
  ASSERT_TRUE(
      renderer.waitUntil([](const RendererStatus& s) { return s.fine_shown == 2; }, kPatience));
  FrameInfo info;
  const Framebuffer* shown = renderer.acquireLatest(&info);
  ASSERT_NE(shown, nullptr);
  EXPECT_EQ(info.source, FrameSource::kFine);
  // Held twice for 50 ms at 90 degrees per second; each hold rounds down to whole 1/65536 turns.
  EXPECT_EQ(info.view.yaw,
            Angle::fromTurns16(2 * (std::int64_t{50'000} * 90 * 65536 / 360'000'000)));
  EXPECT_EQ(frameChecksum(*shown), frameChecksum(directRender(*fine_, info.view)));
}

TEST_F(DualResolution, AHeldKeyTurnsBySpeedTimesTimeWhateverTheFrameRate) {
  constexpr int kSlowFrameMs = 50;
  for (const int coarse_delay_ms : {0, kSlowFrameMs}) {
    const RenderFunction delayed = [coarse_delay_ms](const LevelView& level,
                                                     const FrameSetup& setup, Framebuffer& frame,
                                                     const std::atomic<bool>* abort) {
      std::this_thread::sleep_for(milliseconds(coarse_delay_ms));
      return renderLevel(Variant::kFixedBaseline, level, setup, frame, abort);
    };
    InteractiveConfig config;
    config.degrees_per_second = 90;
    DualResolutionRenderer renderer(*coarse_, *fine_, clock_, config, delayed);
    clock_.set(0);
    renderer.handle(at(0, ViewEventKind::kPress));
    // Advance the clock by 10 ms of script time per 3 ms of real time and watch the coarse frames.
    const std::int64_t hold_start_us = realMicroseconds();
    std::uint64_t last_generation = 0;
    for (std::int64_t t_ms = 10; t_ms < 1000; t_ms += 10) {
      clock_.set(t_ms * 1000);
      std::this_thread::sleep_for(milliseconds(3));
      FrameInfo info;
      if (renderer.acquireLatest(&info) != nullptr && info.generation != last_generation &&
          info.source == FrameSource::kCoarse) {
        last_generation = info.generation;
        EXPECT_EQ(info.view.yaw, Angle::fromTurns16(info.view_time_us * 90 * 65536 / 360'000'000))
            << "a coarse frame shows the view of its own time";
      }
    }
    const std::int64_t held_real_ms = (realMicroseconds() - hold_start_us) / 1000;
    const std::uint64_t coarse_frames = renderer.status().coarse_shown;
    clock_.set(1'000'000);
    renderer.handle(at(1000, ViewEventKind::kRelease));
    renderer.handle(at(1000, ViewEventKind::kTick));
    const std::uint64_t version = renderer.status().view_version;
    ASSERT_TRUE(renderer.waitUntil(
        [&](const RendererStatus& s) {
          return s.latest.source == FrameSource::kFine && s.latest.view_version == version;
        },
        kPatience));
    EXPECT_EQ(renderer.status().latest.view.yaw, Angle::fromDegrees(90))
        << "1 s at 90 degrees per second, with " << coarse_frames << " coarse frames in "
        << held_real_ms << " ms of real time";
    EXPECT_GE(coarse_frames, 1u);
    if (coarse_delay_ms == kSlowFrameMs) {
      EXPECT_LE(coarse_frames, static_cast<std::uint64_t>(held_real_ms / kSlowFrameMs + 2))
          << "the slow renderer really was slow";
    }
  }
}

// Built from the whole model: H draws each view at depth auto, L (after a zoom step) one stored
// depth coarser, or the same when depth auto is already the coarsest.
TEST_F(DualResolution, BuiltFromAModelHDrawsDepthAutoAndLOneStoredDepthCoarser) {
  const InteractiveConfig config;
  DualResolutionRenderer renderer(*model_, clock_, config);
  Q16 zoom = config.initial_view.zoom;
  for (int step = 0; step < 6; ++step) {
    Camera camera;
    camera.width = config.width;
    camera.height = config.height;
    camera.zoom = zoom;
    const int fine_index = static_cast<int>(autoLevel(*model_, camera) - &model_->level(0));
    const int coarse_depth = model_->level(std::max(0, fine_index - 1)).depth;
    const std::uint64_t version = renderer.status().view_version;
    if (step > 0) {  // a zoom step: L draws the new view once
      ASSERT_TRUE(renderer.waitUntil(
          [&](const RendererStatus& s) {
            return s.latest.view_version == version && !s.coarse_busy;
          },
          kPatience));
      FrameInfo shown;
      ASSERT_NE(renderer.acquireLatest(&shown), nullptr);
      if (shown.source == FrameSource::kCoarse) {
        EXPECT_EQ(shown.depth, coarse_depth) << "zoom step " << step;
      }
    }
    renderer.handle(at(0, ViewEventKind::kTick));
    ASSERT_TRUE(renderer.waitUntil(
        [&](const RendererStatus& s) {
          return s.latest.source == FrameSource::kFine && s.latest.view_version == version;
        },
        kPatience));
    EXPECT_EQ(renderer.status().latest.depth, model_->level(fine_index).depth)
        << "zoom step " << step;
    // The zoom of the view just drawn, read before the zoom step: once the step is handled, L may
    // already have shown the new view (a loaded machine lets it finish before this thread reads).
    zoom = renderer.status().latest.view.zoom;
    renderer.handle(at(0, ViewEventKind::kZoomOut));
    zoom = Q16::fromRaw(static_cast<std::int32_t>(std::int64_t{zoom.raw()} * 4 / 5));
  }
}

TEST_F(DualResolution, AfterReleaseTheFineFrameIsShownAndBothThreadsSleep) {
  DualResolutionRenderer renderer(*coarse_, *fine_, clock_, InteractiveConfig{});
  ScriptedTimeline timeline({at(0, ViewEventKind::kPress), at(120, ViewEventKind::kRelease)},
                            300'000, clock_);
  playThrough(timeline, renderer, ViewEventKind::kRelease);
  playThrough(timeline, renderer, ViewEventKind::kTick);  // t = 200
  const std::uint64_t version = renderer.status().view_version;
  ASSERT_TRUE(renderer.waitUntil(
      [&](const RendererStatus& s) {
        return s.latest.source == FrameSource::kFine && s.latest.view_version == version &&
               !s.fine_busy && !s.coarse_busy;
      },
      kPatience));
  const std::uint64_t generation = renderer.status().latest.generation;
  const std::int64_t cpu_before_us = processCpuMicroseconds();
  std::this_thread::sleep_for(milliseconds(300));
  const std::int64_t cpu_used_us = processCpuMicroseconds() - cpu_before_us;
  EXPECT_LT(cpu_used_us, 30'000) << "idle threads must sleep, not spin";
  EXPECT_EQ(renderer.status().latest.generation, generation) << "nothing was drawn while idle";
}

// Takes each new frame as the window would, checking the one it gives back and the new one.
class FrontChecker {
 public:
  explicit FrontChecker(DualResolutionRenderer& renderer) : renderer_(renderer) {}

  void check() {
    if (renderer_.status().latest.generation == shown_info_.generation) return;  // nothing new
    // The frame on screen is still exactly what its thread finished: nobody wrote into it. (It
    // is ours only until the next acquireLatest, hence checked first.)
    if (shown_ != nullptr) {
      ASSERT_EQ(frameChecksum(*shown_), shown_info_.checksum) << "torn frame";
    }
    FrameInfo info;
    const Framebuffer* latest = renderer_.acquireLatest(&info);
    ASSERT_NE(latest, nullptr);
    // The new one is complete, newer, and of the size it was started at.
    ASSERT_EQ(frameChecksum(*latest), info.checksum) << "torn frame";
    ASSERT_EQ(latest->width(), info.width);
    ASSERT_EQ(latest->height(), info.height);
    ASSERT_GT(info.generation, shown_info_.generation);
    ++frames_checked_;
    shown_ = latest;
    shown_info_ = info;
  }

  const Framebuffer* shown() const { return shown_; }
  const FrameInfo& shownInfo() const { return shown_info_; }
  std::uint64_t framesChecked() const { return frames_checked_; }

 private:
  DualResolutionRenderer& renderer_;
  const Framebuffer* shown_ = nullptr;
  FrameInfo shown_info_;
  std::uint64_t frames_checked_ = 0;
};

void releaseAll(DualResolutionRenderer& renderer, std::int64_t now_us) {
  for (int key = 0; key < kNavigationKeyCount; ++key) {
    renderer.handle({now_us, ViewEventKind::kRelease, static_cast<NavigationKey>(key)});
  }
}

// Makes H draw until a press of `key` stops it: H's frames take `fine_budget_ms` (set to
// `fine_ms` again afterwards).
void forceAnAbort(DualResolutionRenderer& renderer, std::int64_t now_us, NavigationKey key,
                  std::atomic<int>& fine_budget_ms, int fine_ms) {
  releaseAll(renderer, now_us);
  renderer.handle({now_us, ViewEventKind::kToggleFill});  // a new view, so a fine frame is due
  const RendererStatus before = renderer.status();
  fine_budget_ms.store(static_cast<int>(kPatience.count()));
  renderer.handle({now_us, ViewEventKind::kTick});
  ASSERT_TRUE(renderer.waitUntil(
      [&](const RendererStatus& s) { return s.fine_started > before.fine_started && s.fine_busy; },
      kPatience))
      << "H did not start after a tick";
  renderer.handle({now_us, ViewEventKind::kPress, key});
  ASSERT_TRUE(renderer.waitUntil(
      [&](const RendererStatus& s) { return s.fine_aborted > before.fine_aborted && !s.fine_busy; },
      kPatience))
      << "a press did not abort H";
  fine_budget_ms.store(fine_ms);
}

// An event of a random kind, key and size at `now_us`.
ViewEvent randomEvent(std::mt19937& random, std::int64_t now_us) {
  constexpr ViewEventKind kKinds[] = {
      ViewEventKind::kPress,   ViewEventKind::kPress,   ViewEventKind::kRelease,
      ViewEventKind::kRelease, ViewEventKind::kTick,    ViewEventKind::kTick,
      ViewEventKind::kZoomIn,  ViewEventKind::kZoomOut, ViewEventKind::kToggleFill,
      ViewEventKind::kReset,   ViewEventKind::kResize};
  ViewEvent event;
  event.time_us = now_us;
  event.kind = kKinds[std::uniform_int_distribution<std::size_t>(0, std::size(kKinds) - 1)(random)];
  event.key = static_cast<NavigationKey>(
      std::uniform_int_distribution<int>(0, kNavigationKeyCount - 1)(random));
  // Few sizes, so that often only one side changes.
  event.width = std::uniform_int_distribution<std::int32_t>(0, 1)(random) == 0 ? 64 : 320;
  event.height = std::uniform_int_distribution<std::int32_t>(0, 1)(random) == 0 ? 48 : 240;
  return event;
}

TEST_F(DualResolution, ThousandsOfRandomEventsLeaveNoDeadlockNoLostAndNoTornFrame) {
  // Resizes among the events: buffers are reallocated by their threads while the others draw,
  // hand over and show frames of another size.
  // Fine frames of at least 3 ms, so that presses often land while H is drawing. How often
  // depends on the scheduler (on a loaded machine H may never start before the next event), so
  // every few hundred events one abort is forced: H draws until a press stops it.
  constexpr int kFineMs = 3;
  const auto fine_budget_ms = std::make_shared<std::atomic<int>>(kFineMs);
  DualResolutionRenderer renderer(*coarse_, *fine_, clock_, InteractiveConfig{},
                                  slowFine(fine_budget_ms));
  std::mt19937 random(12345);
  std::int64_t now_us = 0;
  FrontChecker front(renderer);
  for (int i = 0; i < 2000; ++i) {
    if (i % 250 == 125) {
      forceAnAbort(renderer, now_us, static_cast<NavigationKey>(i % kOrbitNavigationKeyCount),
                   *fine_budget_ms, kFineMs);
      if (HasFatalFailure()) return;
    }
    now_us += std::uniform_int_distribution<std::int64_t>(0, 20'000)(random);
    clock_.set(now_us);
    renderer.handle(randomEvent(random, now_us));
    front.check();
    if (i % 16 == 0) std::this_thread::sleep_for(milliseconds(1));
  }
  releaseAll(renderer, now_us);
  renderer.handle({now_us + kTickPeriodMicroseconds, ViewEventKind::kTick});
  const std::uint64_t version = renderer.status().view_version;
  ASSERT_TRUE(renderer.waitUntil(
      [&](const RendererStatus& s) {
        return s.latest.source == FrameSource::kFine && s.latest.view_version == version &&
               !s.fine_busy;
      },
      kPatience))
      << "deadlock, or the final fine frame was lost";
  front.check();
  ASSERT_NE(front.shown(), nullptr);
  EXPECT_EQ(frameChecksum(*front.shown()), front.shownInfo().checksum);
  EXPECT_EQ(front.shownInfo().source, FrameSource::kFine);
  EXPECT_EQ(front.shownInfo().view_version, version);
  const RendererStatus status = renderer.status();
  EXPECT_GE(status.fine_started, status.fine_shown + status.fine_aborted);
  EXPECT_GE(status.fine_aborted, 8u) << "at least the forced aborts";
  EXPECT_GT(front.framesChecked(), 2u);
}

}  // namespace
}  // namespace octopoint::dual_resolution_testing
