#include "lab/reference_render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "lab/reference_rotation.h"

namespace octopoint::tradeoff {
namespace {

using Colour = std::array<double, 3>;  // R, G, B in 0..255

struct ScreenPoint {
  double x, y;  // pixels: pixel (col, row) spans [col, col + 1) x [row, row + 1)
  double z;     // scan units, smaller is nearer
};

// The double precision z-buffer and the image it decides.
class DepthImage {
 public:
  DepthImage(const Camera& camera, Rgb background)
      : width_(camera.width),
        depth_(static_cast<std::size_t>(camera.width) * static_cast<std::size_t>(camera.height),
               std::numeric_limits<double>::infinity()),
        image_(camera.height, camera.width, CV_8UC3,
               cv::Scalar(background.b, background.g, background.r)),
        covered_(cv::Mat::zeros(camera.height, camera.width, CV_8U)) {}

  void plot(int col, int row, double z, const Colour& rgb) {
    double& nearest = depth_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
                             static_cast<std::size_t>(col)];
    if (!(z < nearest)) return;
    nearest = z;
    auto channel = [](double v) {
      return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
    };
    image_.at<cv::Vec3b>(row, col) = cv::Vec3b(channel(rgb[2]), channel(rgb[1]), channel(rgb[0]));
    covered_.at<std::uint8_t>(row, col) = 255;
  }

  cv::Mat image() const { return image_; }
  cv::Mat covered() const { return covered_; }

 private:
  int width_;
  std::vector<double> depth_;
  cv::Mat image_;
  cv::Mat covered_;
};

// The pixels whose centres lie in [low, high] along an axis of `size` pixels, clamped to the
// screen (first > last when there is none).
struct PixelSpan {
  int first, last;
};
PixelSpan centresWithin(double low, double high, int size) {
  return {static_cast<int>(std::clamp(std::ceil(low - 0.5), 0.0, double(size))),
          static_cast<int>(std::clamp(std::floor(high - 0.5), -1.0, double(size - 1)))};
}

// Twice the signed area of (a, b, p): positive when p lies to the left of a->b (y down).
double edge(const ScreenPoint& a, const ScreenPoint& b, double px, double py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

void drawTriangle(const ScreenPoint (&v)[3], const Colour (&c)[3], const Camera& camera,
                  DepthImage& out) {
  const double area = edge(v[0], v[1], v[2].x, v[2].y);
  // Seen edge-on a triangle covers no area, so no pixel centre.
  if (!(std::fabs(area) > 1e-12)) return;
  const double sign = area > 0 ? 1.0 : -1.0;
  const PixelSpan cols = centresWithin(std::min({v[0].x, v[1].x, v[2].x}),
                                       std::max({v[0].x, v[1].x, v[2].x}), camera.width);
  const PixelSpan rows = centresWithin(std::min({v[0].y, v[1].y, v[2].y}),
                                       std::max({v[0].y, v[1].y, v[2].y}), camera.height);
  for (int row = rows.first; row <= rows.last; ++row) {
    const double py = row + 0.5;
    for (int col = cols.first; col <= cols.last; ++col) {
      const double px = col + 0.5;
      // Barycentric weights of the pixel centre; all >= 0 inside or on an edge.
      const double w0 = edge(v[1], v[2], px, py) * sign, w1 = edge(v[2], v[0], px, py) * sign,
                   w2 = edge(v[0], v[1], px, py) * sign;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const double l0 = w0 / std::fabs(area), l1 = w1 / std::fabs(area), l2 = 1.0 - l0 - l1;
      Colour rgb;
      for (std::size_t k = 0; k < 3; ++k) rgb[k] = l0 * c[0][k] + l1 * c[1][k] + l2 * c[2][k];
      out.plot(col, row, l0 * v[0].z + l1 * v[1].z + l2 * v[2].z, rgb);
    }
  }
}

void drawSplat(const ScreenPoint& p, double radius_px, const Colour& rgb, const Camera& camera,
               DepthImage& out) {
  const PixelSpan cols = centresWithin(p.x - radius_px, p.x + radius_px, camera.width);
  const PixelSpan rows = centresWithin(p.y - radius_px, p.y + radius_px, camera.height);
  const double radius_squared = radius_px * radius_px;
  for (int row = rows.first; row <= rows.last; ++row) {
    const double dy = row + 0.5 - p.y;
    for (int col = cols.first; col <= cols.last; ++col) {
      const double dx = col + 0.5 - p.x;
      if (dx * dx + dy * dy <= radius_squared) out.plot(col, row, p.z, rgb);
    }
  }
}

}  // namespace

ScreenProjection::ScreenProjection(const prepare::CubeFit& fit, const Camera& camera)
    : rotation_(referenceRotation(camera.yaw, camera.pitch, camera.roll)),
      centre_{fit.origin[0] + fit.edge / 2, fit.origin[1] + fit.edge / 2,
              fit.origin[2] + fit.edge / 2},
      pixels_per_unit_(camera.zoom.raw() / 65536.0 * std::min(camera.width, camera.height) /
                       fit.edge),
      screen_x_(camera.width / 2.0 + camera.pan_x_px),
      screen_y_(camera.height / 2.0 + camera.pan_y_px) {}

std::array<double, 3> ScreenProjection::operator()(const std::array<float, 3>& position) const {
  double p[3];
  for (std::size_t axis = 0; axis < 3; ++axis) p[axis] = position[axis] - centre_[axis];
  auto row = [&](std::size_t i) {
    return rotation_[i][0] * p[0] + rotation_[i][1] * p[1] + rotation_[i][2] * p[2];
  };
  return {row(0) * pixels_per_unit_ + screen_x_, row(1) * pixels_per_unit_ + screen_y_, row(2)};
}

cv::Mat renderReference(const ReferenceSurface& surface, const prepare::CubeFit& fit,
                        const Camera& camera, Rgb background, cv::Mat* covered) {
  const ScreenProjection project(fit, camera);
  std::vector<ScreenPoint> screen(surface.positions.size());
  for (std::size_t i = 0; i < surface.positions.size(); ++i) {
    const auto [x, y, z] = project(surface.positions[i]);
    screen[i] = {x, y, z};
  }
  auto colour = [&](std::size_t i) -> Colour {
    if (surface.colours.empty()) return {200, 200, 200};
    return {double(surface.colours[i][0]), double(surface.colours[i][1]),
            double(surface.colours[i][2])};
  };

  DepthImage out(camera, background);
  for (const auto& t : surface.triangles) {
    const ScreenPoint v[3] = {screen[t[0]], screen[t[1]], screen[t[2]]};
    const Colour c[3] = {colour(t[0]), colour(t[1]), colour(t[2])};
    drawTriangle(v, c, camera, out);
  }
  for (std::size_t i = 0; i < surface.splat_radius.size(); ++i) {
    drawSplat(screen[i], surface.splat_radius[i] * project.pixelsPerUnit(), colour(i), camera, out);
  }
  *covered = out.covered();
  return out.image();
}

}  // namespace octopoint::tradeoff
