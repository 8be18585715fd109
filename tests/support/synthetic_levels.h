#pragma once
// Dense synthetic surfaces as octree levels, built in memory without the preparer (so core_tests,
// which also runs on the device, can use them): a flat square and a sphere, voxelized
// conservatively, i.e. every voxel whose cube meets the surface is occupied. Every point of the
// surface thus lies inside an occupied voxel's cube, and its projection inside that voxel's
// projected cube: the exact silhouette of the surface is covered by the voxels' footprints.
//
// Coordinates: the model cube is [-1/2, 1/2]^3 (x right, y down, z away, octopoint/camera.h);
// voxel (i, j, k) of depth d spans [i/2^d - 1/2, (i+1)/2^d - 1/2] along x, and so on.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/fixed.h"
#include "octopoint/model.h"

namespace octopoint::testing_support {

struct SyntheticLevel {
  int depth = 0;
  std::vector<std::uint8_t> nodes, leaves;
  LevelView view() const { return LevelView{depth, nodes, leaves}; }
};

// Morton key of voxel (i, j, k): per level from the root, the child index (x << 2) | (y << 1) | z.
inline std::uint64_t mortonKey(std::uint32_t i, std::uint32_t j, std::uint32_t k, int depth) {
  std::uint64_t key = 0;
  for (int bit = depth - 1; bit >= 0; --bit) {
    key = key << 3 | ((i >> bit & 1u) << 2) | ((j >> bit & 1u) << 1) | (k >> bit & 1u);
  }
  return key;
}

// The depth-first stream of sorted, distinct Morton keys; leaf colours from `colour(key)`.
template <typename Colour>
SyntheticLevel encodeLevel(std::vector<std::uint64_t> keys, int depth, Colour colour) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  SyntheticLevel level;
  level.depth = depth;
  auto emit = [&](auto& self, std::size_t begin, std::size_t end, int tree_level) -> void {
    const int shift = 3 * (depth - 1 - tree_level);
    std::array<std::size_t, 9> bounds{};
    bounds[0] = begin;
    std::uint8_t mask = 0;
    for (unsigned child = 0; child < 8; ++child) {
      std::size_t at = bounds[child];
      while (at < end && ((keys[at] >> shift) & 7u) == child) ++at;
      bounds[child + 1] = at;
      if (at != bounds[child]) mask |= static_cast<std::uint8_t>(1u << child);
    }
    level.nodes.push_back(mask);
    for (unsigned child = 0; child < 8; ++child) {
      if (bounds[child + 1] == bounds[child]) continue;
      if (tree_level + 1 == depth) {
        level.leaves.push_back(colour(keys[bounds[child]]));
      } else {
        self(self, bounds[child], bounds[child + 1], tree_level + 1);
      }
    }
  };
  if (!keys.empty()) emit(emit, 0, keys.size(), 0);
  level.nodes.shrink_to_fit();  // ends at the last byte: ASan sees a read past the stream
  level.leaves.shrink_to_fit();
  return level;
}

// A camera of width x height pixels at `zoom`, turned `yaw` and `pitch` degrees: the views the
// tests of synthetic surfaces draw.
inline Camera viewOf(int width, int height, double zoom, int yaw, int pitch = 0) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(std::lround(zoom * Q16::kOneRaw)));
  camera.yaw = Angle::fromDegrees(yaw);
  camera.pitch = Angle::fromDegrees(pitch);
  return camera;
}

inline std::uint8_t colourOf(std::uint64_t key) {
  return static_cast<std::uint8_t>((key * 2654435761u) >> 24);
}

// The centre of voxel index i at `depth`, in cube units.
inline double voxelCentre(std::uint32_t i, int depth) {
  return (i + 0.5) / std::ldexp(1.0, depth) - 0.5;
}

// A sphere of `radius` (cube units) about the cube's centre: the voxels whose cube meets its
// surface (nearest point of the cube inside the sphere, farthest outside or on it).
inline std::vector<std::uint64_t> sphereKeys(double radius, int depth) {
  const std::uint32_t n = 1u << depth;
  const double half = 0.5 / n;
  std::vector<std::uint64_t> keys;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = 0; j < n; ++j) {
      for (std::uint32_t k = 0; k < n; ++k) {
        double nearest = 0, farthest = 0;
        for (const double c :
             {voxelCentre(i, depth), voxelCentre(j, depth), voxelCentre(k, depth)}) {
          const double a = std::fabs(c);
          nearest += std::max(0.0, a - half) * std::max(0.0, a - half);
          farthest += (a + half) * (a + half);
        }
        if (nearest <= radius * radius && radius * radius <= farthest)
          keys.push_back(mortonKey(i, j, k, depth));
      }
    }
  }
  return keys;
}

inline SyntheticLevel sphereLevel(double radius, int depth) {
  return encodeLevel(sphereKeys(radius, depth), depth, colourOf);
}

// A flat square through the cube's centre: the points a * u + b * v with |a|, |b| <= side / 2,
// u and v orthonormal. Its voxels: those whose cube meets the plane and whose centre's (a, b) lie
// within the square widened by half a voxel diagonal (so every point of the square is in one).
struct Square {
  std::array<double, 3> u, v;
  double side;
};

inline SyntheticLevel squareLevel(const Square& square, int depth) {
  const std::uint32_t n = 1u << depth;
  const double half = 0.5 / n;
  const std::array<double, 3> normal = {square.u[1] * square.v[2] - square.u[2] * square.v[1],
                                        square.u[2] * square.v[0] - square.u[0] * square.v[2],
                                        square.u[0] * square.v[1] - square.u[1] * square.v[0]};
  const double slab = half * (std::fabs(normal[0]) + std::fabs(normal[1]) + std::fabs(normal[2]));
  const double reach = square.side / 2 + half * std::sqrt(3.0);
  std::vector<std::uint64_t> keys;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = 0; j < n; ++j) {
      for (std::uint32_t k = 0; k < n; ++k) {
        const std::array<double, 3> c = {voxelCentre(i, depth), voxelCentre(j, depth),
                                         voxelCentre(k, depth)};
        auto dot = [&](const std::array<double, 3>& w) {
          return c[0] * w[0] + c[1] * w[1] + c[2] * w[2];
        };
        if (std::fabs(dot(normal)) <= slab && std::fabs(dot(square.u)) <= reach &&
            std::fabs(dot(square.v)) <= reach) {
          keys.push_back(mortonKey(i, j, k, depth));
        }
      }
    }
  }
  return encodeLevel(std::move(keys), depth, colourOf);
}

}  // namespace octopoint::testing_support
