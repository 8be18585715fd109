#pragma once
// Fitting a scan into the model cube: the axis-aligned bounding box of its points, centred in a
// cube whose edge is the box's longest side. The cube is then cut into 2^depth voxels per axis.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>

#include "octopoint/model.h"

namespace octopoint::prepare {

struct CubeFit {
  std::array<double, 3> origin{};  // the cube's minimum corner, in scan units
  double edge = 0;                 // the cube's edge, in scan units
};

// The bounding box of points seen one at a time (the streamed preparer's first pass).
struct Bounds {
  std::array<double, 3> low{kEmpty, kEmpty, kEmpty};
  std::array<double, 3> high{-kEmpty, -kEmpty, -kEmpty};
  std::uint64_t count = 0;

  void add(const std::array<double, 3>& p) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      low[axis] = std::min(low[axis], p[axis]);
      high[axis] = std::max(high[axis], p[axis]);
    }
    ++count;
  }
  void merge(const Bounds& other) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      low[axis] = std::min(low[axis], other.low[axis]);
      high[axis] = std::max(high[axis], other.high[axis]);
    }
    count += other.count;
  }

 private:
  static constexpr double kEmpty = std::numeric_limits<double>::infinity();
};

// Throws PrepareError naming `path` when the points span no volume along any axis (all points
// identical), since no cube can be fitted then.
CubeFit fitCube(std::span<const std::array<float, 3>> positions, const std::string& path);
CubeFit fitCube(const Bounds& bounds, const std::string& path);

// The smallest cube edge the preparer records: below 1 nm the picometre count of the format
// (octopoint/model.h) would round by more than 0.05%.
inline constexpr double kMinCubeEdgeMetres = 1e-9;

// The cube's edge in picometres, as the model format stores it (a u64: up to 18,446 km, far past
// the 2,000 km a scan within kMaxAbsCoordinate metres can span), rounded to nearest. Throws
// PrepareError naming `path` when the edge is below kMinCubeEdgeMetres or above what a u64 holds,
// so no scan is stored with a wrong size.
std::uint64_t cubeEdgePicometres(const CubeFit& fit, double metres_per_scan_unit,
                                 const std::string& path);

// The cube's placement as the model format records it (octopoint/model.h): `fit` is in the
// model's axes; with `scan_axes_y_up` the scan's are those turned back (180 degrees about x), so
// the corner recorded, the lowest in the scan's own axes, is (x0, -(y0 + edge), -(z0 + edge)).
CubePlacement cubePlacement(const CubeFit& fit, bool scan_axes_y_up);

// The voxel index along one axis at `depth`, in 0..2^depth - 1 (the far face of the cube belongs to
// the last voxel). Every path of the preparer computes keys with exactly this expression; inline,
// and with `cells` = 2^depth computed once, because the streamed preparer calls it three times per
// point (ldexp is exact, so both forms give the same index).
// The index is clamp(floor(scaled), 0, cells - 1); written with comparisons and a truncation, which
// is the floor of a non-negative number, because x86-64's baseline has no floor instruction.
inline std::uint32_t voxelIndexIn(double coordinate, double origin, double edge, double cells) {
  const double scaled = (coordinate - origin) / edge * cells;
  if (!(scaled < cells)) return static_cast<std::uint32_t>(cells) - 1;
  if (!(scaled >= 0)) return 0;
  return static_cast<std::uint32_t>(scaled);
}
inline std::uint32_t voxelIndex(double coordinate, double origin, double edge, int depth) {
  return voxelIndexIn(coordinate, origin, edge, std::ldexp(1.0, depth));
}

}  // namespace octopoint::prepare
