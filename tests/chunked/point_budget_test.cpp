// The progressive model's point budget (octopoint/progressive.h, draw): a view whose points
// exceed the budget draws the chunks it ranks last one depth coarser, exactly as a model that had
// not received them; the ones it keeps are the nearest (largest on screen first); a budget too
// small even for that moves the whole frame a level coarser; a budget the view fits changes
// nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "codegen/model_writer.h"
#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "tests/support/chunked_test_support.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

using octopoint::testing::Bytes;
using octopoint::testing::makeCamera;

// The default model at depths 4..8 in small chunks (as tests/chunked/progressive_model_test.cpp).
struct BudgetFixture {
  prepare::PreparedModel prepared =
      fuzzing::preparedModel(*models::defaultModel(), {4, 5, 6, 7, 8});
  Bytes image = prepare::serializeChunkedModel(prepared, {64, 600});
  std::vector<prepare::PreparedLevel> streams = octopoint::testing::levelStreams(image, prepared);

  ProgressiveModel headOnly() const {
    std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(image, nullptr);
    EXPECT_TRUE(model.has_value());
    return std::move(*model);
  }
  ProgressiveModel whole() const {
    std::optional<ProgressiveModel> model = progressiveModelFromPrefix(image, nullptr);
    EXPECT_TRUE(model.has_value());
    return std::move(*model);
  }
};

const BudgetFixture& fixture() {
  static const BudgetFixture f;
  return f;
}

struct Drawn {
  Framebuffer frame;
  ProgressiveDrawStats stats;
};

Drawn drawWith(const ProgressiveModel& model, ProgressiveFrame& snapshot, const Camera& camera,
               int coarser_levels = 0) {
  Drawn out{Framebuffer(camera.width, camera.height), {}};
  out.frame.clear();
  model.snapshot(snapshot);
  EXPECT_TRUE(model.draw(snapshot, camera, Variant::kFixedFast, out.frame, &out.stats, nullptr,
                         coarser_levels));
  return out;
}

// The level whose depth the view draws.
int levelOfDepth(const ProgressiveModel& model, int depth) {
  int level = 0;
  while (level + 1 < model.levelCount() && model.levelDepth(level + 1) <= depth) ++level;
  return level;
}

// A region's centre on screen (Q(32-F).F), as the model places it: the sum of the child offsets
// down to its region level.
Vec3 regionCentre(const ProgressiveModel& model, const Camera& camera, int level,
                  std::uint32_t region) {
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, model.levelDepth(level), kDefaultFractionBits, &setup),
            CameraError::kNone);
  const int region_level = model.head().levels[static_cast<std::size_t>(level)].region_level;
  Vec3 centre = setup.root;
  for (int l = 0; l < region_level; ++l) {
    const Vec3& d = setup.child_offset[static_cast<std::size_t>(l)]
                                      [(region >> (3 * (region_level - 1 - l))) & 7u];
    centre = {centre.x + d.x, centre.y + d.y, centre.z + d.z};
  }
  return centre;
}

TEST(PointBudget, ChunksOverTheBudgetAreDrawnAsIfTheyHadNotArrived) {
  const BudgetFixture& f = fixture();
  const ProgressiveModel model = f.whole();
  for (const Camera& camera : {makeCamera(30, -20, 1, 320, 240), makeCamera(0, 0, 2, 320, 240),
                               makeCamera(160, 30, 0.5, 320, 240)}) {
    ProgressiveFrame snapshot;
    const Drawn full = drawWith(model, snapshot, camera);
    ASSERT_EQ(full.stats.over_budget_chunks, 0u);
    const std::uint64_t budget = full.stats.points * 3 / 4;
    snapshot.setPointBudget(budget);
    const Drawn within = drawWith(model, snapshot, camera);
    EXPECT_LE(within.stats.points, budget);
    EXPECT_GT(within.stats.points, budget / 2) << "keeps as much of the depth as fits";
    EXPECT_EQ(within.stats.drawn_depth, full.stats.drawn_depth);
    ASSERT_GT(within.stats.over_budget_chunks, 0u);
    EXPECT_FALSE(octopoint::testing::sameFrame(within.frame, full.frame));

    // A model holding every chunk but those the budget drew coarser draws the same frame, bit for
    // bit, without a budget; and that is the independent reference's frame for those chunks.
    const int level = levelOfDepth(model, within.stats.drawn_depth);
    ProgressiveModel without = f.headOnly();
    octopoint::testing::feedTables(without, f.image);
    std::uint32_t withheld = 0;
    for (const FetchItem& item : octopoint::testing::allChunkItems(without)) {
      if (item.level == level && snapshot.overBudget(level, item.index)) {
        ++withheld;
        continue;
      }
      octopoint::testing::feed(without, f.image, item);
    }
    EXPECT_EQ(withheld, within.stats.over_budget_chunks);
    ProgressiveFrame plain;
    EXPECT_TRUE(
        octopoint::testing::sameFrame(drawWith(without, plain, camera).frame, within.frame));
    EXPECT_TRUE(octopoint::testing::sameFrame(
        within.frame,
        octopoint::testing::referenceFrame(without, f.streams, camera, Variant::kFixedFast)));
  }
}

// Zoomed out so that every region lies whole on screen: all are as large on screen, so the budget
// keeps the nearest (smallest z) and draws the farther ones coarser.
TEST(PointBudget, KeepsTheNearestChunksAtTheirDepth) {
  const BudgetFixture& f = fixture();
  const ProgressiveModel model = f.whole();
  for (const int yaw : {0, 180, 90}) {
    const Camera camera = makeCamera(yaw, 10, 0.5, 320, 240);
    ProgressiveFrame snapshot;
    const Drawn full = drawWith(model, snapshot, camera);
    snapshot.setPointBudget(full.stats.points * 2 / 3);
    const Drawn within = drawWith(model, snapshot, camera);
    ASSERT_GT(within.stats.over_budget_chunks, 0u);
    const int level = levelOfDepth(model, within.stats.drawn_depth);
    std::int64_t farthest_kept = INT64_MIN, nearest_coarser = INT64_MAX;
    int kept = 0;
    for (std::uint32_t i = 0; i < model.chunkCount(level); ++i) {
      const std::int32_t z = regionCentre(model, camera, level, model.record(level, i).region).z;
      if (snapshot.overBudget(level, i)) {
        nearest_coarser = std::min<std::int64_t>(nearest_coarser, z);
      } else {
        farthest_kept = std::max<std::int64_t>(farthest_kept, z);
        ++kept;
      }
    }
    EXPECT_GT(kept, 0);
    EXPECT_LE(farthest_kept, nearest_coarser) << "yaw " << yaw;
  }
}

// A budget below even the coarser depth's points moves the frame up a level (down to level 1,
// whose chunks then all give way to the base): the frame of a model that has only the record
// tables, drawn that many levels coarser.
TEST(PointBudget, ABudgetTooSmallForOneDepthCoarserDrawsALevelAbove) {
  const BudgetFixture& f = fixture();
  const ProgressiveModel model = f.whole();
  ProgressiveModel tables_only = f.headOnly();
  octopoint::testing::feedTables(tables_only, f.image);
  const Camera camera = makeCamera(20, -10, 1, 320, 240);
  ProgressiveFrame snapshot;
  const Drawn full = drawWith(model, snapshot, camera);
  const int full_level = levelOfDepth(model, full.stats.drawn_depth);
  ASSERT_GE(full_level, 3);
  snapshot.setPointBudget(1);
  const Drawn within = drawWith(model, snapshot, camera);
  EXPECT_EQ(within.stats.drawn_depth, model.levelDepth(1));
  EXPECT_EQ(within.stats.over_budget_chunks, within.stats.pieces);
  ProgressiveFrame plain;
  EXPECT_TRUE(octopoint::testing::sameFrame(
      drawWith(tables_only, plain, camera, full_level - 1).frame, within.frame));
}

TEST(PointBudget, ABudgetTheViewFitsChangesNothing) {
  const BudgetFixture& f = fixture();
  const ProgressiveModel model = f.whole();
  const Camera camera = makeCamera(30, -20, 1, 320, 240);
  ProgressiveFrame snapshot;
  const Drawn full = drawWith(model, snapshot, camera);
  snapshot.setPointBudget(full.stats.points);
  const Drawn within = drawWith(model, snapshot, camera);
  EXPECT_EQ(within.stats.over_budget_chunks, 0u);
  EXPECT_EQ(within.stats.points, full.stats.points);
  EXPECT_TRUE(octopoint::testing::sameFrame(within.frame, full.frame));
}

}  // namespace
}  // namespace octopoint
