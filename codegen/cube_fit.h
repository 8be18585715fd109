#pragma once
// Fitting a scan into the model cube: the axis-aligned bounding box of its points, centred in a
// cube whose edge is the box's longest side. The cube is then cut into 2^depth voxels per axis.

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace octopoint::prepare {

struct CubeFit {
  std::array<double, 3> origin{};  // the cube's minimum corner, in scan units
  double edge = 0;                 // the cube's edge, in scan units
};

// Throws PrepareError naming `path` when the points span no volume along any axis (all points
// identical), since no cube can be fitted then.
CubeFit fitCube(std::span<const std::array<float, 3>> positions, const std::string& path);

// The voxel index along one axis at `depth`, in 0..2^depth - 1 (the far face of the cube belongs to
// the last voxel).
std::uint32_t voxelIndex(double coordinate, double origin, double edge, int depth);

}  // namespace octopoint::prepare
