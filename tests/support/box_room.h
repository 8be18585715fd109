#pragma once
// A closed room as an octree level (depth 6, voxels of 1/64 cube edge), for the collision tests:
// a floor two voxels thick, a ceiling, four walls, a wall one voxel thick across half the room
// (with a doorway beside it), a pillar and a low box on the floor two voxels tall. Everything
// occupied is whole voxels, so its faces are exact in Q.24 units. Voxel indices (i, j, k) along
// x, y (down) and z; voxel n spans [n * 2^18 - 2^23, (n + 1) * 2^18 - 2^23] in Q.24 cube edges.

#include <cstdint>
#include <vector>

#include "tests/support/synthetic_levels.h"

namespace octopoint::testing_support {

struct BoxRoom {
  static constexpr int kDepth = 6;
  static constexpr std::int64_t kVoxel = std::int64_t{1} << (24 - kDepth);  // Q.24
  static constexpr int kLow = 4, kHigh = 59;        // the outer walls' voxels along x and z
  static constexpr int kCeiling = 10, kFloor = 50;  // the ceiling's voxel, the floor's first
  static constexpr int kThinWall = 32;              // x voxel of the thin wall, for k <= 40
  static constexpr int kThinWallEnd = 40;
  static constexpr int kBoxLow = 40, kBoxHigh = 47;  // the low box: i and k of 40..47 / 16..23
  static constexpr int kBoxTop = kFloor - 2;         // its top voxel

  // The lowest coordinate (Q.24) of voxel n.
  static constexpr std::int64_t at(int n) { return n * kVoxel - (std::int64_t{1} << 23); }

  static bool occupied(int i, int j, int k) {
    if (i < kLow || i > kHigh || k < kLow || k > kHigh || j < kCeiling || j > kFloor + 1) {
      return false;
    }
    if (j == kCeiling || j >= kFloor) return true;                        // ceiling, floor
    if (i == kLow || i == kHigh || k == kLow || k == kHigh) return true;  // outer walls
    if (i == kThinWall && k <= kThinWallEnd) return true;
    if (i >= 16 && i <= 19 && k >= 44 && k <= 47) return true;  // the pillar
    return i >= kBoxLow && i <= kBoxHigh && k >= 16 && k <= 23 && j >= kBoxTop;
  }

  static SyntheticLevel level() {
    std::vector<std::uint64_t> keys;
    for (int i = 0; i < 64; ++i) {
      for (int j = 0; j < 64; ++j) {
        for (int k = 0; k < 64; ++k) {
          if (occupied(i, j, k)) {
            keys.push_back(mortonKey(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j),
                                     static_cast<std::uint32_t>(k), kDepth));
          }
        }
      }
    }
    return encodeLevel(std::move(keys), kDepth, [](std::uint64_t) { return std::uint8_t{1}; });
  }
};

}  // namespace octopoint::testing_support
