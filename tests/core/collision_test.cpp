// Collision queries (renderer/collision.h): a sphere against a model's occupied voxels, answered
// exactly as a brute-force test of every leaf answers it (the default model's finest level, spheres
// at random about its leaves; a one-voxel level at its faces and corners; centres outside the cube
// and at the largest coordinates), the ground under a point likewise, and instances with a
// transform carried conservatively (never "free" where the turned, scaled voxels meet the sphere).

#include "renderer/collision.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/models.h"
#include "tests/support/synthetic_levels.h"

namespace octopoint {
namespace {

using testing_support::encodeLevel;
using testing_support::mortonKey;

// Every leaf's lowest corner (Q.24) and its edge, by a plain walk of the stream.
struct CollisionLeafList {
  std::vector<ModelPoint> corners;
  std::int64_t edge = 0;
};

CollisionLeafList collisionLeavesOf(const LevelView& level) {
  CollisionLeafList list;
  list.edge = kPerspectiveUnit >> level.depth;
  const std::uint8_t* cursor = level.nodes.data();
  auto visit = [&](auto& self, int tree_level, ModelPoint lo) -> void {
    const unsigned mask = *cursor++;
    const std::int64_t child_edge = kPerspectiveUnit >> (tree_level + 1);
    for (unsigned child = 0; child < 8; ++child) {
      if ((mask >> child & 1u) == 0) continue;
      const ModelPoint c{lo.x + ((child >> 2) & 1) * child_edge,
                         lo.y + ((child >> 1) & 1) * child_edge, lo.z + (child & 1) * child_edge};
      if (tree_level + 1 == level.depth) {
        list.corners.push_back(c);
      } else {
        self(self, tree_level + 1, c);
      }
    }
  };
  const std::int64_t half = kPerspectiveUnit / 2;
  visit(visit, 0, {-half, -half, -half});
  return list;
}

// The squared distance from `c` to the closed cube at `lo` (the tests' centres lie within 2^25 of
// the leaves: every square fits).
std::int64_t squaredGap(const ModelPoint& c, const ModelPoint& lo, std::int64_t edge) {
  auto gap = [](std::int64_t v, std::int64_t low, std::int64_t high) -> std::int64_t {
    if (v < low) return low - v;
    if (v > high) return v - high;
    return 0;
  };
  const std::int64_t gx = gap(c.x, lo.x, lo.x + edge), gy = gap(c.y, lo.y, lo.y + edge),
                     gz = gap(c.z, lo.z, lo.z + edge);
  return gx * gx + gy * gy + gz * gz;
}

bool bruteForceMeets(const CollisionLeafList& leaves, const CollisionSphere& sphere) {
  const std::int64_t r2 = sphere.radius * sphere.radius;
  for (const ModelPoint& lo : leaves.corners) {
    if (squaredGap(sphere.centre, lo, leaves.edge) < r2) return true;
  }
  return false;
}

ModelView collisionDefaultModel() {
  ModelIssue issue;
  return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
}

TEST(CollisionQuery, AgreesWithEveryLeafOnTheDefaultModel) {
  const ModelView model = collisionDefaultModel();
  for (const int depth : {0, 6}) {
    const std::optional<CollisionModel> collision = CollisionModel::of(model, depth);
    ASSERT_TRUE(collision);
    const LevelView& level = depth == 0 ? model.finestLevel() : *model.levelOfDepth(depth);
    EXPECT_EQ(collision->depth(), level.depth);
    const CollisionLeafList leaves = collisionLeavesOf(level);
    std::mt19937_64 random(33 + static_cast<unsigned>(depth));
    int met = 0;
    constexpr int kQueries = 1500;
    for (int q = 0; q < kQueries; ++q) {
      // About a random leaf, from inside it to 2^19 units (2 to 8 voxels) away: hits, misses
      // and grazes; radii from 2^10 units (1/16 to 1/64 voxel) to 2^18 (4 to 16 voxels).
      const ModelPoint& lo = leaves.corners[random() % leaves.corners.size()];
      const std::int64_t radius = std::int64_t{1} << (10 + static_cast<int>(random() % 9));
      constexpr std::int64_t kAway = std::int64_t{1} << 19;
      const std::int64_t span = leaves.edge + 2 * kAway;
      auto around = [&](std::int64_t low) {
        return low - kAway + static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(span));
      };
      const CollisionSphere sphere{{around(lo.x), around(lo.y), around(lo.z)}, radius};
      const bool expected = bruteForceMeets(leaves, sphere);
      CollisionStats stats;
      ASSERT_EQ(collision->meets(sphere, &stats), expected)
          << "depth " << level.depth << " query " << q << " centre " << sphere.centre.x << ","
          << sphere.centre.y << "," << sphere.centre.z << " radius " << radius;
      met += expected ? 1 : 0;
      // Bounded: far fewer boxes than leaves.
      EXPECT_LT(stats.boxes_tested, leaves.corners.size() / 4);
    }
    // Both answers are exercised.
    EXPECT_GT(met, kQueries / 5);
    EXPECT_LT(met, kQueries * 4 / 5);
  }
}

// One voxel of depth 4 at index (5, 9, 2).
struct OneVoxel {
  testing_support::SyntheticLevel level =
      encodeLevel({mortonKey(5, 9, 2, 4)}, 4, [](std::uint64_t) { return std::uint8_t{0}; });
  std::int64_t edge = kPerspectiveUnit >> 4;
  ModelPoint lo{5 * edge - kPerspectiveUnit / 2, 9 * edge - kPerspectiveUnit / 2,
                2 * edge - kPerspectiveUnit / 2};
};

TEST(CollisionQuery, TouchingAFaceOrACornerIsNotMeetingIt) {
  const OneVoxel voxel;
  const std::optional<CollisionModel> collision = CollisionModel::ofLevel(voxel.level.view());
  ASSERT_TRUE(collision);
  const ModelPoint lo = voxel.lo;
  const std::int64_t e = voxel.edge;
  // Faces: a centre 1000 units before each face; radius 1000 touches, 1001 meets.
  const ModelPoint faces[] = {
      {lo.x - 1000, lo.y + e / 2, lo.z + e / 2}, {lo.x + e + 1000, lo.y + e / 2, lo.z + e / 2},
      {lo.x + e / 2, lo.y - 1000, lo.z + e / 2}, {lo.x + e / 2, lo.y + e + 1000, lo.z + e / 2},
      {lo.x + e / 2, lo.y + e / 2, lo.z - 1000}, {lo.x + e / 2, lo.y + e / 2, lo.z + e + 1000}};
  for (const ModelPoint& c : faces) {
    EXPECT_FALSE(collision->meets({c, 1000}));
    EXPECT_TRUE(collision->meets({c, 1001}));
  }
  // Corners: (2, 3, 6) * 100 from each corner, outwards: 700 away.
  for (unsigned corner = 0; corner < 8; ++corner) {
    const std::int64_t sx = (corner & 4u) ? 1 : -1, sy = (corner & 2u) ? 1 : -1,
                       sz = (corner & 1u) ? 1 : -1;
    const ModelPoint c{lo.x + ((corner & 4u) ? e : 0) + sx * 200,
                       lo.y + ((corner & 2u) ? e : 0) + sy * 300,
                       lo.z + ((corner & 1u) ? e : 0) + sz * 600};
    EXPECT_FALSE(collision->meets({c, 700})) << corner;
    EXPECT_TRUE(collision->meets({c, 701})) << corner;
  }
  // Inside, and a sphere of one unit at the very corner.
  EXPECT_TRUE(collision->meets({{lo.x + 1, lo.y + 1, lo.z + 1}, 1}));
  EXPECT_TRUE(collision->meets({lo, 1}));
  EXPECT_FALSE(collision->meets({{lo.x - 1, lo.y, lo.z}, 1}));
}

TEST(CollisionQuery, OutsideTheCubeAndAtTheLargestCoordinates) {
  const OneVoxel voxel;
  const std::optional<CollisionModel> collision = CollisionModel::ofLevel(voxel.level.view());
  ASSERT_TRUE(collision);
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  for (const std::int64_t far : {kMax, kMin, kMax / 2, kMin / 2, std::int64_t{1} << 40}) {
    EXPECT_FALSE(collision->meets({{far, far, far}, kMaxCollisionRadius}));
    EXPECT_FALSE(collision->meets({{far, voxel.lo.y, voxel.lo.z}, kMaxCollisionRadius}));
    EXPECT_FALSE(sphereMeets(std::span<const CollisionInstance>(), {{far, far, far}, 5}));
  }
  // Radii outside 1 .. the largest meet nothing, even at the voxel.
  EXPECT_FALSE(collision->meets({voxel.lo, 0}));
  EXPECT_FALSE(collision->meets({voxel.lo, -5}));
  EXPECT_FALSE(collision->meets({voxel.lo, kMax}));
  // A voxel on the cube's boundary, reached from outside the cube.
  const testing_support::SyntheticLevel corner =
      encodeLevel({mortonKey(15, 15, 15, 4)}, 4, [](std::uint64_t) { return std::uint8_t{0}; });
  const std::optional<CollisionModel> at_corner = CollisionModel::ofLevel(corner.view());
  ASSERT_TRUE(at_corner);
  const std::int64_t top = kPerspectiveUnit / 2;  // the cube's largest coordinate
  EXPECT_FALSE(at_corner->meets({{top + 3 * 100, top + 4 * 100, top}, 500}));
  EXPECT_TRUE(at_corner->meets({{top + 3 * 100, top + 4 * 100, top}, 501}));
  EXPECT_TRUE(at_corner->meets({{top + kMaxCollisionRadius - 1, top, top}, kMaxCollisionRadius}));
}

TEST(CollisionGround, IsTheHighestTopUnderTheColumnAsEveryLeafSays) {
  const ModelView model = collisionDefaultModel();
  const std::optional<CollisionModel> collision = CollisionModel::of(model);
  ASSERT_TRUE(collision);
  const CollisionLeafList leaves = collisionLeavesOf(model.finestLevel());
  std::mt19937_64 random(330);
  int found = 0;
  for (int q = 0; q < 400; ++q) {
    const ModelPoint& lo = leaves.corners[random() % leaves.corners.size()];
    const std::int64_t width = std::int64_t{1} << (14 + static_cast<int>(random() % 6));
    const std::int64_t reach = std::int64_t{1} << (18 + static_cast<int>(random() % 5));
    const ModelPoint p{lo.x + static_cast<std::int64_t>(random() % 200000) - 100000,
                       lo.y - static_cast<std::int64_t>(random() % 1000000),
                       lo.z + static_cast<std::int64_t>(random() % 200000) - 100000};
    std::optional<std::int64_t> expected;
    for (const ModelPoint& v : leaves.corners) {
      const bool overlaps = v.x < p.x + width && v.x + leaves.edge > p.x - width &&
                            v.z < p.z + width && v.z + leaves.edge > p.z - width &&
                            v.y <= p.y + reach && v.y + leaves.edge >= p.y;
      if (overlaps && (!expected || v.y < *expected)) expected = v.y;
    }
    ASSERT_EQ(collision->groundBelow(p, width, reach), expected) << q;
    found += expected ? 1 : 0;
  }
  EXPECT_GT(found, 100);
  EXPECT_LT(found, 390);
}

// The exact answer for an instance, in 128-bit integers and doubles for the turn: the world
// sphere carried into the model's frame exactly, against every leaf, with `extra` world units
// added to the radius.
bool exactInstanceMeets(const CollisionLeafList& leaves, const InstanceTransform& t,
                        const CollisionSphere& sphere, double extra) {
  const double turn = t.turn.turns16() * 2 * 3.14159265358979323846 / Angle::kUnitsPerTurn;
  const double scale = std::ldexp(1.0, t.scale);
  const double dx = static_cast<double>(sphere.centre.x - t.at.x),
               dy = static_cast<double>(sphere.centre.y - t.at.y),
               dz = static_cast<double>(sphere.centre.z - t.at.z);
  const double mx = (std::cos(turn) * dx - std::sin(turn) * dz) / scale, my = dy / scale,
               mz = (std::sin(turn) * dx + std::cos(turn) * dz) / scale;
  const double r = (static_cast<double>(sphere.radius) + extra) / scale;
  const double e = static_cast<double>(leaves.edge);
  for (const ModelPoint& lo : leaves.corners) {
    auto gap = [e](double v, double low) {
      return v < low ? low - v : v > low + e ? v - low - e : 0.0;
    };
    const double gx = gap(mx, static_cast<double>(lo.x)), gy = gap(my, static_cast<double>(lo.y)),
                 gz = gap(mz, static_cast<double>(lo.z));
    if (gx * gx + gy * gy + gz * gz < r * r) return true;
  }
  return false;
}

TEST(CollisionInstances, TurnedScaledAndMovedAreNeverMissedAndErrOnlyByThePad) {
  const ModelView model = collisionDefaultModel();
  const std::optional<CollisionModel> collision = CollisionModel::of(model, 6);
  ASSERT_TRUE(collision);
  const CollisionLeafList leaves = collisionLeavesOf(*model.levelOfDepth(6));
  std::mt19937_64 random(3303);
  int met = 0;
  for (int q = 0; q < 1000; ++q) {
    // Every scale of a scene (-8..8), anywhere a scene may place it (|at| up to 2^44).
    InstanceTransform t;
    const auto coordinate = [&random](int bits) {
      return static_cast<std::int64_t>(random() % (std::uint64_t{1} << (bits + 1))) -
             (std::int64_t{1} << bits);
    };
    const int place_bits = q % 8 == 0 ? 44 : 27;
    t.at = {coordinate(place_bits), coordinate(place_bits - 1), coordinate(place_bits)};
    t.turn = Angle::fromTurns16(q % 4 == 0 ? 16384 * (q / 4 % 4)
                                           : static_cast<std::int64_t>(random() % 65536));
    t.scale = static_cast<int>(random() % 17) - 8;
    const CollisionInstance instance{&*collision, t};
    // A sphere about a leaf of the instance, in world units.
    const ModelPoint& lo = leaves.corners[random() % leaves.corners.size()];
    const double turn = t.turn.turns16() * 2 * 3.14159265358979323846 / Angle::kUnitsPerTurn;
    const double scale = std::ldexp(1.0, t.scale);
    const double lx = static_cast<double>(lo.x), lz = static_cast<double>(lo.z);
    const ModelPoint world_leaf{
        t.at.x + std::llround(scale * (std::cos(turn) * lx + std::sin(turn) * lz)),
        t.at.y + std::llround(scale * static_cast<double>(lo.y)),
        t.at.z + std::llround(scale * (-std::sin(turn) * lx + std::cos(turn) * lz))};
    // Radii of 2^6 .. 2^24 (up to a scene edge: past 2^31 model units at scale -8).
    const std::int64_t radius = std::int64_t{1} << (6 + static_cast<int>(random() % 19));
    const std::int64_t span = 4 * radius;
    auto around = [&](std::int64_t v) {
      return v - 2 * radius +
             static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(span));
    };
    const CollisionSphere sphere{{around(world_leaf.x), around(world_leaf.y), around(world_leaf.z)},
                                 radius};
    const bool answer = sphereMeets(std::span(&instance, 1), sphere);
    if (exactInstanceMeets(leaves, t, sphere, 0)) {
      EXPECT_TRUE(answer) << q;  // never missed
    }
    if (answer) {
      // Only within the pad: 3 units of the turn, a model unit of the scale's rounding, and
      // (past 2^31 model units) the 12 model units of the quartered squares.
      EXPECT_TRUE(exactInstanceMeets(leaves, t, sphere, 4.0 + 2.0 * scale + 12.0 * scale)) << q;
    }
    // Unturned and unscaled: exactly the model's answer about the translation.
    if (t.turn == Angle{} && t.scale == 0) {
      const ModelPoint local{sphere.centre.x - t.at.x, sphere.centre.y - t.at.y,
                             sphere.centre.z - t.at.z};
      EXPECT_EQ(answer, collision->meets({local, radius})) << q;
    }
    met += answer ? 1 : 0;
  }
  EXPECT_GT(met, 170);
  EXPECT_LT(met, 830);
}

}  // namespace
}  // namespace octopoint
