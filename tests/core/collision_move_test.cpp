// Moving with collision (renderer/collision_move.h) in a generated box room
// (tests/support/box_room.h) and in the default model: a long step stops before a wall one voxel
// thick instead of passing it, a step into a wall slides along it, gravity keeps the eye at eye
// height above the floor and the low box, instances move the room; and 10,000 random walk steps
// (seeded) never put the eye's sphere into occupied space nor under the floor.

#include "renderer/collision_move.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <optional>
#include <random>

#include "fixedpoint/trig.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "renderer/collision.h"
#include "tests/support/box_room.h"

namespace octopoint {
namespace {

using testing_support::BoxRoom;

constexpr std::int64_t kRoomRadius = BoxRoom::kVoxel / 4;     // a quarter voxel: 2^16
constexpr std::int64_t kRoomEyeHeight = 3 * BoxRoom::kVoxel;  // three voxels above the floor
constexpr std::int64_t kFloorTop = BoxRoom::at(BoxRoom::kFloor);
// What a blocked axis may fall short of the wall: 1/64 of a sub-step, at most the radius.
constexpr std::int64_t kSlideGap = kRoomRadius / 64 + 1;

// The voxel's centre along an axis.
constexpr std::int64_t roomCentre(int n) { return BoxRoom::at(n) + BoxRoom::kVoxel / 2; }

struct RoomWorld {
  testing_support::SyntheticLevel level = BoxRoom::level();
  CollisionModel model = *CollisionModel::ofLevel(level.view());
  CollisionInstance instance{&model, {}};
  std::span<const CollisionInstance> world() const { return {&instance, 1}; }
};

TEST(CollisionMove, ALongStepStopsBeforeAThinWallInsteadOfPassingIt) {
  const RoomWorld room;
  const WalkBody body{kRoomRadius, 0};
  const ModelPoint from{roomCentre(28), roomCentre(30), roomCentre(20)};
  ASSERT_FALSE(sphereMeets(room.world(), {from, kRoomRadius}));
  // Eight voxels in one step: 32 radii; the wall is one voxel thick and free space lies behind.
  const ModelPoint to{roomCentre(36), from.y, from.z};
  ASSERT_FALSE(sphereMeets(room.world(), {to, kRoomRadius}));
  const CollisionMove move = moveWithCollision(room.world(), body, from, to);
  EXPECT_TRUE(move.blocked);
  const std::int64_t wall = BoxRoom::at(BoxRoom::kThinWall);
  EXPECT_LE(move.eye.x + kRoomRadius, wall);
  EXPECT_GE(move.eye.x + kRoomRadius, wall - kSlideGap);
  EXPECT_EQ(move.eye.y, from.y);
  EXPECT_EQ(move.eye.z, from.z);
  // Through the doorway beside it the same step goes all the way.
  const ModelPoint door{roomCentre(28), roomCentre(30), roomCentre(50)};
  const ModelPoint beyond{roomCentre(36), door.y, door.z};
  const CollisionMove through = moveWithCollision(room.world(), body, door, beyond);
  EXPECT_FALSE(through.blocked);
  EXPECT_EQ(through.eye, beyond);
}

TEST(CollisionMove, AStepIntoAWallSlidesAlongIt) {
  const RoomWorld room;
  const WalkBody body{kRoomRadius, 0};
  const ModelPoint from{roomCentre(30), roomCentre(30), roomCentre(10)};
  // Four voxels towards the wall and four along it, at once.
  const ModelPoint to{from.x + 4 * BoxRoom::kVoxel, from.y, from.z + 4 * BoxRoom::kVoxel};
  const CollisionMove move = moveWithCollision(room.world(), body, from, to);
  EXPECT_TRUE(move.blocked);
  const std::int64_t wall = BoxRoom::at(BoxRoom::kThinWall);
  EXPECT_LE(move.eye.x + kRoomRadius, wall);
  EXPECT_GE(move.eye.x + kRoomRadius, wall - kSlideGap);
  EXPECT_EQ(move.eye.z, to.z);  // the component along the wall, whole
  EXPECT_EQ(move.eye.y, from.y);
  // Into the corner of the room: both components stop, neither passes.
  const ModelPoint corner_to{BoxRoom::at(BoxRoom::kLow) - BoxRoom::kVoxel, from.y,
                             BoxRoom::at(BoxRoom::kLow) - BoxRoom::kVoxel};
  const CollisionMove cornered = moveWithCollision(room.world(), body, from, corner_to);
  EXPECT_GE(cornered.eye.x - kRoomRadius, BoxRoom::at(BoxRoom::kLow + 1));
  EXPECT_GE(cornered.eye.z - kRoomRadius, BoxRoom::at(BoxRoom::kLow + 1));
  EXPECT_LE(cornered.eye.x - kRoomRadius, BoxRoom::at(BoxRoom::kLow + 1) + kSlideGap);
  EXPECT_LE(cornered.eye.z - kRoomRadius, BoxRoom::at(BoxRoom::kLow + 1) + kSlideGap);
}

TEST(CollisionMove, GravityKeepsTheEyeAtEyeHeightOverTheFloorAndTheBox) {
  const RoomWorld room;
  const WalkBody body{kRoomRadius, kRoomEyeHeight};
  // Five voxels above the floor: within reach (six), so it comes down to three.
  const ModelPoint from{roomCentre(36), kFloorTop - 5 * BoxRoom::kVoxel, roomCentre(10)};
  const CollisionMove settled = moveWithCollision(room.world(), body, from, from);
  EXPECT_TRUE(settled.grounded);
  EXPECT_EQ(settled.eye.y, kFloorTop - kRoomEyeHeight);
  // Onto the box (its top two voxels up) and off it again, level.
  const ModelPoint on_box{roomCentre(44), settled.eye.y, roomCentre(20)};
  const CollisionMove up = moveWithCollision(room.world(), body, settled.eye, on_box);
  EXPECT_EQ(up.eye.x, on_box.x);
  EXPECT_EQ(up.eye.z, on_box.z);
  EXPECT_EQ(up.eye.y, BoxRoom::at(BoxRoom::kBoxTop) - kRoomEyeHeight);
  const ModelPoint off{roomCentre(52), up.eye.y, roomCentre(20)};
  const CollisionMove down = moveWithCollision(room.world(), body, up.eye, off);
  EXPECT_EQ(down.eye.y, kFloorTop - kRoomEyeHeight);
  // Without gravity the eye keeps its height.
  const CollisionMove floating = moveWithCollision(room.world(), {kRoomRadius, 0}, from, from);
  EXPECT_EQ(floating.eye, from);
  EXPECT_FALSE(floating.grounded);
}

TEST(CollisionMove, AMovedRoomMovesTheWalkAndATurnedOneStillStopsIt) {
  const RoomWorld room;
  const WalkBody body{kRoomRadius, kRoomEyeHeight};
  const ModelPoint from{roomCentre(28), roomCentre(40), roomCentre(20)};
  const ModelPoint to{roomCentre(36), from.y, roomCentre(24)};
  const CollisionMove local = moveWithCollision(room.world(), body, from, to);
  const ModelPoint shift{5 * kPerspectiveUnit + 12345, -kPerspectiveUnit / 3, 77};
  CollisionInstance moved = room.instance;
  moved.transform.at = shift;
  const auto plus = [&shift](const ModelPoint& p) {
    return ModelPoint{p.x + shift.x, p.y + shift.y, p.z + shift.z};
  };
  const CollisionMove world = moveWithCollision({&moved, 1}, body, plus(from), plus(to));
  EXPECT_EQ(world.eye, plus(local.eye));
  EXPECT_EQ(world.grounded, local.grounded);
  // Turned a quarter turn (the model's +x now along the world's -z) and doubled: the thin wall
  // now lies across z, and a long step along -z stops before it.
  CollisionInstance turned = room.instance;
  turned.transform = {.at = shift, .turn = Angle::fromDegrees(90), .scale = 1};
  // World = shift + 2 Ry(90) model: model (x, y, z) -> (2 z, 2 y, -2 x) about the shift.
  const auto world_of = [&shift](const ModelPoint& m) {
    return ModelPoint{shift.x + 2 * m.z, shift.y + 2 * m.y, shift.z - 2 * m.x};
  };
  const WalkBody twice{2 * kRoomRadius, 0};
  const ModelPoint turned_from = world_of(from);
  const ModelPoint turned_to = world_of({roomCentre(36), from.y, from.z});
  const CollisionMove stopped = moveWithCollision({&turned, 1}, twice, turned_from, turned_to);
  EXPECT_TRUE(stopped.blocked);
  const std::int64_t wall_far_side = shift.z - 2 * BoxRoom::at(BoxRoom::kThinWall);
  EXPECT_GE(stopped.eye.z - 2 * kRoomRadius, wall_far_side - 8);  // the turn's pad
  EXPECT_LE(stopped.eye.z - 2 * kRoomRadius, wall_far_side + 2 * kSlideGap + 8);
}

// A seeded random walk: steps of up to four voxels (16 radii) in a random direction, a fifth of
// them with a vertical part; after each, the eye's sphere meets nothing (the exact query) and,
// with gravity, stands at eye height over the ground under it.
struct RandomWalkResult {
  int blocked = 0;
  int grounded = 0;
  int slid = 0;  // steps that ended off the line asked for (horizontally): a wall turned them
};

RandomWalkResult randomRoomWalk(const RoomWorld& room, const WalkBody& body, unsigned seed) {
  std::mt19937_64 random(seed);
  // Standing on the floor (flying: as high).
  ModelPoint eye{roomCentre(20), kFloorTop - kRoomEyeHeight, roomCentre(20)};
  RandomWalkResult result;
  for (int step = 0; step < 10'000; ++step) {
    const Angle yaw = Angle::fromTurns16(static_cast<std::int64_t>(random() % 65536));
    const auto length = static_cast<std::int64_t>(random() % (4 * BoxRoom::kVoxel));
    const std::int64_t rise =
        random() % 5 == 0
            ? static_cast<std::int64_t>(random() % (8 * BoxRoom::kVoxel)) - 4 * BoxRoom::kVoxel
            : 0;
    const ModelPoint to{eye.x + length * sinQ30(yaw) / (std::int64_t{1} << 30), eye.y + rise,
                        eye.z + length * cosQ30(yaw) / (std::int64_t{1} << 30)};
    const CollisionMove move = moveWithCollision(room.world(), body, eye, to);
    // Off the line: the cross product of the move and the request, horizontally, beyond the
    // sub-steps' rounding (values below 2^21: the products fit).
    const std::int64_t mx = move.eye.x - eye.x, mz = move.eye.z - eye.z, wx = to.x - eye.x,
                       wz = to.z - eye.z;
    const std::int64_t cross = mx * wz - mz * wx;
    if (std::abs(cross) > (std::abs(mx) + std::abs(mz)) * (std::abs(wx) + std::abs(wz)) / 16) {
      ++result.slid;
    }
    eye = move.eye;
    result.blocked += move.blocked ? 1 : 0;
    result.grounded += move.grounded ? 1 : 0;
    EXPECT_FALSE(sphereMeets(room.world(), {eye, body.radius}))
        << "step " << step << " eye " << eye.x << "," << eye.y << "," << eye.z;
    EXPECT_LE(eye.y + body.radius, kFloorTop) << "under the floor at step " << step;
    if (body.eye_height != 0) {
      const std::optional<std::int64_t> standing = groundUnder(room.world(), body, eye);
      EXPECT_TRUE(standing) << step;
      if (standing) {
        EXPECT_LE(std::abs(eye.y - *standing), kSlideGap) << step;
      }
    }
    if (::testing::Test::HasFailure()) break;
  }
  return result;
}

TEST(CollisionRandomWalk, TenThousandStepsInTheBoxRoomNeverEnterAWallNorTheFloor) {
  const RoomWorld room;
  const RandomWalkResult flying = randomRoomWalk(room, {kRoomRadius, 0}, 33);
  const RandomWalkResult walking = randomRoomWalk(room, {kRoomRadius, kRoomEyeHeight}, 34);
  // The walls were met often: the test exercised the stops and the slides.
  EXPECT_GT(flying.blocked, 1000);
  EXPECT_GT(walking.blocked, 1000);
  // And slid along them (a step that only stopped would stay on its line).
  EXPECT_GT(flying.slid, 500);
  EXPECT_GT(walking.slid, 500);
  EXPECT_EQ(walking.grounded, 10'000);
}

TEST(CollisionRandomWalk, TenThousandStepsInTheDefaultModelNeverEnterItsVoxels) {
  ModelIssue issue;
  const ModelView model = *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  const CollisionModel collision = *CollisionModel::of(model);
  const CollisionInstance instance{&collision, {}};
  const std::span<const CollisionInstance> world(&instance, 1);
  for (const std::int64_t eye_height : {std::int64_t{0}, kPerspectiveUnit / 16}) {
    const WalkBody body{kPerspectiveUnit / 256, eye_height};  // one depth-8 voxel
    std::mt19937_64 random(35 + static_cast<unsigned>(eye_height));
    // The eye at the table's edge (the perspective benchmarks' view).
    const ModelPoint start{0, kPerspectiveUnit * 28 / 100, -kPerspectiveUnit * 46 / 100};
    ASSERT_FALSE(sphereMeets(world, {start, body.radius}));
    ModelPoint eye = start;
    int blocked = 0;
    for (int step = 0; step < 10'000; ++step) {
      // Steps of up to 1/16 cube edge (16 depth-8 voxels), drawn back towards the start when
      // the walk strays a third of an edge from it.
      const auto toward = [&random](std::int64_t from, std::int64_t home) {
        const std::int64_t span = kPerspectiveUnit / 16;
        std::int64_t d = static_cast<std::int64_t>(random() % (2 * span)) - span;
        if (from - home > kPerspectiveUnit / 3) d = -std::abs(d);
        if (home - from > kPerspectiveUnit / 3) d = std::abs(d);
        return from + d;
      };
      const ModelPoint to{toward(eye.x, start.x), toward(eye.y, start.y), toward(eye.z, start.z)};
      const CollisionMove move = moveWithCollision(world, body, eye, to);
      eye = move.eye;
      blocked += move.blocked ? 1 : 0;
      ASSERT_FALSE(collision.meets({eye, body.radius}))
          << "step " << step << " eye " << eye.x << "," << eye.y << "," << eye.z;
    }
    EXPECT_GT(blocked, 100) << eye_height;
  }
}

}  // namespace
}  // namespace octopoint
