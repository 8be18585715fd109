#include "codegen/cube_fit.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>

#include "codegen/prepare_error.h"

namespace octopoint::prepare {

CubeFit fitCube(std::span<const std::array<float, 3>> positions, const std::string& path) {
  Bounds bounds;
  for (const auto& p : positions) bounds.add({p[0], p[1], p[2]});
  return fitCube(bounds, path);
}

CubeFit fitCube(const Bounds& bounds, const std::string& path) {
  CubeFit fit;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    fit.edge = std::max(fit.edge, bounds.high[axis] - bounds.low[axis]);
  }
  if (bounds.count == 0 || !(fit.edge > 0)) {
    throw PrepareError(path + ": all " + std::to_string(bounds.count) +
                       " points are at the same position, so they span no volume to voxelize");
  }
  for (std::size_t axis = 0; axis < 3; ++axis) {
    fit.origin[axis] = (bounds.low[axis] + bounds.high[axis]) / 2 - fit.edge / 2;
  }
  return fit;
}

std::uint64_t cubeEdgePicometres(const CubeFit& fit, double metres_per_scan_unit,
                                 const std::string& path) {
  const double metres = fit.edge * metres_per_scan_unit;
  const double picometres = std::round(metres * 1e12);
  // 2^64 as a double; every double below it converts to u64 exactly.
  constexpr double kTwoTo64 = 18446744073709551616.0;
  if (!(metres >= kMinCubeEdgeMetres) || !(picometres < kTwoTo64)) {
    char edge[32];
    std::snprintf(edge, sizeof edge, "%.3g", metres);
    throw PrepareError(path + ": the scan spans " + edge +
                       " m; the model format records cube edges from 1 nm to 18,446 km");
  }
  return static_cast<std::uint64_t>(picometres);
}

CubePlacement cubePlacement(const CubeFit& fit, bool scan_axes_y_up) {
  std::array<double, 3> corner = fit.origin;
  if (scan_axes_y_up) {
    corner[1] = -(fit.origin[1] + fit.edge);
    corner[2] = -(fit.origin[2] + fit.edge);
  }
  CubePlacement cube;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    // + 0.0 turns a corner of -0 into +0: the same place, one spelling.
    cube.corner_bits[axis] = std::bit_cast<std::uint64_t>(corner[axis] + 0.0);
  }
  cube.edge_bits = std::bit_cast<std::uint64_t>(fit.edge);
  cube.scan_axes = scan_axes_y_up ? format::kScanAxesYUp : format::kScanAxesYDown;
  return cube;
}

}  // namespace octopoint::prepare
