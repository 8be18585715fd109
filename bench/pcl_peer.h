#pragma once
// The peer the renderer is measured against (docs/design.md section 4): how a PCL user draws the
// same voxels today. A flat pcl::PointCloud of the voxel centres is transformed with Eigen
// (pcl::transformPointCloud) and the projected points are z-buffered, in single precision.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/model.h"

namespace octopoint::bench {

class PclPeer {
 public:
  // Takes the voxel centres of `level` (in voxel units, centred on the cube) and their colours.
  PclPeer(const ModelView& model, const LevelView& level, std::int32_t width, std::int32_t height);

  // Draws one frame with the camera's rotation, zoom and pan (orthographic, as octopoint does).
  void render(const Camera& camera);
  std::size_t points() const { return cloud_.size(); }
  std::size_t coveredPixels() const;

 private:
  int depth_;
  std::int32_t width_, height_;
  pcl::PointCloud<pcl::PointXYZRGB> cloud_;
  pcl::PointCloud<pcl::PointXYZRGB> transformed_;  // reused: no allocation after the first frame
  std::vector<float> depth_buffer_;
  std::vector<std::uint32_t> colour_buffer_;
};

}  // namespace octopoint::bench
