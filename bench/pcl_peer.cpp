#include "bench/pcl_peer.h"

#include <pcl/common/transforms.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/decode_baseline.h"

namespace octopoint::bench {

PclPeer::PclPeer(const ModelView& model, const LevelView& level, std::int32_t width,
                 std::int32_t height)
    : depth_(level.depth),
      width_(width),
      height_(height),
      depth_buffer_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)),
      colour_buffer_(depth_buffer_.size()) {
  // The identity camera on a 2^d square maps voxel i to i + 0.5 pixels: read the voxel centres
  // off the decoder, exactly.
  Camera identity;
  identity.width = identity.height = 1 << level.depth;
  FrameSetup setup;
  // The identity camera on the level's own grid fits any depth up to kMaxViewportSide (2^13) a
  // side; a deeper level (refused) leaves the peer's cloud empty.
  if (buildFrameSetup(identity, level.depth, kDefaultFractionBits, &setup) != CameraError::kNone)
    return;
  const float unit = 1.0f / static_cast<float>(1 << setup.fraction_bits);
  const float half_cube = static_cast<float>(1 << (level.depth - 1));
  auto collect = [&](std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t colour) {
    const Rgb rgb = model.paletteColour(colour);
    pcl::PointXYZRGB point(rgb.r, rgb.g, rgb.b);
    point.x = static_cast<float>(x) * unit - half_cube;
    point.y = static_cast<float>(y) * unit - half_cube;
    point.z = static_cast<float>(z) * unit;
    cloud_.push_back(point);
  };
  BaselineWalk<decltype(collect)>(level, setup, collect).run();
}

void PclPeer::render(const Camera& camera) {
  constexpr float kRadiansPerUnit = 6.28318530718f / 65536.0f;
  const float scale = static_cast<float>(camera.zoom.raw()) / 65536.0f *
                      static_cast<float>(std::min(width_, height_)) /
                      static_cast<float>(1 << depth_);
  Eigen::Affine3f transform = Eigen::Affine3f::Identity();
  transform.translate(
      Eigen::Vector3f(static_cast<float>(width_) / 2 + static_cast<float>(camera.pan_x_px),
                      static_cast<float>(height_) / 2 + static_cast<float>(camera.pan_y_px), 0));
  transform.scale(scale);
  transform.rotate(Eigen::AngleAxisf(static_cast<float>(camera.roll.turns16()) * kRadiansPerUnit,
                                     Eigen::Vector3f::UnitZ()));
  transform.rotate(Eigen::AngleAxisf(static_cast<float>(camera.pitch.turns16()) * kRadiansPerUnit,
                                     Eigen::Vector3f::UnitX()));
  transform.rotate(Eigen::AngleAxisf(static_cast<float>(camera.yaw.turns16()) * kRadiansPerUnit,
                                     Eigen::Vector3f::UnitY()));
  pcl::transformPointCloud(cloud_, transformed_, transform);

  std::fill(depth_buffer_.begin(), depth_buffer_.end(), std::numeric_limits<float>::infinity());
  for (const pcl::PointXYZRGB& p : transformed_) {
    if (!(p.x >= 0.0f && p.y >= 0.0f)) continue;
    const auto x = static_cast<std::int32_t>(p.x);
    const auto y = static_cast<std::int32_t>(p.y);
    if (x >= width_ || y >= height_) continue;
    const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                           static_cast<std::size_t>(x);
    if (p.z < depth_buffer_[at]) {
      depth_buffer_[at] = p.z;
      colour_buffer_[at] = p.rgba;
    }
  }
}

std::size_t PclPeer::coveredPixels() const {
  return static_cast<std::size_t>(std::count_if(depth_buffer_.begin(), depth_buffer_.end(),
                                                [](float z) { return std::isfinite(z); }));
}

}  // namespace octopoint::bench
