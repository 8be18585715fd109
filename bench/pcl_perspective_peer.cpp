#include "bench/pcl_perspective_peer.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace octopoint::bench {
namespace {

// Every leaf centre of `level` in cube edges about the cube's centre, in stream order.
void collectCentres(const std::uint8_t*& node, int level, int depth, double x, double y, double z,
                    std::vector<std::array<double, 3>>& centres) {
  if (level == depth) {
    centres.push_back({x, y, z});
    return;
  }
  const std::uint8_t mask = *node++;
  const double step = std::ldexp(1.0, -(level + 2));  // a child lies a quarter of its parent's edge
  for (unsigned k = 0; k < 8; ++k) {
    if (!(mask & (1u << k))) continue;
    collectCentres(node, level + 1, depth, x + ((k & 4) ? step : -step),
                   y + ((k & 2) ? step : -step), z + ((k & 1) ? step : -step), centres);
  }
}

double radians(Angle angle) {
  return static_cast<double>(angle.turns16()) * 2 * 3.14159265358979323846 / Angle::kUnitsPerTurn;
}

}  // namespace

template <typename Scalar>
PclPerspectivePeer<Scalar>::PclPerspectivePeer(const ModelView& model, const LevelView& level,
                                               std::int32_t width, std::int32_t height)
    : width_(width),
      height_(height),
      depth_buffer_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)),
      colour_buffer_(depth_buffer_.size()) {
  std::vector<std::array<double, 3>> centres;
  const std::uint8_t* node = level.nodes.data();
  collectCentres(node, 0, level.depth, 0, 0, 0, centres);
  cloud_.resize(3, static_cast<Eigen::Index>(centres.size()));
  camera_.resize(3, cloud_.cols());
  colours_.resize(centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      cloud_(axis, static_cast<Eigen::Index>(i)) =
          static_cast<Scalar>(centres[i][static_cast<std::size_t>(axis)]);
    }
    const Rgb rgb = model.paletteColour(level.leaves[i]);
    colours_[i] = (std::uint32_t{rgb.r} << 16) | (std::uint32_t{rgb.g} << 8) | rgb.b;
  }
}

template <typename Scalar>
void PclPerspectivePeer<Scalar>::render(const PerspectiveCamera& camera) {
  using Vector = Eigen::Matrix<Scalar, 3, 1>;
  using AngleAxis = Eigen::AngleAxis<Scalar>;
  const Eigen::Matrix<Scalar, 3, 3> rotation =
      (AngleAxis(static_cast<Scalar>(-radians(camera.roll)), Vector::UnitZ()) *
       AngleAxis(static_cast<Scalar>(-radians(camera.pitch)), Vector::UnitX()) *
       AngleAxis(static_cast<Scalar>(-radians(camera.yaw)), Vector::UnitY()))
          .toRotationMatrix();
  const double unit = static_cast<double>(kPerspectiveUnit);
  const Vector eye(static_cast<Scalar>(static_cast<double>(camera.eye.x) / unit),
                   static_cast<Scalar>(static_cast<double>(camera.eye.y) / unit),
                   static_cast<Scalar>(static_cast<double>(camera.eye.z) / unit));
  camera_.noalias() = rotation * (cloud_.colwise() - eye);

  const auto f =
      static_cast<Scalar>(static_cast<double>(height_) / 2 / std::tan(radians(camera.fov) / 2));
  const auto near = static_cast<Scalar>(static_cast<double>(camera.near) / unit);
  const auto centre_x = static_cast<Scalar>(width_) / 2,
             centre_y = static_cast<Scalar>(height_) / 2;
  std::fill(depth_buffer_.begin(), depth_buffer_.end(), std::numeric_limits<Scalar>::infinity());
  for (Eigen::Index i = 0; i < camera_.cols(); ++i) {
    const Scalar z = camera_(2, i);
    if (!(z >= near)) continue;
    const Scalar sx = centre_x + f * camera_(0, i) / z;
    const Scalar sy = centre_y + f * camera_(1, i) / z;
    if (!(sx >= 0 && sy >= 0 && sx < static_cast<Scalar>(width_) &&
          sy < static_cast<Scalar>(height_))) {
      continue;
    }
    const std::size_t at =
        static_cast<std::size_t>(static_cast<std::int32_t>(sy)) * static_cast<std::size_t>(width_) +
        static_cast<std::size_t>(static_cast<std::int32_t>(sx));
    if (z < depth_buffer_[at]) {
      depth_buffer_[at] = z;
      colour_buffer_[at] = colours_[static_cast<std::size_t>(i)];
    }
  }
}

template <typename Scalar>
std::size_t PclPerspectivePeer<Scalar>::coveredPixels() const {
  return static_cast<std::size_t>(std::count_if(depth_buffer_.begin(), depth_buffer_.end(),
                                                [](Scalar z) { return std::isfinite(z); }));
}

template class PclPerspectivePeer<float>;
template class PclPerspectivePeer<double>;

}  // namespace octopoint::bench
