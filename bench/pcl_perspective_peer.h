#pragma once
// The perspective peer (docs/perspective.md, "Against a PCL/Eigen peer"): how a PCL user draws the
// same voxels in perspective today. The voxel centres of a level, in cube edges about the cube's
// centre, sit in an Eigen matrix; each frame moves them into camera space with one Eigen product
// (the camera's rotation, Rz(-roll) Rx(-pitch) Ry(-yaw), about its eye), divides by depth
// (x = W / 2 + f x / z, f = (H / 2) / tan(fov / 2), as renderer/perspective.h defines the
// projection) and z-buffers one pixel a point, in float or double.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "octopoint/model.h"
#include "renderer/perspective.h"

namespace octopoint::bench {

template <typename Scalar>
class PclPerspectivePeer {
 public:
  // Takes the voxel centres of `level` and their colours; frames of width x height.
  PclPerspectivePeer(const ModelView& model, const LevelView& level, std::int32_t width,
                     std::int32_t height);

  // Draws one frame of `camera` (its size the peer's): nothing nearer than its near plane.
  void render(const PerspectiveCamera& camera);
  std::size_t points() const { return static_cast<std::size_t>(cloud_.cols()); }
  std::size_t coveredPixels() const;

 private:
  using Points = Eigen::Matrix<Scalar, 3, Eigen::Dynamic>;
  std::int32_t width_, height_;
  Points cloud_;   // cube edges about the cube's centre
  Points camera_;  // reused: no allocation after the first frame
  std::vector<std::uint32_t> colours_;
  std::vector<Scalar> depth_buffer_;
  std::vector<std::uint32_t> colour_buffer_;
};

extern template class PclPerspectivePeer<float>;
extern template class PclPerspectivePeer<double>;

}  // namespace octopoint::bench
