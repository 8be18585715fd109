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

// The smallest cube edge the preparer records: below 1 nm the picometre count of the format
// (renderer/model_format.h) would round by more than 0.05%.
inline constexpr double kMinCubeEdgeMetres = 1e-9;

// The cube's edge in picometres, as the model format stores it (a u64: up to 18,446 km, far past
// the 2,000 km a scan within kMaxAbsCoordinate metres can span), rounded to nearest. Throws
// PrepareError naming `path` when the edge is below kMinCubeEdgeMetres or above what a u64 holds,
// so no scan is stored with a wrong size.
std::uint64_t cubeEdgePicometres(const CubeFit& fit, double metres_per_scan_unit, const std::string& path);

// The voxel index along one axis at `depth`, in 0..2^depth - 1 (the far face of the cube belongs to
// the last voxel).
std::uint32_t voxelIndex(double coordinate, double origin, double edge, int depth);

}  // namespace octopoint::prepare
