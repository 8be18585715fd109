// PCL as the oracle of our geometry: OctreePointCloud::serializeTree writes one occupancy byte per
// branch node, depth-first, child = (x << 2) | (y << 1) | z, which is our stream's definition.
#include <gtest/gtest.h>
#include <pcl/octree/octree_pointcloud.h>
#include <pcl/point_types.h>

#include <random>
#include <set>

#include "codegen/octree_encoder.h"
#include "codegen/voxelizer.h"

namespace octopoint {
namespace {

std::vector<std::uint8_t> pclStream(const std::vector<std::uint64_t>& keys, int depth) {
  const double edge = static_cast<double>(1 << depth);
  pcl::octree::OctreePointCloud<pcl::PointXYZ> octree(1.0);  // one voxel = one unit
  octree.defineBoundingBox(0.0, 0.0, 0.0, edge, edge, edge);
  EXPECT_EQ(static_cast<int>(octree.getTreeDepth()), depth);
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (std::uint64_t key : keys) {
    const auto v = prepare::mortonDecode(key, depth);
    cloud->push_back(pcl::PointXYZ(static_cast<float>(v[0]) + 0.5f, static_cast<float>(v[1]) + 0.5f,
                                   static_cast<float>(v[2]) + 0.5f));
  }
  octree.setInputCloud(cloud);
  octree.addPointsFromInputCloud();
  std::vector<char> serialized;
  octree.serializeTree(serialized);
  return {serialized.begin(), serialized.end()};
}

TEST(PclOracle, OurStreamEqualsSerializeTreeForRandomVoxelSets) {
  for (int depth = 2; depth <= 9; ++depth) {
    std::mt19937 random(static_cast<std::uint32_t>(depth));
    std::uniform_int_distribution<std::uint32_t> index(0, (1u << depth) - 1);
    std::set<std::uint64_t> unique;
    for (int i = 0; i < 3000; ++i)
      unique.insert(prepare::mortonKey(index(random), index(random), index(random), depth));
    const std::vector<std::uint64_t> keys(unique.begin(), unique.end());
    EXPECT_EQ(prepare::encodeOctree(keys, depth), pclStream(keys, depth)) << "depth " << depth;
  }
}

TEST(PclOracle, OurStreamEqualsSerializeTreeForAVoxelizedSphere) {
  // A structured set (a shell) exercises long runs of full and sparse masks.
  const int depth = 7;
  std::set<std::uint64_t> unique;
  const int n = 1 << depth;
  for (int x = 0; x < n; ++x) {
    for (int y = 0; y < n; ++y) {
      for (int z = 0; z < n; ++z) {
        const int r2 =
            (2 * x - n) * (2 * x - n) + (2 * y - n) * (2 * y - n) + (2 * z - n) * (2 * z - n);
        if (r2 > (n - 8) * (n - 8) && r2 <= n * n) {
          unique.insert(prepare::mortonKey(static_cast<std::uint32_t>(x),
                                           static_cast<std::uint32_t>(y),
                                           static_cast<std::uint32_t>(z), depth));
        }
      }
    }
  }
  const std::vector<std::uint64_t> keys(unique.begin(), unique.end());
  EXPECT_EQ(prepare::encodeOctree(keys, depth), pclStream(keys, depth));
}

}  // namespace
}  // namespace octopoint
