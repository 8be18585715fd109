// Collision against a scene (renderer/scene_collision.h): its grid finds every instance a sphere
// meets (the same answer as testing every instance in turn, sphere for sphere and step for step
// of a walk), while testing only the few instances near the sphere; bad scenes are refused.

#include "renderer/scene_collision.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "octopoint/models.h"
#include "renderer/collision_move.h"

namespace octopoint {
namespace {

ModelView sceneCollisionModel() {
  ModelIssue issue;
  return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
}

// 400 instances of the default model scattered over 16 x 16 scene edges, turned any way, at
// scales -3..1, a few of them stacked.
std::vector<SceneInstance> scatteredInstances(unsigned seed) {
  std::mt19937_64 random(seed);
  std::vector<SceneInstance> instances;
  for (int i = 0; i < 400; ++i) {
    const auto across = [&random] {
      return static_cast<std::int64_t>(random() % (std::uint64_t{16} << 24)) -
             (std::int64_t{8} << 24);
    };
    InstanceTransform t;
    t.at = {across(), static_cast<std::int64_t>(random() % (1u << 24)) - (1 << 23), across()};
    t.turn = Angle::fromTurns16(static_cast<std::int64_t>(random() % 65536));
    t.scale = static_cast<int>(random() % 5) - 3;
    instances.push_back({0, t});
  }
  return instances;
}

TEST(SceneCollision, FindsWhatTestingEveryInstanceFindsAndTestsFew) {
  const ModelView model = sceneCollisionModel();
  const ModelView* models[] = {&model};
  const std::vector<SceneInstance> instances = scatteredInstances(33);
  SceneError error;
  const SceneCollision scene(models, instances, &error);
  ASSERT_EQ(error, SceneError::kNone);
  ASSERT_FALSE(scene.unindexedModel());
  ASSERT_EQ(scene.instances().size(), instances.size());
  std::mt19937_64 random(34);
  int met = 0;
  CollisionStats stats;
  constexpr int kQueries = 4000;
  for (int q = 0; q < kQueries; ++q) {
    // About an instance, or anywhere over the scene and beyond it.
    const InstanceTransform& near = instances[random() % instances.size()].transform;
    const auto jitter = [&random](int bits) {
      return static_cast<std::int64_t>(random() % (std::uint64_t{2} << bits)) -
             (std::int64_t{1} << bits);
    };
    const int spread = q % 4 == 0 ? 28 : 22;
    const CollisionSphere sphere{
        {near.at.x + jitter(spread), near.at.y + jitter(spread - 1), near.at.z + jitter(spread)},
        std::int64_t{1} << (12 + static_cast<int>(random() % 13))};
    const bool answer = scene.meets(sphere, &stats);
    ASSERT_EQ(answer, sphereMeets(scene.instances(), sphere)) << q;
    met += answer ? 1 : 0;
  }
  EXPECT_GT(met, kQueries / 10);
  EXPECT_LT(met, kQueries * 9 / 10);
  // A tenth of the 400 per query at most (the grid's cells as wide as the widest box).
  EXPECT_LT(stats.instances_tested, std::uint64_t{40} * kQueries);
}

TEST(SceneCollision, AWalkAmongTheInstancesIsTheWalkTestingEveryInstance) {
  const ModelView model = sceneCollisionModel();
  const ModelView* models[] = {&model};
  const std::vector<SceneInstance> instances = scatteredInstances(35);
  SceneError error;
  const SceneCollision scene(models, instances, &error);
  ASSERT_EQ(error, SceneError::kNone);
  const CollisionInstances every(scene.instances());
  std::mt19937_64 random(36);
  for (const std::int64_t eye_height : {std::int64_t{0}, std::int64_t{1} << 21}) {
    const WalkBody body{std::int64_t{1} << 18, eye_height};
    ModelPoint eye{0, 0, 0};
    int blocked = 0;
    for (int step = 0; step < 300; ++step) {
      const auto part = [&random] {
        return static_cast<std::int64_t>(random() % (std::uint64_t{1} << 23)) -
               (std::int64_t{1} << 22);
      };
      const ModelPoint to{eye.x + part(), eye.y + part() / 2, eye.z + part()};
      const CollisionMove move = moveWithCollision(scene, body, eye, to);
      const CollisionMove expected = moveWithCollision(every, body, eye, to);
      ASSERT_EQ(move.eye, expected.eye) << step;
      ASSERT_EQ(move.blocked, expected.blocked) << step;
      blocked += move.blocked ? 1 : 0;
      eye = move.eye;
    }
    EXPECT_GT(blocked, 5) << eye_height;
  }
}

// Containers moved between frames (place): a query meets each moved instance where it is now, far
// from where the grid was built, and nowhere it was: the answers are those of testing every
// instance at its new place; a bad move is refused and leaves the instance where it was.
TEST(SceneCollision, MovedInstancesAreMetWhereTheyAreNow) {
  const ModelView model = sceneCollisionModel();
  const ModelView* models[] = {&model};
  std::vector<SceneInstance> instances = scatteredInstances(37);
  SceneError error;
  SceneCollision scene(models, instances, &error);
  ASSERT_EQ(error, SceneError::kNone);
  // The reference: every instance at its place now, each tested in turn.
  const auto every_instance = [&scene](const std::vector<SceneInstance>& at) {
    std::vector<CollisionInstance> list;
    for (const SceneInstance& instance : at)
      list.push_back({scene.instances()[instance.model].model, instance.transform});
    return list;
  };
  std::mt19937_64 random(38);
  // Every tenth instance moves three times, once well outside the grid's extent.
  for (int round = 0; round < 3; ++round) {
    for (std::size_t i = 0; i < instances.size(); i += 10) {
      InstanceTransform& t = instances[i].transform;
      t.at.x += (round == 1 ? std::int64_t{40} : std::int64_t{3}) << 24;
      t.at.z -= std::int64_t{2} << 24;
      t.turn = Angle::fromTurns16(static_cast<std::int64_t>(random() % 65536));
      ASSERT_EQ(scene.place(i, t), SceneError::kNone);
    }
    const std::vector<CollisionInstance> now = every_instance(instances);
    const CollisionInstances every(now);
    int met_moved = 0;
    for (int q = 0; q < 600; ++q) {
      const bool about_moved = q % 2 == 0;
      const std::size_t which = (random() % (instances.size() / 10)) * 10 + (about_moved ? 0 : 5);
      const InstanceTransform& near = instances[which].transform;
      const auto jitter = [&random](int bits) {
        return static_cast<std::int64_t>(random() % (std::uint64_t{2} << bits)) -
               (std::int64_t{1} << bits);
      };
      const CollisionSphere sphere{
          {near.at.x + jitter(22), near.at.y + jitter(21), near.at.z + jitter(22)},
          std::int64_t{1} << (14 + static_cast<int>(random() % 9))};
      const bool answer = scene.meets(sphere);
      ASSERT_EQ(answer, every.meets(sphere)) << "round " << round << " query " << q;
      met_moved += about_moved && answer ? 1 : 0;
    }
    EXPECT_GT(met_moved, 30) << round;
  }
  // Where a moved instance stood when the grid was built, it is met no more (unless another
  // instance stands there): the first instance's old place, tested against every instance now.
  const InstanceTransform before = scatteredInstances(37)[0].transform;
  const CollisionSphere old_place{before.at, std::int64_t{1} << 18};
  EXPECT_EQ(scene.meets(old_place), sphereMeets(every_instance(instances), old_place));
  // Refused moves leave the instance where it was.
  const InstanceTransform kept = scene.instances()[10].transform;
  EXPECT_EQ(scene.place(instances.size(), kept), SceneError::kBadInstanceIndex);
  EXPECT_EQ(scene.place(10, {.at = {0, 0, 0}, .turn = Angle{}, .scale = 9}), SceneError::kBadScale);
  EXPECT_EQ(scene.place(10, {{kMaxSceneCoordinate * 2, 0, 0}, {}, 0}),
            SceneError::kCoordinateTooLarge);
  EXPECT_EQ(scene.instances()[10].transform.at.x, kept.at.x);
  EXPECT_EQ(scene.instances()[10].transform.at.z, kept.at.z);
}

TEST(SceneCollision, RefusesWhatTheRendererRefuses) {
  const ModelView model = sceneCollisionModel();
  const ModelView* models[] = {&model};
  SceneError error;
  std::vector<SceneInstance> instances{{1, {}}};
  const SceneCollision bad_index(models, instances, &error);
  EXPECT_EQ(error, SceneError::kBadModelIndex);
  EXPECT_FALSE(bad_index.meets({{0, 0, 0}, kMaxCollisionRadius}));
  instances = {{0, {.at = {0, 0, 0}, .turn = Angle{}, .scale = 9}}};
  const SceneCollision bad_scale(models, instances, &error);
  EXPECT_EQ(error, SceneError::kBadScale);
  const SceneCollision none(models, {}, &error);
  EXPECT_EQ(error, SceneError::kNoInstances);
  // Far away on every axis, at the extremes: nothing met, nothing read.
  instances = {{0, {}}};
  const SceneCollision one(models, instances, &error);
  ASSERT_EQ(error, SceneError::kNone);
  EXPECT_TRUE(one.meets({{0, 0, 0}, kMaxCollisionRadius}));
  for (const std::int64_t far : {INT64_MAX, INT64_MIN, std::int64_t{1} << 45}) {
    CollisionStats stats;
    EXPECT_FALSE(one.meets({{far, 0, far}, kMaxCollisionRadius}, &stats));
    EXPECT_EQ(stats.instances_tested, 0u);
  }
}

}  // namespace
}  // namespace octopoint
