// The progressive model (octopoint/progressive.h) against independent references: a model
// holding every chunk a view needs draws exactly the whole-model stream's frame; a model holding
// any set of chunks (a prefix of the file, or chunks in any order) draws exactly the frame worked
// out from the whole-model streams for that set (tests/support/chunked_test_support.h); a damaged
// chunk is refused without touching the rest; fetch priorities ask for what the view needs and
// nothing finer.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "codegen/level_voxels.h"
#include "codegen/model_writer.h"
#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "renderer/level_of_detail.h"
#include "tests/support/chunked_test_support.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

using octopoint::testing::Bytes;
using octopoint::testing::makeCamera;

// The default model at depths 4..8 (4 and 5 coarsened from its finest level), small chunks so
// that there are many of them. The "thinned" one lacks depth-8 voxels under a sixth of the depth-4
// cells and every other depth-7 cell of another sixth, as visibility pruning might leave it: voxels
// of depth 7 with nothing at depth 8, and whole chunks of depth 8 without a voxel.
prepare::PreparedModel thinned(prepare::PreparedModel model) {
  prepare::LevelVoxels finest = prepare::decodeLevel(model.levels.back());
  prepare::LevelVoxels kept{finest.depth, {}, {}};
  for (std::size_t i = 0; i < finest.keys.size(); ++i) {
    const std::uint64_t key = finest.keys[i];
    if ((key >> 12) % 6 == 1 || ((key >> 12) % 6 == 4 && (key >> 3) % 2 == 0)) continue;
    kept.keys.push_back(key);
    kept.colours.push_back(finest.colours[i]);
  }
  model.levels.back() = prepare::encodeLevel(kept);
  return model;
}

struct Fixture {
  explicit Fixture(bool thin)
      : prepared(thin ? thinned(fuzzing::preparedModel(*models::defaultModel(), {4, 5, 6, 7, 8}))
                      : fuzzing::preparedModel(*models::defaultModel(), {4, 5, 6, 7, 8})) {}
  prepare::PreparedModel prepared;
  Bytes image = prepare::serializeChunkedModel(prepared, {64, 600});
  std::vector<prepare::PreparedLevel> streams = octopoint::testing::levelStreams(image, prepared);

  ProgressiveModel headOnly() const {
    ChunkedIssue issue;
    std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(image, &issue);
    EXPECT_TRUE(model.has_value()) << describe(issue.error);
    return std::move(*model);
  }
};

class ProgressiveModelTest : public ::testing::TestWithParam<bool> {
 protected:
  const Fixture& fixture() const {
    static const Fixture whole(false), thin(true);
    return GetParam() ? thin : whole;
  }
};

Framebuffer drawn(ProgressiveModel& model, const Camera& camera,
                  Variant variant = Variant::kFixedFast) {
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  EXPECT_TRUE(model.draw(camera, variant, frame));
  return frame;
}

const std::vector<Camera>& cameras() {
  static const std::vector<Camera> list = {
      makeCamera(0, 0, 1, 320, 240),         makeCamera(30, -20, 1, 320, 240),
      makeCamera(-60, 10, 0.25, 160, 120),   makeCamera(15, 5, 4, 320, 240, 40, -30),
      makeCamera(180, 45, 2, 200, 300, -90), makeCamera(0, 0, 0.5, 1, 1)};
  return list;
}

TEST_P(ProgressiveModelTest, TheFileIsLayeredAsWritten) {
  const Fixture& f = fixture();
  ProgressiveModel model = f.headOnly();
  ASSERT_GE(model.levelCount(), 3);
  EXPECT_LE(model.levelDepth(0), 4);  // the base: the coarsest depth, or coarser
  EXPECT_EQ(model.levelDepth(model.levelCount() - 1), 8);
  for (int level = 1; level < model.levelCount(); ++level) EXPECT_EQ(model.chunkCount(level), 0u);
  octopoint::testing::feedTables(model, f.image);
  std::uint64_t expected_offset = model.head().levels[1].chunks_offset;
  for (const FetchItem& item : octopoint::testing::allChunkItems(model)) {
    EXPECT_EQ(item.offset, expected_offset) << "chunks lie back to back in level and region order";
    expected_offset += item.bytes;
  }
  EXPECT_EQ(expected_offset, f.image.size());
  // The thinned model has empty chunks and voxels that vanish at the finer depth.
  std::size_t empty_chunks = 0;
  const int finest = model.levelCount() - 1;
  for (std::uint32_t i = 0; i < model.chunkCount(finest); ++i) {
    const ChunkRecord& r = model.record(finest, i);
    empty_chunks += r.points == 0;
  }
  EXPECT_EQ(empty_chunks > 0, GetParam());
}

TEST_P(ProgressiveModelTest, HoldingEverythingDrawsTheWholeModelStreamBitForBit) {
  const Fixture& f = fixture();
  ChunkedIssue issue;
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(f.image, &issue);
  ASSERT_TRUE(model.has_value());
  ASSERT_EQ(issue.error, ChunkedError::kNone) << describe(issue.error);
  EXPECT_EQ(model->chunksIn(ChunkState::kHeld), octopoint::testing::allChunkItems(*model).size());
  for (const Camera& camera : cameras()) {
    ASSERT_TRUE(model->viewComplete(camera));
    const int wanted = *model->wantedDepth(camera);
    const prepare::PreparedLevel* level = octopoint::testing::finestLevelAtMost(f.streams, wanted);
    ASSERT_NE(level, nullptr);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup),
              CameraError::kNone);
    for (const VariantInfo& info : allVariants()) {
      if (!isFixedPoint(info.variant)) continue;
      Framebuffer expected(camera.width, camera.height);
      expected.clear();
      ASSERT_TRUE(renderLevel(info.variant, LevelView{level->depth, level->nodes, level->leaves},
                              setup, expected));
      EXPECT_TRUE(octopoint::testing::sameFrame(drawn(*model, camera, info.variant), expected))
          << info.name << " at depth " << level->depth << ", " << camera.width << "x"
          << camera.height;
    }
  }
}

TEST_P(ProgressiveModelTest, EveryPrefixEndingOnAChunkDrawsTheModelOfThoseChunks) {
  const Fixture& f = fixture();
  ProgressiveModel model = f.headOnly();
  for (const Camera& camera : cameras()) {  // the head alone: the base
    EXPECT_TRUE(octopoint::testing::sameFrame(
        drawn(model, camera),
        octopoint::testing::referenceFrame(model, f.streams, camera, Variant::kFixedFast)));
  }
  octopoint::testing::feedTables(model, f.image);
  const std::vector<FetchItem> items = octopoint::testing::allChunkItems(model);
  // Every chunk boundary of the two coarsest levels, then about 150 more spread over the rest (each
  // check decodes every level's whole stream for the reference).
  const std::size_t coarse_items = model.chunkCount(1) + model.chunkCount(2);
  const std::size_t stride = std::max<std::size_t>(1, (items.size() - coarse_items) / 150);
  for (std::size_t i = 0; i < items.size(); ++i) {
    octopoint::testing::feed(model, f.image, items[i]);
    if (i >= coarse_items && i % stride != 0 && i + 1 != items.size()) continue;
    const Camera& camera = cameras()[i % cameras().size()];
    ASSERT_TRUE(octopoint::testing::sameFrame(
        drawn(model, camera),
        octopoint::testing::referenceFrame(model, f.streams, camera, Variant::kFixedFast)))
        << "after chunk " << i << " of " << items.size();
  }
}

TEST_P(ProgressiveModelTest, ChunksInAnyOrderWithDamagedCopiesDrawTheSame) {
  const Fixture& f = fixture();
  ProgressiveModel model = f.headOnly();
  octopoint::testing::feedTables(model, f.image);
  std::vector<FetchItem> items = octopoint::testing::allChunkItems(model);
  std::mt19937 random(12);
  std::shuffle(items.begin(), items.end(), random);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const FetchItem& item = items[i];
    if (i % 3 == 0) {  // a damaged copy first: refused, and nothing else changes
      Bytes damaged(f.image.begin() + static_cast<std::ptrdiff_t>(item.offset),
                    f.image.begin() + static_cast<std::ptrdiff_t>(item.offset + item.bytes));
      damaged[random() % damaged.size()] ^= static_cast<std::uint8_t>(1u << (random() % 8));
      EXPECT_EQ(model.accept(item, damaged).error, ChunkedError::kBadChunkCrc);
      EXPECT_EQ(model.chunkState(item.level, item.index), ChunkState::kMissing);
    }
    octopoint::testing::feed(model, f.image, item);
    if (i % 23 == 0 || i + 1 == items.size()) {
      const Camera& camera = cameras()[i % cameras().size()];
      ASSERT_TRUE(octopoint::testing::sameFrame(
          drawn(model, camera),
          octopoint::testing::referenceFrame(model, f.streams, camera, Variant::kFixedFast)))
          << "after " << i + 1 << " chunks in shuffled order";
    }
  }
  EXPECT_EQ(model.chunksIn(ChunkState::kHeld), items.size());
}

TEST_P(ProgressiveModelTest, AChunkRefusedThreeTimesIsGivenUpAndItsRegionStaysCoarser) {
  const Fixture& f = fixture();
  ProgressiveModel model = f.headOnly();
  octopoint::testing::feedTables(model, f.image);
  const std::vector<FetchItem> items = octopoint::testing::allChunkItems(model);
  // The level-1 chunk with the most voxels: finer chunks lie inside it.
  FetchItem victim = items[0];
  for (std::uint32_t i = 0; i < model.chunkCount(1); ++i) {
    if (model.record(1, i).points > model.record(1, victim.index).points) victim = items[i];
  }
  ASSERT_EQ(victim.level, 1);
  Bytes truncated(f.image.begin() + static_cast<std::ptrdiff_t>(victim.offset),
                  f.image.begin() + static_cast<std::ptrdiff_t>(victim.offset + victim.bytes - 1));
  for (int attempt = 1; attempt <= ProgressiveModel::kMaxChunkAttempts; ++attempt) {
    EXPECT_EQ(model.accept(victim, truncated).error, ChunkedError::kWrongChunkLength);
    EXPECT_EQ(model.chunkState(victim.level, victim.index),
              attempt < ProgressiveModel::kMaxChunkAttempts ? ChunkState::kMissing
                                                            : ChunkState::kUnavailable);
  }
  for (const FetchItem& item : items) {
    if (!(item == victim)) octopoint::testing::feed(model, f.image, item);
  }
  // Its finer chunks arrived and are valid, but wait for it forever; nobody asks for them.
  EXPECT_GT(model.chunksIn(ChunkState::kWaiting), 0u);
  std::vector<FetchItem> wanted(64);
  EXPECT_EQ(model.fetchPriority(cameras()[0], true, wanted), 0u);
  for (const Camera& camera : cameras()) {
    EXPECT_TRUE(octopoint::testing::sameFrame(
        drawn(model, camera),
        octopoint::testing::referenceFrame(model, f.streams, camera, Variant::kFixedFast)));
  }
}

// Fetches what fetchPriority asks for, one item at a time, until it asks for nothing.
std::uint64_t fetchUntilComplete(ProgressiveModel& model, const Bytes& image, const Camera& camera,
                                 std::vector<FetchItem>* order) {
  std::uint64_t bytes = 0;
  std::vector<FetchItem> next(1);
  while (model.fetchPriority(camera, false, next) == 1) {
    octopoint::testing::feed(model, image, next[0]);
    bytes += next[0].bytes;
    if (order != nullptr) order->push_back(next[0]);
  }
  return bytes;
}

TEST_P(ProgressiveModelTest, FetchPriorityAsksForWhatTheViewNeedsCoarseFirstAndNothingFiner) {
  const Fixture& f = fixture();
  for (const Camera& camera : cameras()) {
    ProgressiveModel model = f.headOnly();
    std::vector<FetchItem> order;
    const std::uint64_t fetched = fetchUntilComplete(model, f.image, camera, &order);
    EXPECT_TRUE(model.viewComplete(camera));
    const int wanted = *model.wantedDepth(camera);
    int wanted_level = 0;
    while (wanted_level + 1 < model.levelCount() && model.levelDepth(wanted_level + 1) <= wanted)
      ++wanted_level;
    int previous_level = 0;
    for (const FetchItem& item : order) {
      if (item.kind == FetchItem::Kind::kChunk) {
        EXPECT_LE(model.levelDepth(item.level), wanted) << "never finer than the view needs";
      } else {  // the table of the level after says whether that level is densely sampled
        EXPECT_LE(item.level, wanted_level + 1);
      }
      EXPECT_TRUE(item.visible);
      EXPECT_GE(item.level, previous_level) << "coarse before fine";
      previous_level = item.level;
    }
    EXPECT_LE(fetched, f.image.size());
    // What it fetched draws what the whole model draws for this view.
    std::optional<ProgressiveModel> whole = progressiveModelFromPrefix(f.image, nullptr);
    EXPECT_TRUE(octopoint::testing::sameFrame(drawn(model, camera), drawn(*whole, camera)));
  }
}

TEST_P(ProgressiveModelTest, AZoomedViewFetchesOnlyPartOfTheFile) {
  const Fixture& f = fixture();
  ProgressiveModel model = f.headOnly();
  const Camera zoomed = makeCamera(0, 0, 4, 320, 240);
  const std::uint64_t fetched = fetchUntilComplete(model, f.image, zoomed, nullptr);
  EXPECT_LT(fetched, f.image.size() / 2);
  std::vector<FetchItem> rest(4096);
  const std::size_t invisible = model.fetchPriority(zoomed, true, rest);
  EXPECT_GT(invisible, 0u);
  for (std::size_t i = 0; i < invisible; ++i) EXPECT_FALSE(rest[i].visible);
}

TEST_P(ProgressiveModelTest, ACoarserFrameDrawsTheLevelAboveAndAnAbortStopsIt) {
  const Fixture& f = fixture();
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(f.image, nullptr);
  const Camera camera = makeCamera(20, -10, 1, 320, 240);
  const int wanted = *model->wantedDepth(camera);
  const auto level =
      std::find_if(f.streams.rbegin(), f.streams.rend(),
                   [&](const prepare::PreparedLevel& l) { return l.depth < wanted; });
  ASSERT_NE(level, f.streams.rend());
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup),
            CameraError::kNone);
  Framebuffer expected(camera.width, camera.height);
  expected.clear();
  ASSERT_TRUE(renderLevel(Variant::kFixedFast, LevelView{level->depth, level->nodes, level->leaves},
                          setup, expected));
  Framebuffer coarser(camera.width, camera.height);
  coarser.clear();
  ProgressiveDrawStats stats;
  ASSERT_TRUE(model->draw(camera, Variant::kFixedFast, coarser, &stats, nullptr, 1));
  EXPECT_EQ(stats.drawn_depth, level->depth);
  EXPECT_TRUE(octopoint::testing::sameFrame(coarser, expected));
  const std::atomic<bool> abort{true};
  Framebuffer aborted(camera.width, camera.height);
  aborted.clear();
  EXPECT_FALSE(model->draw(camera, Variant::kFixedFast, aborted, nullptr, &abort));
}

// A drawing thread draws a snapshot without the feeder's lock: what arrives after the snapshot
// must not show in it (nor may the snapshot's streams change), and a new snapshot shows it all.
TEST_P(ProgressiveModelTest, ASnapshotDrawsTheModelAsItWasWhileChunksKeepArriving) {
  const Fixture& f = fixture();
  ProgressiveModel whole = f.headOnly();
  EXPECT_EQ(whole.acceptBytes(0, f.image, nullptr), f.image.size());
  // Up to the middle of the chunks of the level before the finest: coarser than every camera's
  // complete frame.
  const ChunkedHead& head = whole.head();
  const int finest = whole.levelCount() - 1;
  const std::uint64_t cut = (head.levels[static_cast<std::size_t>(finest - 1)].chunks_offset +
                             head.levels[static_cast<std::size_t>(finest)].chunks_offset) /
                            2;
  const std::span<const std::uint8_t> prefix = std::span(f.image).first(cut);
  int incomplete_views = 0;
  for (const Camera& camera : cameras()) {
    if (camera.width < 100) continue;
    ProgressiveModel model = f.headOnly(), prefix_only = f.headOnly();
    // A prefix ends inside a chunk: what it holds whole is taken, the rest waits.
    static_cast<void>(model.acceptBytes(0, prefix, nullptr));
    static_cast<void>(prefix_only.acceptBytes(0, prefix, nullptr));
    ProgressiveFrame snapshot;
    model.snapshot(snapshot);
    EXPECT_EQ(model.acceptBytes(0, f.image, nullptr), f.image.size());  // the rest arrives
    Framebuffer frame(camera.width, camera.height);
    frame.clear();
    ASSERT_TRUE(model.draw(snapshot, camera, Variant::kFixedFast, frame));
    EXPECT_TRUE(octopoint::testing::sameFrame(frame, drawn(prefix_only, camera)));
    if (!prefix_only.viewComplete(camera)) {
      ++incomplete_views;
      EXPECT_FALSE(octopoint::testing::sameFrame(frame, drawn(whole, camera)))
          << "the rest must draw something the prefix does not";
    }
    model.snapshot(snapshot);
    frame.clear();
    ASSERT_TRUE(model.draw(snapshot, camera, Variant::kFixedFast, frame));
    EXPECT_TRUE(octopoint::testing::sameFrame(frame, drawn(whole, camera)));
  }
  EXPECT_GE(incomplete_views, 2);
}

// Depth auto stops at the finest depth the scan samples densely (renderer/level_of_detail.h): the
// thinned model's depth 8 has fewer than 3x the voxels of its depth 7, so no view draws or fetches
// it, however closely it looks; the whole model's depth 8 is dense and drawn when zoomed in.
TEST_P(ProgressiveModelTest, DepthAutoStopsAtTheDenselySampledDepth) {
  const Fixture& f = fixture();
  ProgressiveModel model = f.headOnly();
  const Camera zoomed = makeCamera(15, 5, 8, 320, 240);
  const int finest_depth = model.levelDepth(model.levelCount() - 1);
  EXPECT_EQ(model.wantedDepth(zoomed), finest_depth) << "the finest level's table is not known";
  octopoint::testing::feedTables(model, f.image);
  std::vector<std::uint64_t> voxels;
  for (const prepare::PreparedLevel& level : f.streams) voxels.push_back(level.leaves.size());
  const bool finest_dense = voxels.back() >= 3 * voxels[voxels.size() - 2];
  EXPECT_EQ(finest_dense, !GetParam());
  EXPECT_EQ(model.wantedDepth(zoomed), finest_dense ? finest_depth : finest_depth - 1);
  std::vector<FetchItem> order;
  fetchUntilComplete(model, f.image, zoomed, &order);
  for (const FetchItem& item : order)
    EXPECT_LE(model.levelDepth(item.level), *model.wantedDepth(zoomed));
  ProgressiveDrawStats stats;
  Framebuffer frame(zoomed.width, zoomed.height);
  ASSERT_TRUE(model.draw(zoomed, Variant::kFixedFast, frame, &stats));
  EXPECT_EQ(stats.drawn_depth, *model.wantedDepth(zoomed));
  model.useEveryStoredDepth(true);
  EXPECT_EQ(model.wantedDepth(zoomed), finest_depth);

  // A version-1 file of the same depths: autoLevel stops at the same depth, and the complete
  // stream draws its frame.
  const Bytes v1 = prepare::serializeModel(f.prepared);
  const std::optional<ModelView> file = ModelView::fromBytes(v1, nullptr);
  ASSERT_TRUE(file.has_value());
  model.useEveryStoredDepth(false);
  for (const Camera& camera : {zoomed, makeCamera(0, 0, 1, 320, 240)}) {
    EXPECT_EQ(autoLevel(*file, camera)->depth, *model.wantedDepth(camera));
  }
}

INSTANTIATE_TEST_SUITE_P(WholeAndThinned, ProgressiveModelTest, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& param) {
                           return param.param ? "thinned" : "whole";
                         });

}  // namespace
}  // namespace octopoint
