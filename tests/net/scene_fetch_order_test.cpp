// A scene's fetch order (net/scene_fetch_order.h): heads first, the nearest instance's model's
// first; then every model's coarse levels before the fine ones, within a level the nearer
// instance's regions first; each item once; nothing for an instance behind the eye unless the
// tier takes what the view does not show.
#include "net/scene_fetch_order.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "tests/support/net_test_support.h"

namespace octopoint {
namespace {

constexpr std::int64_t kSceneEdge = kPerspectiveUnit;

struct SceneFixture {
  // Model 1 two scene edges ahead of the eye, model 0 six ahead and four behind it.
  std::vector<SceneInstance> instances = {
      {1, {{0, 0, 2 * kSceneEdge}, Angle{}, 0}},
      {0, {{0, 0, 6 * kSceneEdge}, Angle{}, 0}},
      {0, {{0, 0, -4 * kSceneEdge}, Angle{}, 0}},
  };
  // The default model's chunked file with its head and every record table, no chunk.
  ProgressiveModel tablesOnly() const {
    const std::vector<std::uint8_t>& image = testing::streamedModelImage();
    ChunkedIssue issue;
    const std::size_t tables_end =
        progressiveModelFromPrefix(image, &issue)->head().levels[1].chunks_offset;
    std::optional<ProgressiveModel> model =
        progressiveModelFromPrefix(std::span(image).first(tables_end), &issue);
    EXPECT_TRUE(model.has_value());
    return std::move(*model);
  }
};

net::SceneFetchTier tierAtOrigin(bool around) {
  PerspectiveCamera camera;  // at the origin, looking along +z
  camera.width = 320;
  camera.height = 240;
  net::SceneFetchTier tier;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &tier.view),
            PerspectiveError::kNone);
  tier.include_invisible = around;
  return tier;
}

TEST(SceneFetchOrder, HeadsFirstTheNearestInstancesModelFirstNothingBehindTheEye) {
  const SceneFixture scene;
  std::vector<ProgressiveModel*> models(2, nullptr);
  net::SceneFetchOrder order;
  std::vector<net::SceneFetchEntry> entries;
  const std::vector<net::SceneFetchTier> view = {tierAtOrigin(false)};
  order.order(models, scene.instances, view, entries);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_TRUE(entries[0].head && entries[1].head);
  EXPECT_EQ(entries[0].model, 1u);  // two scene edges ahead
  EXPECT_EQ(entries[1].model, 0u);
  // Only the instance behind the eye: nothing in view, its model's head around the eye.
  net::SceneFetchTier behind = tierAtOrigin(false);
  behind.every_instance = false;
  behind.instances = {2};
  order.order(models, scene.instances, std::vector{behind}, entries);
  EXPECT_TRUE(entries.empty());
  behind.include_invisible = true;
  order.order(models, scene.instances, std::vector{behind}, entries);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].model, 0u);
}

TEST(SceneFetchOrder, CoarseLevelsOfEveryModelFirstTheNearerInstanceFirstEachItemOnce) {
  const SceneFixture scene;
  ProgressiveModel far = scene.tablesOnly(), near = scene.tablesOnly();
  std::vector<ProgressiveModel*> models = {&far, &near};
  net::SceneFetchOrder order;
  std::vector<net::SceneFetchEntry> entries;
  order.order(models, scene.instances, std::vector{tierAtOrigin(false)}, entries);
  ASSERT_FALSE(entries.empty());
  std::set<std::tuple<std::uint32_t, int, std::uint32_t>> seen;
  int level = 0;
  std::uint32_t last_model = 1;
  bool both = false;
  for (const net::SceneFetchEntry& entry : entries) {
    EXPECT_FALSE(entry.head);
    EXPECT_EQ(entry.item.kind, FetchItem::Kind::kChunk);  // every table is held
    EXPECT_TRUE(seen.insert({entry.model, entry.item.level, entry.item.index}).second);
    EXPECT_GE(entry.item.level, level);  // coarse before fine
    if (entry.item.level != level) last_model = 1;
    level = entry.item.level;
    // Within a level, the instance two scene edges ahead (model 1) before the one six ahead.
    EXPECT_LE(entry.model, last_model) << "level " << level;
    last_model = entry.model;
    both = both || entry.model == 0;
  }
  EXPECT_TRUE(both);
  EXPECT_EQ(entries.front().model, 1u);
}

}  // namespace
}  // namespace octopoint
