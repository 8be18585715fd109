// The surface reference (app/reference_surface.h, app/reference_render.h): dense at every size and
// zoom, faithful at the edges, never bridging a jump in depth. Synthetic scans with exact answers.
#include "app/reference_render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "app/reference_surface.h"
#include "codegen/cube_fit.h"

namespace octopoint::tradeoff {
namespace {

using prepare::Scan;

constexpr Rgb kBackground{236, 236, 240};
const std::vector<std::pair<int, int>> kSizes = {{1, 1},     {7, 5},      {176, 208},
                                                 {320, 240}, {1280, 960}, {1920, 1080}};
const std::vector<double> kZooms = {0.25, 0.5, 1, 2, 4, 8};

Camera cameraFor(int width, int height, double zoom, int yaw_degrees = 0) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(std::lround(zoom * Q16::kOneRaw)));
  camera.yaw = Angle::fromDegrees(yaw_degrees);
  return camera;
}

// A depth camera's grid of `columns` x `rows` seen from the origin (focal length `focal` in grid
// steps, principal point (cx, cy)); `depth(column, row)` is each point's z. Colour: red grows
// with the column, green with the row.
template <typename Depth>
Scan depthImage(int columns, int rows, double focal, double cx, double cy, Depth depth) {
  Scan scan;
  scan.organized = true;
  scan.grid_width = static_cast<std::uint32_t>(columns);
  scan.grid_height = static_cast<std::uint32_t>(rows);
  scan.shading = prepare::ScanShading::kColour;
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < columns; ++col) {
      const double z = depth(col, row);
      scan.positions.push_back({static_cast<float>((col - cx) / focal * z),
                                static_cast<float>((row - cy) / focal * z), static_cast<float>(z)});
      scan.colours.push_back({static_cast<std::uint8_t>(col * 255 / (columns - 1)),
                              static_cast<std::uint8_t>(row * 255 / (rows - 1)), 128});
      scan.grid_index.push_back(static_cast<std::uint32_t>(row * columns + col));
    }
  }
  return scan;
}

// Whether the pixel centre (px, py) lies inside the convex polygon `corners` (in order) by more
// than `margin` pixels (margin > 0), or outside it by more than -margin (margin < 0).
bool insideBy(const std::vector<std::array<double, 3>>& corners, double px, double py,
              double margin) {
  double orientation = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % corners.size()];
    orientation += a[0] * b[1] - b[0] * a[1];
  }
  double least = 1e300;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % corners.size()];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    const double signed_distance =
        ((b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])) / length;
    least = std::min(least, orientation > 0 ? signed_distance : -signed_distance);
  }
  return margin > 0 ? least > margin : least < margin;
}

TEST(ReferenceRender, OrganizedPlaneCoversExactlyItsOutlineAtEverySizeAndZoom) {
  const int columns = 160, rows = 120;
  const Scan plane = depthImage(columns, rows, 150.0, 79.5, 59.5, [](int, int) { return 1.0; });
  const ReferenceSurface surface = buildReferenceSurface(plane);
  ASSERT_EQ(surface.triangles.size(), 2u * (columns - 1) * (rows - 1));
  const prepare::CubeFit fit = prepare::fitCube(plane.positions, "plane");
  const std::size_t c = columns, r = rows;
  const std::array<std::size_t, 4> corner_index = {0, c - 1, c * r - 1, c * (r - 1)};
  for (int yaw : {0, 30}) {
    for (const auto& [width, height] : kSizes) {
      for (double zoom : kZooms) {
        const Camera camera = cameraFor(width, height, zoom, yaw);
        const ScreenProjection project(fit, camera);
        std::vector<std::array<double, 3>> corners;
        for (std::size_t i : corner_index) corners.push_back(project(plane.positions[i]));
        cv::Mat covered;
        renderReference(surface, fit, camera, kBackground, &covered);
        int holes = 0, spills = 0;
        for (int y = 0; y < height; ++y) {
          for (int x = 0; x < width; ++x) {
            const bool on = covered.at<std::uint8_t>(y, x) != 0;
            holes += !on && insideBy(corners, x + 0.5, y + 0.5, 1e-6);
            spills += on && insideBy(corners, x + 0.5, y + 0.5, -1e-6);
          }
        }
        EXPECT_EQ(holes, 0) << width << "x" << height << " zoom " << zoom << " yaw " << yaw;
        EXPECT_EQ(spills, 0) << width << "x" << height << " zoom " << zoom << " yaw " << yaw;
      }
    }
  }
}

TEST(ReferenceRender, ColourIsInterpolatedAcrossTheSurface) {
  const int columns = 64, rows = 48;
  const Scan plane = depthImage(columns, rows, 60.0, 31.5, 23.5, [](int, int) { return 1.0; });
  const ReferenceSurface surface = buildReferenceSurface(plane);
  const prepare::CubeFit fit = prepare::fitCube(plane.positions, "plane");
  const Camera camera = cameraFor(640, 480, 1);
  const ScreenProjection project(fit, camera);
  cv::Mat covered;
  const cv::Mat image = renderReference(surface, fit, camera, kBackground, &covered);
  const auto left = project(plane.positions[0]), right = project(plane.positions[columns - 1]);
  // Red runs linearly from 0 at the first column to 255 at the last.
  for (int x = static_cast<int>(left[0]) + 1; x < static_cast<int>(right[0]) - 1; x += 7) {
    const double expected = 255.0 * (x + 0.5 - left[0]) / (right[0] - left[0]);
    const cv::Vec3b bgr = image.at<cv::Vec3b>(240, x);
    EXPECT_NEAR(bgr[2], expected, 2.0)
        << "x " << x;  // integer colours of the grid: within 1 + rounding
    EXPECT_EQ(bgr[0], 128);
  }
}

// A near half (depth 1) and a far half (depth 2) side by side in one depth image: the sensor sees
// past the near half's edge, and no surface joins the two.
TEST(ReferenceRender, DepthJumpInTheGridIsNotBridged) {
  const int columns = 120, rows = 90;
  const double focal = 100, cx = 30, cy = 44.5;
  const Scan scan = depthImage(columns, rows, focal, cx, cy,
                               [&](int col, int) { return col < columns / 2 ? 1.0 : 2.0; });
  const ReferenceSurface surface = buildReferenceSurface(scan);
  for (const auto& t : surface.triangles) {
    const bool near0 = scan.positions[t[0]][2] < 1.5, near1 = scan.positions[t[1]][2] < 1.5,
               near2 = scan.positions[t[2]][2] < 1.5;
    EXPECT_TRUE(near0 == near1 && near1 == near2) << "a triangle joins the near and the far half";
  }
  // Drawn from the front: between the near half's right edge and the far half's left edge lies
  // background, and both halves are there.
  const prepare::CubeFit fit = prepare::fitCube(scan.positions, "step");
  const Camera camera = cameraFor(640, 480, 1);
  const ScreenProjection project(fit, camera);
  cv::Mat covered;
  renderReference(surface, fit, camera, kBackground, &covered);
  const double near_right = project(scan.positions[columns / 2 - 1])[0];
  const double far_left = project(scan.positions[columns / 2])[0];
  const double middle_row =
      project(scan.positions[static_cast<std::size_t>(rows / 2 * columns)])[1];
  ASSERT_GT(far_left - near_right, 20);
  const int row = static_cast<int>(middle_row);
  for (int x = static_cast<int>(near_right) + 2; x < static_cast<int>(far_left) - 1; ++x) {
    EXPECT_EQ(covered.at<std::uint8_t>(row, x), 0) << "bridged at x " << x;
  }
  EXPECT_NE(covered.at<std::uint8_t>(row, static_cast<int>(near_right) - 3), 0);
  EXPECT_NE(covered.at<std::uint8_t>(row, static_cast<int>(far_left) + 3), 0);
}

// A step of six grid steps (a depth camera's quantized depth on a surface seen at a grazing angle)
// is surface: it stays joined, although it lies within 12.5 degrees of the line of sight (PCL's
// default shadow test would cut it). Ten grid steps, past kMaxEdgeGridSteps, is a jump.
TEST(ReferenceRender, DepthStepUpToEightGridStepsStaysJoined) {
  const int columns = 120, rows = 90;
  const double focal = 100;
  for (double steps : {6.0, 10.0}) {
    const Scan scan = depthImage(columns, rows, focal, 59.5, 44.5, [&](int col, int) {
      return col < columns / 2 ? 1.0 : 1.0 + steps / focal;
    });
    const ReferenceSurface surface = buildReferenceSurface(scan);
    const std::size_t full = 2u * (columns - 1) * (rows - 1);
    if (steps < kMaxEdgeGridSteps)
      EXPECT_EQ(surface.triangles.size(), full);
    else
      EXPECT_EQ(surface.triangles.size(), full - 2u * (rows - 1));  // the quads across the step go
  }
}

// Missing points (NaN in the file) leave their triangles out, nothing else.
TEST(ReferenceRender, MissingGridPointsDropOnlyTheirTriangles) {
  Scan scan = depthImage(10, 8, 10.0, 4.5, 3.5, [](int, int) { return 1.0; });
  // Take out the point at column 4, row 3 (an inner point: six triangles touch it, or fewer with
  // the adaptive cut; at least one quad's worth of area goes).
  const std::size_t gone = 3 * 10 + 4;
  scan.positions.erase(scan.positions.begin() + static_cast<std::ptrdiff_t>(gone));
  scan.colours.erase(scan.colours.begin() + static_cast<std::ptrdiff_t>(gone));
  scan.grid_index.erase(scan.grid_index.begin() + static_cast<std::ptrdiff_t>(gone));
  const ReferenceSurface surface = buildReferenceSurface(scan);
  const std::size_t full = 2u * 9 * 7;
  EXPECT_LT(surface.triangles.size(), full);
  EXPECT_GE(surface.triangles.size(), full - 6);
  for (const auto& t : surface.triangles) {
    for (std::uint32_t v : t) EXPECT_LT(v, scan.positions.size());
  }
}

// An evenly sampled square (an unorganized scan: one point anywhere in each cell of a 200 x 200
// grid, as a scanner's jittered samples): the splats cover the square, away from its ragged
// border, at every size and zoom, and spill no further than a splat.
TEST(ReferenceRender, UnorganizedSplatsCoverADensePlane) {
  Scan scan;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const int side = 200, count = side * side;
  const float cell = 2.0f / side;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      scan.positions.push_back(
          {-1 + (x + unit(random)) * cell, -1 + (y + unit(random)) * cell, 0.0f});
  scan.positions.push_back({0, 0, 0.001f});  // the cube needs some depth: one point off the plane
  const ReferenceSurface surface = buildReferenceSurface(scan);
  ASSERT_EQ(surface.splat_radius.size(), scan.positions.size());
  ASSERT_TRUE(surface.triangles.empty());
  const float largest = *std::max_element(surface.splat_radius.begin(), surface.splat_radius.end());
  const double spacing = 2.0 / std::sqrt(double(count));  // mean spacing of the points
  const prepare::CubeFit fit = prepare::fitCube(scan.positions, "random plane");
  for (const auto& [width, height] : kSizes) {
    for (double zoom : kZooms) {
      const Camera camera = cameraFor(width, height, zoom);
      const ScreenProjection project(fit, camera);
      const auto low = project({-1, -1, 0}), high = project({1, 1, 0});
      // Within 2 spacings of the border the random sampling itself thins out; beyond the largest
      // splat outside it nothing may be drawn.
      const double inset = 2 * spacing * project.pixelsPerUnit(),
                   reach = largest * project.pixelsPerUnit() + 1;
      cv::Mat covered;
      renderReference(surface, fit, camera, kBackground, &covered);
      int holes = 0, spills = 0;
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          const double px = x + 0.5, py = y + 0.5;
          const bool on = covered.at<std::uint8_t>(y, x) != 0;
          holes += !on && px > low[0] + inset && px < high[0] - inset && py > low[1] + inset &&
                   py < high[1] - inset;
          spills += on && (px < low[0] - reach || px > high[0] + reach || py < low[1] - reach ||
                           py > high[1] + reach);
        }
      }
      EXPECT_EQ(holes, 0) << width << "x" << height << " zoom " << zoom;
      EXPECT_EQ(spills, 0) << width << "x" << height << " zoom " << zoom;
    }
  }
}

TEST(ReferenceSurfaceTest, StrayPointGetsNoWiderSplatThanTheQuantile) {
  Scan scan;
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 50; ++x) scan.positions.push_back({x * 0.01f, y * 0.01f, 0.0f});
  scan.positions.push_back({5.0f, 5.0f, 5.0f});  // far from everything
  const ReferenceSurface surface = buildReferenceSurface(scan);
  // Inside the grid the 6th nearest neighbour is a diagonal one: sqrt(2) grid steps. Fewer than
  // 10% of the points lie on the border (where it is 2 steps), so that is the quantile too.
  EXPECT_NEAR(surface.splat_radius[25 * 50 + 25], 0.01f * std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(surface.splat_radius.back(), 0.01f * std::sqrt(2.0f), 1e-5f);
}

}  // namespace
}  // namespace octopoint::tradeoff
