#include "app/reference_render.h"

#include <cmath>
#include <limits>
#include <vector>

#include "app/reference_rotation.h"

namespace octopoint::tradeoff {

cv::Mat renderReference(const prepare::Scan& scan, const prepare::CubeFit& fit, const Camera& camera,
                        Rgb background, cv::Mat* covered) {
  const Matrix3d r = referenceRotation(camera.yaw, camera.pitch, camera.roll);

  const double pixels_per_unit = camera.zoom.raw() / 65536.0 * std::min(camera.width, camera.height) / fit.edge;
  const double centre[3] = {fit.origin[0] + fit.edge / 2, fit.origin[1] + fit.edge / 2, fit.origin[2] + fit.edge / 2};
  cv::Mat image(camera.height, camera.width, CV_8UC3, cv::Scalar(background.b, background.g, background.r));
  *covered = cv::Mat::zeros(camera.height, camera.width, CV_8U);
  std::vector<double> depth(static_cast<std::size_t>(camera.width) * static_cast<std::size_t>(camera.height),
                            std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    double p[3];
    for (int axis = 0; axis < 3; ++axis) p[axis] = scan.positions[i][static_cast<std::size_t>(axis)] - centre[axis];
    const double x = (r[0][0] * p[0] + r[0][1] * p[1] + r[0][2] * p[2]) * pixels_per_unit + camera.width / 2.0 + camera.pan_x_px;
    const double y = (r[1][0] * p[0] + r[1][1] * p[1] + r[1][2] * p[2]) * pixels_per_unit + camera.height / 2.0 + camera.pan_y_px;
    const double z = r[2][0] * p[0] + r[2][1] * p[1] + r[2][2] * p[2];
    const double px = std::floor(x), py = std::floor(y);
    if (px < 0 || py < 0 || px >= camera.width || py >= camera.height) continue;
    const auto col = static_cast<int>(px), row = static_cast<int>(py);
    double& nearest = depth[static_cast<std::size_t>(row) * static_cast<std::size_t>(camera.width) + static_cast<std::size_t>(col)];
    if (z >= nearest) continue;
    nearest = z;
    const auto& c = scan.colours.empty() ? std::array<std::uint8_t, 3>{200, 200, 200} : scan.colours[i];
    image.at<cv::Vec3b>(row, col) = cv::Vec3b(c[2], c[1], c[0]);
    covered->at<std::uint8_t>(row, col) = 255;
  }
  return image;
}

}  // namespace octopoint::tradeoff
