// The progressive model fed by one thread while two others draw it (what octopoint-view does with
// a model streaming in): the feeder holds the lock only to accept a table or chunk, the drawers
// only to take a snapshot, and they draw without it. Real threads; scripts/test-tsan runs this
// under ThreadSanitizer, which fails on any unsynchronised access. Every frame must be exactly the
// frame of a model fed the items its snapshot saw, however many arrived while it was drawn.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

struct Drawn {
  std::size_t items = 0;  // how many items the model had accepted at the snapshot
  int coarser = 0;
  Framebuffer frame;
  int repeats_while_feeding = 0;  // redraws of the snapshot while more items arrived
};

bool samePixels(const Framebuffer& a, const Framebuffer& b) {
  for (std::int32_t y = 0; y < a.height(); ++y) {
    for (std::int32_t x = 0; x < a.width(); ++x) {
      if (a.covered(x, y) != b.covered(x, y) || a.colourIndexAt(x, y) != b.colourIndexAt(x, y))
        return false;
    }
  }
  return true;
}

// The model's items in file order: the record tables, then the chunks level by level.
std::vector<FetchItem> fileOrderItems(const ProgressiveModel& whole) {
  std::vector<FetchItem> items;
  for (int level = 1; level < whole.levelCount(); ++level)
    items.push_back(whole.recordTableItem(level));
  for (int level = 1; level < whole.levelCount(); ++level) {
    for (std::uint32_t i = 0; i < whole.chunkCount(level); ++i)
      items.push_back(whole.chunkItem(level, i));
  }
  return items;
}

// The model the feeder fills and the drawers draw, with what they share.
struct Streaming {
  std::span<const std::uint8_t> image;
  std::vector<FetchItem> items;
  ProgressiveModel& model;
  Camera camera;
  std::mutex mutex;
  std::size_t accepted = 0;  // under mutex
  std::atomic<std::size_t> accepted_now{0};
  std::atomic<int> redraws{0};  // redraws of a snapshot, by both drawers

  std::span<const std::uint8_t> bytesOf(const FetchItem& item) const {
    return image.subspan(static_cast<std::size_t>(item.offset),
                         static_cast<std::size_t>(item.bytes));
  }
};

void feed(Streaming& s) {
  for (std::size_t i = 0; i < s.items.size(); ++i) {
    if (i == s.items.size() / 2) {
      // On a loaded machine the feeder could otherwise accept every item before a drawer runs
      // at all. Halfway, it waits until a drawer redraws a snapshot (it goes on redrawing while
      // the next 8 items arrive); bounded, so a drawer that never gets there fails, not hangs.
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
      while (s.redraws.load() == 0 && std::chrono::steady_clock::now() < give_up)
        std::this_thread::yield();
    }
    {
      const std::lock_guard lock(s.mutex);
      EXPECT_EQ(s.model.accept(s.items[i], s.bytesOf(s.items[i])).error, ChunkedError::kNone);
      s.accepted = i + 1;
    }
    s.accepted_now = i + 1;
    std::this_thread::yield();
  }
}

// Draws snapshots `coarser` depths coarser until one holds every item; returns one frame per
// distinct snapshot.
std::vector<Drawn> drawWhileFed(Streaming& s, int coarser) {
  ProgressiveFrame snapshot;
  std::vector<Drawn> drawn;
  while (true) {
    Drawn d{0, coarser, Framebuffer(s.camera.width, s.camera.height), 0};
    {
      const std::lock_guard lock(s.mutex);
      s.model.snapshot(snapshot);
      d.items = s.accepted;
    }
    d.frame.clear();
    EXPECT_TRUE(
        s.model.draw(snapshot, s.camera, Variant::kFixedFast, d.frame, nullptr, nullptr, coarser));
    // Draw the same snapshot again while a few more items arrive: the same frame each time.
    Framebuffer again(s.camera.width, s.camera.height);
    while (s.accepted_now.load() < std::min(d.items + 8, s.items.size())) {
      again.clear();
      EXPECT_TRUE(
          s.model.draw(snapshot, s.camera, Variant::kFixedFast, again, nullptr, nullptr, coarser));
      EXPECT_TRUE(samePixels(again, d.frame)) << "a snapshot changed while it was drawn";
      ++d.repeats_while_feeding;
      ++s.redraws;
    }
    const bool last = d.items == s.items.size();
    if (drawn.empty() || drawn.back().items != d.items) drawn.push_back(std::move(d));
    if (last) return drawn;
  }
}

TEST(ProgressiveThreads, ChunksArriveWhileTwoThreadsDrawSnapshotsWithoutTheLock) {
  const std::vector<std::uint8_t> image =
      fuzzing::chunkedImage(*models::defaultModel(), {5, 6, 7, 8}, {1024, 1500});
  std::optional<ProgressiveModel> whole = progressiveModelFromPrefix(image, nullptr);
  ASSERT_TRUE(whole.has_value());
  std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(image, nullptr);
  ASSERT_TRUE(model.has_value());
  Streaming s{image, fileOrderItems(*whole), *model, {}, {}};
  ASSERT_GT(s.items.size(), 40u);
  s.camera.width = 160;
  s.camera.height = 120;
  s.camera.zoom = Q16::fromRaw(2 * Q16::kOneRaw);
  s.camera.yaw = Angle::fromDegrees(20);

  std::thread feeder([&] { feed(s); });
  std::vector<Drawn> drawn_by[2];
  std::vector<std::thread> drawers;
  for (int coarser = 0; coarser < 2; ++coarser)
    drawers.emplace_back([&, coarser] { drawn_by[coarser] = drawWhileFed(s, coarser); });
  feeder.join();
  for (std::thread& drawer : drawers) drawer.join();

  // Each frame against a model fed, on this thread, the items its snapshot had seen.
  int repeats = 0;
  for (const std::vector<Drawn>& drawn : drawn_by) {
    ASSERT_FALSE(drawn.empty());
    EXPECT_EQ(drawn.back().items, s.items.size());
    for (const Drawn& d : drawn) {
      std::optional<ProgressiveModel> reference = ProgressiveModel::fromHead(image, nullptr);
      for (std::size_t i = 0; i < d.items; ++i)
        EXPECT_EQ(reference->accept(s.items[i], s.bytesOf(s.items[i])).error, ChunkedError::kNone);
      Framebuffer frame(s.camera.width, s.camera.height);
      frame.clear();
      EXPECT_TRUE(
          reference->draw(s.camera, Variant::kFixedFast, frame, nullptr, nullptr, d.coarser));
      EXPECT_TRUE(samePixels(frame, d.frame)) << d.items << " items, coarser " << d.coarser;
      repeats += d.repeats_while_feeding;
    }
  }
  EXPECT_GT(repeats, 0) << "no frame was drawn while chunks arrived";
}

}  // namespace
}  // namespace octopoint
