// The reference's own closure (lab/reference_closure.h): a jittered plane with exact holes, and a
// real scan's holes inside the morphological closing of its covered set.
#include "lab/reference_closure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "lab/reference_render.h"

namespace octopoint::tradeoff {
namespace {

constexpr Rgb kBackground{0, 0, 0};
constexpr int kPlaneSide = 200;  // cells per side of the jittered plane
constexpr unsigned kPlaneSeed = 7;
const std::vector<std::pair<int, int>> kPlaneSizes = {{1, 1},     {7, 5},      {176, 208},
                                                      {320, 240}, {1280, 960}, {1920, 1080}};
const std::vector<double> kPlaneZooms = {0.25, 0.5, 1, 2, 4, 8};
// The closing's radius in sample spacings, and the inside's distance from its outline in radii.
constexpr double kClosingSpacings = 0.5;
constexpr int kInsideRadii = 3;

Camera cameraFor(int width, int height, double zoom, Angle yaw) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(std::lround(zoom * Q16::kOneRaw)));
  camera.yaw = yaw;
  return camera;
}

cv::Mat discOfRadius(int radius) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
}

}  // namespace

prepare::Scan jitteredPlane(int side, unsigned seed) {
  prepare::Scan scan;
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float cell = 2.0f / static_cast<float>(side);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const float u = unit(random), v = unit(random);  // in this order: x, then y
      scan.positions.push_back(
          {-1 + (static_cast<float>(x) + u) * cell, -1 + (static_cast<float>(y) + v) * cell, 0.0f});
    }
  }
  scan.positions.push_back({0, 0, 0.001f});
  return scan;
}

PlaneCoverage jitteredPlaneCoverage(const SplatRule& rule) {
  const prepare::Scan scan = jitteredPlane(kPlaneSide, kPlaneSeed);
  const ReferenceSurface surface = buildReferenceSurface(scan, rule);
  const float largest = *std::max_element(surface.splat_radius.begin(), surface.splat_radius.end());
  const double cell = 2.0 / kPlaneSide;
  const prepare::CubeFit fit = prepare::fitCube(scan.positions, "jittered plane");
  PlaneCoverage coverage;
  std::vector<float> radii = surface.splat_radius;
  const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
  std::nth_element(radii.begin(), middle, radii.end());
  coverage.median_radius = *middle / cell;
  for (const auto& [width, height] : kPlaneSizes) {
    for (const double zoom : kPlaneZooms) {
      const Camera camera = cameraFor(width, height, zoom, Angle());
      const ScreenProjection project(fit, camera);
      const auto low = project({-1, -1, 0}), high = project({1, 1, 0});
      // Within 2 cells of the border the random sampling itself thins out; beyond the largest
      // disc outside it nothing may be drawn.
      const double inset = 2 * cell * project.pixelsPerUnit(),
                   reach = largest * project.pixelsPerUnit() + 1;
      cv::Mat covered;
      renderReference(surface, fit, camera, kBackground, &covered);
      const std::int64_t holes_before = coverage.holes;
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          const double px = x + 0.5, py = y + 0.5;
          const bool on = covered.at<std::uint8_t>(y, x) != 0;
          coverage.holes += !on && px > low[0] + inset && px < high[0] - inset &&
                            py > low[1] + inset && py < high[1] - inset;
          coverage.spills += on && (px < low[0] - reach || px > high[0] + reach ||
                                    py < low[1] - reach || py > high[1] + reach);
        }
      }
      if (coverage.holes > holes_before && coverage.first_hole.empty()) {
        char view[64];
        std::snprintf(view, sizeof view, "%dx%d zoom %g", width, height, zoom);
        coverage.first_hole = view;
      }
    }
  }
  return coverage;
}

Closure measureClosure(const ReferenceSurface& surface, const prepare::CubeFit& fit, double spacing,
                       const std::vector<View>& views, Angle yaw, const std::string& pictures) {
  Closure closure;
  for (const View& view : views) {
    const Camera camera = cameraFor(view.width, view.height, view.zoom, yaw);
    cv::Mat covered;
    renderReference(surface, fit, camera, kBackground, &covered);
    const double pixels_per_unit = ScreenProjection(fit, camera).pixelsPerUnit();
    const int radius =
        std::max(1, static_cast<int>(std::lround(kClosingSpacings * spacing * pixels_per_unit)));
    cv::Mat closed, inside;
    cv::morphologyEx(covered, closed, cv::MORPH_CLOSE, discOfRadius(radius));
    cv::erode(closed, inside, discOfRadius(kInsideRadii * radius));
    const cv::Mat empty_in_closing = closed & ~covered;
    const cv::Mat holes_inside = empty_in_closing & inside;
    const std::int64_t holes = cv::countNonZero(holes_inside);
    const std::int64_t on = cv::countNonZero(covered);
    closure.holes += holes;
    closure.outline_holes += cv::countNonZero(empty_in_closing) - holes;
    closure.covered += on;
    const double share = on > 0 ? static_cast<double>(holes) / static_cast<double>(on) : 0.0;
    closure.worst_share = std::max(closure.worst_share, share);
    if (pictures.empty()) continue;
    std::printf("%dx%d zoom %g: closing radius %d px, holes inside %.4f%% of covered\n", view.width,
                view.height, view.zoom, radius, 100.0 * share);
    cv::Mat picture(covered.size(), CV_8UC3, cv::Scalar(0, 0, 0));
    picture.setTo(cv::Scalar(255, 255, 255), covered);
    picture.setTo(cv::Scalar(0, 160, 255), empty_in_closing);
    picture.setTo(cv::Scalar(0, 0, 255), holes_inside);
    char name[96];
    std::snprintf(name, sizeof name, "/%dx%d_zoom%g_holes.png", view.width, view.height, view.zoom);
    if (!cv::imwrite(pictures + name, picture))
      throw std::runtime_error("cannot write " + pictures + name);
  }
  return closure;
}

}  // namespace octopoint::tradeoff
