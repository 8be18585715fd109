// The interactive renderer driven by a view-drawing function instead of one model (what the
// viewer uses for a chunked model streaming in): each thread draws the view it is given, and a
// kContentChanged event brings a new fine frame of the same view at the next tick, without
// aborting one under way, and only then.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>

#include "octopoint/interactive.h"
#include "tests/support/dual_resolution_fixture.h"

namespace octopoint {
namespace {

using dual_resolution_testing::kPatience;
using dual_resolution_testing::realMicroseconds;

// A "model" whose content is a number: a view draws it as the palette index of pixel (0, 0), and
// which thread asked as the index of pixel (1, 0). `draw_us` makes a fine frame take that long
// (polling abort).
struct CountingContent {
  std::atomic<int> content{1};
  std::atomic<int> fine_draws{0};
  std::atomic<int> draw_us{0};

  ViewDrawFunction drawer() {
    return [this](FrameSource source, const Camera&, Framebuffer& frame,
                  const std::atomic<bool>* abort, int* depth) {
      const std::int64_t end_us = realMicroseconds() + draw_us.load();
      const auto value = static_cast<std::uint8_t>(content.load());
      if (source == FrameSource::kFine) {
        ++fine_draws;
        while (realMicroseconds() < end_us) {
          if (abort != nullptr && abort->load()) return false;
        }
      }
      frame.plot(0, 0, 1, value);
      frame.plot(1, 0, 1, source == FrameSource::kFine ? 1 : 0);
      *depth = 7;
      return true;
    };
  }
};

int shownContent(DualResolutionRenderer& renderer) {
  FrameInfo info;
  const Framebuffer* frame = renderer.acquireLatest(&info);
  return frame == nullptr ? -1 : frame->colourIndexAt(0, 0);
}

TEST(DualResolutionContent, DrawsWhatTheFunctionDrawsAndRedrawsWhenTheContentChanges) {
  CountingContent content;
  ManualClock clock;
  DualResolutionRenderer renderer(content.drawer(), clock, InteractiveConfig{});
  ASSERT_TRUE(
      renderer.waitUntil([](const RendererStatus& s) { return s.fine_shown == 1; }, kPatience));
  EXPECT_EQ(shownContent(renderer), 1);
  EXPECT_EQ(renderer.status().latest.depth, 7);

  // Ticks without new content draw nothing new.
  for (int i = 1; i <= 3; ++i) {
    clock.set(i * kTickPeriodMicroseconds);
    renderer.handle({clock.nowMicroseconds(), ViewEventKind::kTick});
  }
  ASSERT_FALSE(renderer.waitUntil([](const RendererStatus& s) { return s.fine_shown > 1; },
                                  std::chrono::milliseconds(300)));
  EXPECT_EQ(content.fine_draws.load(), 1);

  // New content: the fine frame is due again at the next tick, for the same view.
  const std::uint64_t view_version = renderer.status().view_version;
  content.content = 2;
  renderer.handle({clock.nowMicroseconds(), ViewEventKind::kContentChanged});
  clock.set(4 * kTickPeriodMicroseconds);
  renderer.handle({clock.nowMicroseconds(), ViewEventKind::kTick});
  ASSERT_TRUE(
      renderer.waitUntil([](const RendererStatus& s) { return s.fine_shown == 2; }, kPatience));
  EXPECT_EQ(shownContent(renderer), 2);
  EXPECT_EQ(renderer.status().view_version, view_version);
}

TEST(DualResolutionContent,
     ContentThatArrivesWhileAFineFrameIsDrawnBringsAnotherOneWithoutAborting) {
  CountingContent content;
  content.draw_us = 300'000;
  ManualClock clock;
  DualResolutionRenderer renderer(content.drawer(), clock, InteractiveConfig{});
  ASSERT_TRUE(renderer.waitUntil([](const RendererStatus& s) { return s.fine_busy; }, kPatience));
  content.content = 3;  // arrives while the first fine frame draws content 1
  renderer.handle({clock.nowMicroseconds(), ViewEventKind::kContentChanged});
  ASSERT_TRUE(
      renderer.waitUntil([](const RendererStatus& s) { return s.fine_shown == 1; }, kPatience));
  EXPECT_EQ(renderer.status().fine_aborted, 0u);
  clock.set(kTickPeriodMicroseconds);
  renderer.handle({clock.nowMicroseconds(), ViewEventKind::kTick});
  ASSERT_TRUE(
      renderer.waitUntil([](const RendererStatus& s) { return s.fine_shown == 2; }, kPatience));
  EXPECT_EQ(shownContent(renderer), 3);
}

TEST(DualResolutionContent, HeldKeysDrawCoarseFramesFromTheFunction) {
  CountingContent content;
  ManualClock clock;
  DualResolutionRenderer renderer(content.drawer(), clock, InteractiveConfig{});
  renderer.handle({0, ViewEventKind::kPress, NavigationKey::kYawRight});
  ASSERT_TRUE(renderer.waitUntil(
      [](const RendererStatus& s) {
        return s.coarse_shown >= 2 && s.latest.source == FrameSource::kCoarse;
      },
      kPatience));
  FrameInfo info;
  const Framebuffer* frame = renderer.acquireLatest(&info);
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(info.source, FrameSource::kCoarse);
  EXPECT_EQ(frame->colourIndexAt(1, 0), 0);  // drawn as a coarse frame
  renderer.handle({clock.nowMicroseconds(), ViewEventKind::kRelease, NavigationKey::kYawRight});
}

}  // namespace
}  // namespace octopoint
