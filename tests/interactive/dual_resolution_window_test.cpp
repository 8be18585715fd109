// What a window needs from the dual-resolution renderer: frames that follow the window's size
// (kResize), buffers reallocated once per resize and never per frame, and a frame-ready call that
// lets the display sleep. Real threads and the real decoder, on a manual clock.
#include <array>
#include <functional>
#include <thread>

#include "renderer/level_of_detail.h"
#include "tests/support/dual_resolution_fixture.h"

namespace octopoint::dual_resolution_testing {
namespace {

ViewEvent resize(std::int32_t width, std::int32_t height) {
  ViewEvent event;
  event.kind = ViewEventKind::kResize;
  event.width = width;
  event.height = height;
  return event;
}

// Waits for the newest frame of the current view from `source`, takes it as the display does,
// and checks it is complete, `width` x `height`, and the frame its view gives when drawn directly.
void expectShownFrame(DualResolutionRenderer& renderer, FrameSource source, const LevelView& level,
                      std::int32_t width, std::int32_t height,
                      const std::function<Framebuffer(const LevelView&, const ViewParameters&,
                                                      std::int32_t, std::int32_t)>& direct) {
  const std::uint64_t version = renderer.status().view_version;
  ASSERT_TRUE(renderer.waitUntil(
      [&](const RendererStatus& s) {
        return s.latest.view_version == version && s.latest.source == source;
      },
      kPatience))
      << (source == FrameSource::kFine ? "H" : "L") << " drew no frame at " << width << "x"
      << height;
  FrameInfo info;
  const Framebuffer* shown = renderer.acquireLatest(&info);
  ASSERT_NE(shown, nullptr);
  EXPECT_EQ(info.width, width);
  EXPECT_EQ(info.height, height);
  ASSERT_EQ(shown->width(), width);
  ASSERT_EQ(shown->height(), height);
  EXPECT_EQ(frameChecksum(*shown), info.checksum) << "torn frame";
  EXPECT_EQ(frameChecksum(*shown), frameChecksum(direct(level, info.view, width, height)))
      << "not the frame of its view at " << width << "x" << height;
}

TEST_F(DualResolution, AResizeDrawsTheNextCoarseAndFineFramesAtTheNewSize) {
  DualResolutionRenderer renderer(*coarse_, *fine_, clock_, InteractiveConfig{});
  ASSERT_TRUE(renderer.waitUntil(
      [](const RendererStatus& s) { return s.fine_shown == 1 && !s.fine_busy; }, kPatience));
  const auto direct = [this](const LevelView& level, const ViewParameters& view, std::int32_t width,
                             std::int32_t height) {
    return directRender(level, view, width, height);
  };
  // Larger, odd and tall, the smallest, a side past the camera's limit (clamped to it), and the
  // height alone changing until every buffer in circulation has the same width.
  struct Size {
    std::int32_t asked_width, asked_height, width, height;
  };
  constexpr std::array<Size, 9> kSizes{{{640, 480, 640, 480},
                                        {97, 301, 97, 301},
                                        {1, 1, 1, 1},
                                        {0, kMaxViewportSide + 5, 1, kMaxViewportSide},
                                        {320, 240, 320, 240},
                                        {320, 100, 320, 100},
                                        {320, 180, 320, 180},
                                        {320, 60, 320, 60},
                                        {320, 240, 320, 240}}};
  for (const Size& size : kSizes) {
    const std::uint64_t version_before = renderer.status().view_version;
    renderer.handle(resize(size.asked_width, size.asked_height));
    EXPECT_GT(renderer.status().view_version, version_before) << "a resize is a new view";
    expectShownFrame(renderer, FrameSource::kCoarse, *coarse_, size.width, size.height, direct);
    renderer.handle({0, ViewEventKind::kTick});
    expectShownFrame(renderer, FrameSource::kFine, *fine_, size.width, size.height, direct);
    if (HasFatalFailure()) return;
  }
  // The same size again changes nothing: no new view, nothing drawn.
  const RendererStatus before = renderer.status();
  renderer.handle(resize(320, 240));
  renderer.handle({0, ViewEventKind::kTick});
  EXPECT_EQ(renderer.status().view_version, before.view_version);
  EXPECT_EQ(renderer.status().latest.generation, before.latest.generation);
}

// Built from the whole model, the depth drawn follows the frame's size: a small window draws a
// coarser stored depth, a large one the finest with splats.
TEST_F(DualResolution, BuiltFromAModelTheDepthDrawnFollowsTheSize) {
  DualResolutionRenderer renderer(*model_, clock_, InteractiveConfig{});
  const auto direct = [this](const LevelView& level, const ViewParameters& view, std::int32_t width,
                             std::int32_t height) {
    return directRender(level, view, width, height);
  };
  std::array<int, 2> depths{};
  constexpr std::array<std::array<std::int32_t, 2>, 2> kSizes{{{160, 120}, {1280, 960}}};
  for (std::size_t i = 0; i < kSizes.size(); ++i) {
    const auto [width, height] = kSizes[i];
    Camera camera;
    camera.width = width;
    camera.height = height;
    const LevelView* fine = autoLevel(*model_, camera);
    ASSERT_NE(fine, nullptr);
    renderer.handle(resize(width, height));
    renderer.handle({0, ViewEventKind::kTick});
    expectShownFrame(renderer, FrameSource::kFine, *fine, width, height, direct);
    depths[i] = renderer.status().latest.depth;
    EXPECT_EQ(depths[i], fine->depth) << width << "x" << height;
  }
  EXPECT_LT(depths[0], depths[1]) << "the size did not enter the choice of depth";
}

TEST_F(DualResolution, AResizeAbortsTheFineFrameBeingDrawn) {
  const auto fine_budget_ms = std::make_shared<std::atomic<int>>(0);
  DualResolutionRenderer renderer(*coarse_, *fine_, clock_, InteractiveConfig{},
                                  slowFine(fine_budget_ms));
  ASSERT_TRUE(renderer.waitUntil(
      [](const RendererStatus& s) { return s.fine_shown == 1 && !s.fine_busy; }, kPatience));
  renderer.handle({0, ViewEventKind::kToggleFill});  // a new view, so that a fine frame is due
  fine_budget_ms->store(static_cast<int>(kPatience.count()));  // H draws until stopped
  renderer.handle({0, ViewEventKind::kTick});
  ASSERT_TRUE(renderer.waitUntil(
      [](const RendererStatus& s) { return s.fine_started == 2 && s.fine_busy; }, kPatience));
  renderer.handle(resize(200, 150));
  ASSERT_TRUE(renderer.waitUntil(
      [](const RendererStatus& s) { return s.fine_aborted == 1 && !s.fine_busy; }, kPatience))
      << "the resize did not abort H";
  fine_budget_ms->store(0);
  const auto direct = [this](const LevelView& level, const ViewParameters& view, std::int32_t width,
                             std::int32_t height) {
    return directRender(level, view, width, height);
  };
  expectShownFrame(renderer, FrameSource::kCoarse, *coarse_, 200, 150, direct);
  renderer.handle({0, ViewEventKind::kTick});
  expectShownFrame(renderer, FrameSource::kFine, *fine_, 200, 150, direct);
  EXPECT_EQ(renderer.status().fine_shown, 2u) << "the aborted frame was never shown";
}

TEST_F(DualResolution, AfterAResizeEachBufferIsReallocatedOnceAndThenNever) {
  DualResolutionRenderer renderer(*coarse_, *fine_, clock_, InteractiveConfig{});
  Round round(renderer, clock_);
  round.play();
  ASSERT_FALSE(round.failed());
  EXPECT_EQ(renderer.status().buffers_allocated, 0u) << "nothing is reallocated without a resize";

  // Four frame buffers and two hole fillers (the width changes), each once.
  constexpr std::uint64_t kBuffers = 6;
  renderer.handle(resize(400, 300));
  for (int i = 0; i < 20 && renderer.status().buffers_allocated < kBuffers; ++i) {
    round.play();
    ASSERT_FALSE(round.failed());
  }
  EXPECT_EQ(renderer.status().buffers_allocated, kBuffers);
  for (int i = 0; i < 5; ++i) round.play();
  ASSERT_FALSE(round.failed());
  EXPECT_EQ(renderer.status().buffers_allocated, kBuffers) << "a frame reallocated a buffer";

  // Only the height changes: the fillers stay.
  renderer.handle(resize(400, 200));
  for (int i = 0; i < 20 && renderer.status().buffers_allocated < kBuffers + 4; ++i) round.play();
  for (int i = 0; i < 5; ++i) round.play();
  ASSERT_FALSE(round.failed());
  EXPECT_EQ(renderer.status().buffers_allocated, kBuffers + 4);
}

TEST_F(DualResolution, FrameReadyIsCalledOncePerFrameHandedOver) {
  const auto calls = std::make_shared<std::atomic<int>>(0);
  InteractiveConfig config;
  config.frame_ready = [calls] { calls->fetch_add(1, std::memory_order_relaxed); };
  DualResolutionRenderer renderer(*coarse_, *fine_, clock_, config);
  Round round(renderer, clock_);
  for (int i = 0; i < 3; ++i) round.play();
  ASSERT_FALSE(round.failed());
  const RendererStatus status = renderer.status();
  EXPECT_GE(status.coarse_shown, 9u);
  // The call follows the hand-over (outside the lock): the last one may still be on its way.
  const int handed_over = static_cast<int>(status.coarse_shown + status.fine_shown);
  const std::int64_t give_up_us = realMicroseconds() + kPatience.count() * 1000;
  while (calls->load() < handed_over && realMicroseconds() < give_up_us) {
    std::this_thread::sleep_for(milliseconds(1));
  }
  EXPECT_EQ(calls->load(), handed_over);
}

}  // namespace
}  // namespace octopoint::dual_resolution_testing
