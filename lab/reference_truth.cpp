// Synthetic scans of a square with a known outline, and the pixel-by-pixel match of a drawing with
// that truth (lab/reference_truth.h).
#include "lab/reference_truth.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "lab/reference_render.h"
#include "lab/reference_surface.h"

namespace octopoint::tradeoff {
namespace {

// A line scanner samples more finely along its lines than across them (b = a / kLineRatio); each
// return is off its nominal place by up to kAlongJitter x b along the line and kAcrossJitter x a
// across it.
constexpr double kLineRatio = 1.5;
constexpr double kAlongJitter = 0.15;
constexpr double kAcrossJitter = 0.05;
// Stray returns lie this many nominal steps (cell or b) outside the square's edge.
constexpr double kStrayNearest = 0.5, kStrayFarthest = 3.0;
// The square is turned by this much in its plane, so that its edges cross the voxel grid at a
// slant, as a real object's outline does, instead of lying on the faces of the fitted cube.
constexpr double kTurnDegrees = 20;

double median(std::vector<float> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Twice the signed area of (a, b, p).
double edge(const std::array<double, 3>& a, const std::array<double, 3>& b, double px, double py) {
  return (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]);
}

}  // namespace

TruthScan squareScan(Sampling sampling, int cells, int strays, unsigned seed) {
  TruthScan scan;
  const double turn = kTurnDegrees * 3.14159265358979323846 / 180;
  // (u, v) in the square's own axes, turned into the model's (x, y).
  const auto at = [&](double u, double v) -> std::array<float, 3> {
    return {static_cast<float>(u * std::cos(turn) - v * std::sin(turn)),
            static_cast<float>(u * std::sin(turn) + v * std::cos(turn)), 0.0f};
  };
  scan.corners = {at(-1, -1), at(1, -1), at(1, 1), at(-1, 1)};
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto& positions = scan.points.positions;
  const double step = 2.0 / cells;  // the cell, or the line spacing a
  double nominal = step;            // the finest nominal step: cell, or b along a line
  if (sampling == Sampling::kJittered) {
    for (int y = 0; y < cells; ++y) {
      for (int x = 0; x < cells; ++x) {
        const double u = unit(random), v = unit(random);
        positions.push_back(at(-1 + (x + u) * step, -1 + (y + v) * step));
      }
    }
  } else {
    const double along = step / kLineRatio;
    nominal = along;
    // The first line falls anywhere within a line spacing of the edge, as the object's edge falls
    // anywhere between two of the scanner's lines; so does the first return along each line.
    for (double line = -1 + unit(random) * step; line < 1; line += step) {
      for (double x = -1 + unit(random) * along; x < 1; x += along) {
        const double px = x + (2 * unit(random) - 1) * kAlongJitter * along;
        const double py = line + (2 * unit(random) - 1) * kAcrossJitter * step;
        if (std::fabs(px) > 1 || std::fabs(py) > 1) continue;  // a return comes from the surface
        positions.push_back(at(px, py));
      }
    }
  }
  scan.spacing = median(neighbourDistances(positions, 1));
  for (int i = 0; i < strays; ++i) {
    const double offset =
        1 + (kStrayNearest + (kStrayFarthest - kStrayNearest) * unit(random)) * nominal;
    const double along = 2 * unit(random) - 1;
    const int side = static_cast<int>(unit(random) * 4) % 4;
    const double x = side == 0 ? -offset : side == 1 ? offset : along;
    const double y = side == 2 ? -offset : side == 3 ? offset : along;
    positions.push_back(at(x, y));
  }
  positions.push_back({0, 0, 0.001f});
  return scan;
}

TruthScan depthCameraScan(int across, double distance, double tilt_degrees, unsigned seed) {
  TruthScan scan;
  constexpr double kPi = 3.14159265358979323846;
  const double turn = kTurnDegrees * kPi / 180, tilt = tilt_degrees * kPi / 180;
  // The square's own axes a, b (unit vectors; turned in its plane, then tilted about x) and its
  // centre c; its points are c + u a + v b for u, v in [-1, 1].
  const double a[3] = {std::cos(turn), std::sin(turn) * std::cos(tilt),
                       std::sin(turn) * std::sin(tilt)};
  const double b[3] = {-std::sin(turn), std::cos(turn) * std::cos(tilt),
                       std::cos(turn) * std::sin(tilt)};
  const double c[3] = {0, 0, distance};
  const double normal[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                            a[0] * b[1] - a[1] * b[0]};
  const auto point = [&](double u, double v) -> std::array<double, 3> {
    return {c[0] + u * a[0] + v * b[0], c[1] + u * a[1] + v * b[1], c[2] + u * a[2] + v * b[2]};
  };
  for (std::size_t i = 0; i < 4; ++i) {
    const double u = i == 0 || i == 3 ? -1 : 1, v = i < 2 ? -1 : 1;
    const auto p = point(u, v);
    scan.corners[i] = {static_cast<float>(p[0]), static_cast<float>(p[1]),
                       static_cast<float>(p[2])};
  }
  // Pixel (col, row)'s ray is ((col - cx) / f, (row - cy) / f, 1): `across` steps over the side (2)
  // at the centre's distance.
  const double focal = across * distance / 2;
  double low[2] = {1e300, 1e300}, high[2] = {-1e300, -1e300};
  for (const auto& corner : scan.corners) {
    for (std::size_t k = 0; k < 2; ++k) {
      const double image = focal * corner[k] / corner[2];
      low[k] = std::min(low[k], image), high[k] = std::max(high[k], image);
    }
  }
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr int kMargin = 3;  // grid steps of misses around the square's image
  const double cx = kMargin - std::floor(low[0]) + unit(random);
  const double cy = kMargin - std::floor(low[1]) + unit(random);
  const int width = static_cast<int>(std::ceil(high[0] + cx)) + kMargin;
  const int height = static_cast<int>(std::ceil(high[1] + cy)) + kMargin;
  prepare::Scan& points = scan.points;
  points.organized = true;
  points.grid_width = static_cast<std::uint32_t>(width);
  points.grid_height = static_cast<std::uint32_t>(height);
  points.points_in_file = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  const double plane = normal[0] * c[0] + normal[1] * c[1] + normal[2] * c[2];
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const double ray[3] = {(col - cx) / focal, (row - cy) / focal, 1};
      const double along = plane / (normal[0] * ray[0] + normal[1] * ray[1] + normal[2] * ray[2]);
      double hit[3], local[2] = {0, 0};
      for (std::size_t k = 0; k < 3; ++k) hit[k] = along * ray[k];
      for (std::size_t k = 0; k < 3; ++k) {
        local[0] += (hit[k] - c[k]) * a[k];
        local[1] += (hit[k] - c[k]) * b[k];
      }
      if (!(along > 0) || std::fabs(local[0]) > 1 || std::fabs(local[1]) > 1) {
        ++points.dropped_non_finite;  // the ray misses: NaN in a depth image
        continue;
      }
      points.positions.push_back(
          {static_cast<float>(hit[0]), static_cast<float>(hit[1]), static_cast<float>(hit[2])});
      points.grid_index.push_back(static_cast<std::uint32_t>(row * width + col));
    }
  }
  scan.spacing = median(neighbourDistances(points.positions, 1));
  return scan;
}

cv::Mat truthMask(const TruthScan& scan, const prepare::CubeFit& fit, const Camera& camera) {
  const ScreenProjection project(fit, camera);
  std::array<std::array<double, 3>, 4> corner;
  for (std::size_t i = 0; i < 4; ++i) corner[i] = project(scan.corners[i]);
  // Orientation of the projected outline, so that "inside" is the same side of every edge.
  const double sign = edge(corner[0], corner[1], corner[2][0], corner[2][1]) > 0 ? 1.0 : -1.0;
  cv::Mat mask = cv::Mat::zeros(camera.height, camera.width, CV_8U);
  for (int row = 0; row < camera.height; ++row) {
    for (int col = 0; col < camera.width; ++col) {
      const double px = col + 0.5, py = row + 0.5;
      bool inside = true;
      for (std::size_t i = 0; i < 4 && inside; ++i)
        inside = sign * edge(corner[i], corner[(i + 1) % 4], px, py) >= 0;
      if (inside) mask.at<std::uint8_t>(row, col) = 255;
    }
  }
  return mask;
}

void TruthMatch::add(const TruthMatch& other) {
  truth += other.truth;
  spill += other.spill;
  holes += other.holes;
  inner_holes += other.inner_holes;
  outline += other.outline;
}

namespace {
double shareOf(std::int64_t part, std::int64_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}
}  // namespace

double TruthMatch::spillShare() const { return shareOf(spill, truth); }
double TruthMatch::holeShare() const { return shareOf(holes, truth); }
double TruthMatch::innerHoleShare() const { return shareOf(inner_holes, truth); }
double TruthMatch::meanReachPx() const { return shareOf(spill, outline); }
double TruthMatch::meanOffsetPx() const { return shareOf(spill - holes, outline); }

TruthMatch matchTruth(const cv::Mat& truth, const cv::Mat& covered, int inset) {
  // The truth goes on past the frame's border as it reaches it: the border is no outline.
  cv::Mat eroded, inner;
  cv::erode(truth, eroded, cv::getStructuringElement(cv::MORPH_CROSS, {3, 3}), {-1, -1}, 1,
            cv::BORDER_REPLICATE);
  cv::erode(truth, inner, cv::getStructuringElement(cv::MORPH_RECT, {2 * inset + 1, 2 * inset + 1}),
            {-1, -1}, 1, cv::BORDER_REPLICATE);
  TruthMatch match;
  for (int row = 0; row < truth.rows; ++row) {
    const std::uint8_t* t = truth.ptr<std::uint8_t>(row);
    const std::uint8_t* c = covered.ptr<std::uint8_t>(row);
    const std::uint8_t* e = eroded.ptr<std::uint8_t>(row);
    const std::uint8_t* n = inner.ptr<std::uint8_t>(row);
    for (int col = 0; col < truth.cols; ++col) {
      const bool in = t[col] != 0, on = c[col] != 0;
      match.truth += in;
      match.spill += on && !in;
      match.holes += in && !on;
      match.inner_holes += n[col] != 0 && !on;
      match.outline += in && e[col] == 0;
    }
  }
  return match;
}

TruthReach reachOverViews(const TruthScan& scan, const ReferenceSurface& surface) {
  static const std::pair<int, int> kSizes[] = {{1, 1},     {7, 5},      {176, 208},
                                               {320, 240}, {1280, 960}, {1920, 1080}};
  static const double kZooms[] = {0.25, 0.5, 1, 2, 4, 8};
  const prepare::CubeFit fit = prepare::fitCube(scan.points.positions, "square");
  TruthReach reach;
  TruthMatch all;
  double outline_spacings = 0;
  for (const int yaw : {0, 30}) {
    for (const auto& [width, height] : kSizes) {
      for (const double zoom : kZooms) {
        Camera camera;
        camera.width = width;
        camera.height = height;
        camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(std::lround(zoom * Q16::kOneRaw)));
        camera.yaw = Angle::fromDegrees(yaw);
        const double spacing_px = scan.spacing * ScreenProjection(fit, camera).pixelsPerUnit();
        cv::Mat covered;
        renderReference(surface, fit, camera, Rgb{0, 0, 0}, &covered);
        const TruthMatch match = matchTruth(truthMask(scan, fit, camera), covered,
                                            static_cast<int>(std::ceil(2 * spacing_px)));
        all.add(match);
        outline_spacings += static_cast<double>(match.outline) * spacing_px;
        if (match.inner_holes > 0 && reach.first_hole.empty()) {
          reach.first_hole = std::to_string(width) + "x" + std::to_string(height) + " zoom " +
                             std::to_string(zoom) + " yaw " + std::to_string(yaw);
        }
      }
    }
  }
  reach.spacings = static_cast<double>(all.spill) / outline_spacings;
  reach.signed_spacings = static_cast<double>(all.spill - all.holes) / outline_spacings;
  reach.inner_holes = all.inner_holes;
  return reach;
}

}  // namespace octopoint::tradeoff
