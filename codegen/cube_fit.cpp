#include "codegen/cube_fit.h"

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

}  // namespace octopoint::prepare
