// The perspective walk at ground level in a large model: the eye one or two metres above the ground
// of a depth-14 level (a 1,000 m cube's 6 cm voxels), its near plane the tools' (half a voxel,
// raised to nearPlaneFloor), on a 2560x1920 frame. The ground before the eye is reached through
// fourteen levels of child offsets; every leaf that draws lies within half a pixel of its
// double-precision projection. A walk that rounds its camera-space sums to the Q.24 unit
// (PerspectiveView::walk_bits 0) puts one 0.571 pixel off (the eye 10,650 units up, 30 degrees,
// yaw 0, pitch -35) and most views 0.2 to 0.35; with the view's sub-unit bits the worst is 0.103.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/perspective_walk.h"
#include "tests/support/perspective_reference.h"
#include "tests/support/synthetic_levels.h"

namespace octopoint {
namespace {

constexpr int kGroundDepth = 14;
constexpr std::int64_t kGroundVoxel = std::int64_t{1} << (kPerspectiveUnitBits - kGroundDepth);
// The ground: one layer of voxels at row kGroundRow (y points down), 128 x 128 of them about
// column kGroundI, kGroundK; the eye above its middle, away from the cube's centre.
constexpr std::uint32_t kGroundRow = 10413, kGroundI = 4749, kGroundK = 13621, kGroundHalf = 64;

struct Ground {
  testing_support::SyntheticLevel level;
  std::vector<ModelPoint> centres;  // Q.24, in stream order
};

Ground makeGround() {
  std::vector<std::uint64_t> keys;
  for (std::uint32_t i = kGroundI - kGroundHalf; i < kGroundI + kGroundHalf; ++i) {
    for (std::uint32_t k = kGroundK - kGroundHalf; k < kGroundK + kGroundHalf; ++k)
      keys.push_back(testing_support::mortonKey(i, kGroundRow, k, kGroundDepth));
  }
  Ground ground;
  ground.level = testing_support::encodeLevel(keys, kGroundDepth,
                                              [](std::uint64_t) { return std::uint8_t{1}; });
  // encodeLevel sorts the keys: the leaves' stream order.
  std::sort(keys.begin(), keys.end());
  const auto centre = [](std::uint32_t n) {
    return std::int64_t{n} * kGroundVoxel + kGroundVoxel / 2 - kPerspectiveUnit / 2;
  };
  for (const std::uint64_t key : keys) {
    std::uint32_t xyz[3] = {0, 0, 0};
    for (int bit = 0; bit < kGroundDepth; ++bit) {
      for (int axis = 0; axis < 3; ++axis)
        xyz[axis] |= static_cast<std::uint32_t>((key >> (3 * bit + 2 - axis)) & 1u) << bit;
    }
    ground.centres.push_back({centre(xyz[0]), centre(xyz[1]), centre(xyz[2])});
  }
  return ground;
}

struct GroundResult {
  double worst = 0;         // pixels
  std::size_t checked = 0;  // leaves whose splat reaches the screen
};

GroundResult walkGround(const Ground& ground, const PerspectiveView& view) {
  const LevelView level = ground.level.view();
  constexpr int kF = kDefaultFractionBits;
  const PerspectiveWalkTables tables =
      perspectiveWalkTables(view, level.depth, std::int64_t{1} << (kF - 2));
  const PerspectiveCamera& camera = view.camera;
  const Matrix m = worldToCamera(camera);
  GroundResult result;
  auto check = [&](const PerspectiveLeaf& leaf) {
    ASSERT_LT(leaf.index, ground.centres.size());
    const ModelPoint& p = ground.centres[leaf.index];
    const Vector3 c = exactCameraSpace(m, camera.eye, p);
    ASSERT_GT(c[2], 0) << "leaf " << leaf.index << " behind the eye was drawn";
    const Projected exact = exactProjection(camera, c[0], c[1], c[2]);
    // Only a leaf whose splat (within sqrt(3) half voxels of its centre) reaches the screen draws.
    const double reach = focalOf(camera) * 0.87 * static_cast<double>(kGroundVoxel) / c[2];
    if (exact.x < -reach || exact.y < -reach || exact.x > camera.width + reach ||
        exact.y > camera.height + reach) {
      return;
    }
    ++result.checked;
    result.worst =
        std::max({result.worst, std::abs(std::ldexp(static_cast<double>(leaf.x), -kF) - exact.x),
                  std::abs(std::ldexp(static_cast<double>(leaf.y), -kF) - exact.y)});
  };
  PerspectiveWalk<decltype(check)> walk(level, view, tables, check);
  EXPECT_TRUE(walk.run());
  return result;
}

TEST(PerspectiveGroundTest, EveryLeafNearTheEyeIsWithinHalfAPixelOnALargeFrame) {
  const Ground ground = makeGround();
  // The eye 21,709 and 10,650 units above the ground's top (1.3 and 0.63 m in a 1,000 m cube), off
  // the voxel grid.
  const std::int64_t top = std::int64_t{kGroundRow} * kGroundVoxel - kPerspectiveUnit / 2;
  const std::int64_t x = std::int64_t{kGroundI} * kGroundVoxel - kPerspectiveUnit / 2 + 1234;
  const std::int64_t z = std::int64_t{kGroundK} * kGroundVoxel - kPerspectiveUnit / 2 - 777;
  for (const std::int64_t height : {21709, 10650}) {
    for (const int fov : {30, 70, 120}) {
      for (const int yaw : {0, 37, 200}) {
        for (const int pitch : {-10, -35}) {
          SCOPED_TRACE("height " + std::to_string(height) + ", fov " + std::to_string(fov) +
                       ", yaw " + std::to_string(yaw) + ", pitch " + std::to_string(pitch));
          PerspectiveCamera camera =
              perspectiveCameraOf({x, top - height, z}, yaw, pitch, fov, 2560, 1920);
          camera.near = nearPlaneForDepth(kGroundDepth);
          PerspectiveView view;
          ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view),
                    PerspectiveError::kNone);
          const GroundResult result = walkGround(ground, view);
          EXPECT_GT(result.checked, 300u);  // the ground fills the frame's lower part
          EXPECT_LE(result.worst, 0.5);
        }
      }
    }
  }
}

}  // namespace
}  // namespace octopoint
