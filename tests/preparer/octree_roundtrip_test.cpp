// Voxels -> stream -> decode: with an identity camera that maps one voxel to one pixel, the
// decoder must give back exactly the voxel set the encoder was given, in the same order.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "codegen/octree_encoder.h"
#include "codegen/voxelizer.h"
#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/decode_baseline.h"

namespace octopoint {
namespace {

// At zoom 1 with a 2^d x 2^d framebuffer, leaf centres land on (i + 0.5) pixels on x and y, and
// on (k + 0.5 - 2^(d-1)) on z: exact in Q15, so shifting recovers the voxel indices.
std::vector<std::uint64_t> decodeWithIdentityCamera(const LevelView& level) {
  const int depth = level.depth;
  Camera camera;
  camera.width = camera.height = 1 << depth;
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, depth, kDefaultFractionBits, &setup), CameraError::kNone);
  std::vector<std::uint64_t> keys;
  auto sink = [&](std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t) {
    const int f = setup.fraction_bits;
    const auto vx = static_cast<std::uint32_t>(x >> f);
    const auto vy = static_cast<std::uint32_t>(y >> f);
    const auto vz = static_cast<std::uint32_t>((z >> f) + (1 << (depth - 1)));
    keys.push_back(prepare::mortonKey(vx, vy, vz, depth));
  };
  BaselineWalk<decltype(sink)>(level, setup, sink).run();
  return keys;
}

std::vector<std::uint64_t> randomVoxelKeys(int depth, std::size_t count, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::uint32_t> index(0, (1u << depth) - 1);
  std::set<std::uint64_t> keys;
  for (std::size_t i = 0; i < count; ++i) {
    keys.insert(prepare::mortonKey(index(random), index(random), index(random), depth));
  }
  return {keys.begin(), keys.end()};
}

void expectRoundTrip(const std::vector<std::uint64_t>& keys, int depth) {
  const std::vector<std::uint8_t> nodes = prepare::encodeOctree(keys, depth);
  const std::vector<std::uint8_t> leaves(keys.size(), 0);
  const LevelView level{depth, nodes, leaves};
  ASSERT_EQ(validateLevelStream(level, 1).error, ModelError::kNone);
  EXPECT_EQ(decodeWithIdentityCamera(level), keys) << "depth " << depth;
}

TEST(OctreeRoundTrip, SingleVoxelAtEveryCornerOfDepthOneToEight) {
  for (int depth = 1; depth <= 8; ++depth) {
    const std::uint32_t last = (1u << depth) - 1;
    for (int corner = 0; corner < 8; ++corner) {
      expectRoundTrip({prepare::mortonKey(corner & 4 ? last : 0, corner & 2 ? last : 0,
                                          corner & 1 ? last : 0, depth)},
                      depth);
    }
  }
}

TEST(OctreeRoundTrip, FullCubeOfDepthThree) {
  std::vector<std::uint64_t> keys(512);
  for (std::uint64_t i = 0; i < keys.size(); ++i) keys[i] = i;
  expectRoundTrip(keys, 3);
}

TEST(OctreeRoundTrip, RandomVoxelSetsAtDepthsOneToTen) {
  for (int depth = 1; depth <= 10; ++depth) {
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
      expectRoundTrip(randomVoxelKeys(depth, 2000, seed), depth);
    }
  }
}

TEST(OctreeRoundTrip, StreamHasOneBytePerInnerNode) {
  // Two voxels in opposite corners at depth 2: root, two leaf parents.
  const std::vector<std::uint64_t> keys = {prepare::mortonKey(0, 0, 0, 2),
                                           prepare::mortonKey(3, 3, 3, 2)};
  EXPECT_EQ(prepare::encodeOctree(keys, 2), (std::vector<std::uint8_t>{0x81, 0x01, 0x80}));
}

TEST(MortonKey, DecodeInvertsEncodeAndPutsXHighest) {
  EXPECT_EQ(prepare::mortonKey(1, 0, 0, 1), 4u);
  EXPECT_EQ(prepare::mortonKey(0, 1, 0, 1), 2u);
  EXPECT_EQ(prepare::mortonKey(0, 0, 1, 1), 1u);
  EXPECT_EQ(prepare::mortonKey(2, 0, 0, 2), 32u);  // x's high bit leads the first octal digit
  const std::uint32_t big = (1u << 16) - 3;
  EXPECT_EQ(prepare::mortonDecode(prepare::mortonKey(big, 12345, 7, 16), 16),
            (std::array<std::uint32_t, 3>{big, 12345, 7}));
}

}  // namespace
}  // namespace octopoint
