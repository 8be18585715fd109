// The surface reference (lab/reference_surface.h, lab/reference_render.h): dense at every size and
// zoom, faithful at the edges, never bridging a jump in depth. Synthetic scans with exact answers.
#include "lab/reference_render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "codegen/cube_fit.h"
#include "lab/reference_closure.h"
#include "lab/reference_surface.h"

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

// The mesh itself (no extension past its last samples) covers exactly the pixels whose centre lies
// inside the outline of the samples; with kMeshExtensionSteps it covers every pixel centre inside
// the outline pushed out by that many grid steps (but for its corners, which are rounded) and
// none outside it (a depth camera's true edge lies past its last samples:
// tests/lab/reference_truth_test.cpp).
TEST(ReferenceRender, OrganizedPlaneCoversExactlyItsOutlineAtEverySizeAndZoom) {
  const int columns = 160, rows = 120;
  const double focal = 150, cx = 79.5, cy = 59.5;
  const Scan plane = depthImage(columns, rows, focal, cx, cy, [](int, int) { return 1.0; });
  const ReferenceSurface mesh = buildReferenceSurface(plane, kSplatRule, 0);
  ASSERT_EQ(mesh.triangles.size(), 2u * (columns - 1) * (rows - 1));
  const ReferenceSurface extended = buildReferenceSurface(plane);
  const prepare::CubeFit fit = prepare::fitCube(plane.positions, "plane");
  // The outline's corners in grid coordinates, at depth 1: the samples', and pushed out.
  const auto outline = [&](double out) {
    std::vector<std::array<float, 3>> corners;
    for (const auto& [col, row] :
         {std::pair{-out, -out}, std::pair{columns - 1 + out, -out},
          std::pair{columns - 1 + out, rows - 1 + out}, std::pair{-out, rows - 1 + out}}) {
      corners.push_back(
          {static_cast<float>((col - cx) / focal), static_cast<float>((row - cy) / focal), 1.0f});
    }
    return corners;
  };
  for (const bool extend : {false, true}) {
    const double out = extend ? kMeshExtensionSteps : 0;
    const auto corners3 = outline(out);
    for (int yaw : {0, 30}) {
      for (const auto& [width, height] : kSizes) {
        for (double zoom : kZooms) {
          const Camera camera = cameraFor(width, height, zoom, yaw);
          const ScreenProjection project(fit, camera);
          std::vector<std::array<double, 3>> corners;
          for (const auto& corner : corners3) corners.push_back(project(corner));
          // Within this many pixels of a corner the extension is rounded (up to its width).
          const double corner_px = 1.5 * out / focal * project.pixelsPerUnit();
          cv::Mat covered;
          renderReference(extend ? extended : mesh, fit, camera, kBackground, &covered);
          int holes = 0, spills = 0;
          for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
              const bool on = covered.at<std::uint8_t>(y, x) != 0;
              bool near_corner = false;
              for (const auto& c : corners)
                near_corner |= std::hypot(x + 0.5 - c[0], y + 0.5 - c[1]) < corner_px;
              holes += !on && !near_corner && insideBy(corners, x + 0.5, y + 0.5, 1e-6);
              spills += on && insideBy(corners, x + 0.5, y + 0.5, -1e-6);
            }
          }
          const std::string view = std::to_string(width) + "x" + std::to_string(height) + " zoom " +
                                   std::to_string(zoom) + " yaw " + std::to_string(yaw) +
                                   (extend ? ", extended" : "");
          EXPECT_EQ(holes, 0) << view;
          EXPECT_EQ(spills, 0) << view;
        }
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
    const bool near0 = surface.positions[t[0]][2] < 1.5, near1 = surface.positions[t[1]][2] < 1.5,
               near2 = surface.positions[t[2]][2] < 1.5;
    EXPECT_TRUE(near0 == near1 && near1 == near2) << "a triangle joins the near and the far half";
  }
  // Drawn from the front: between the near half's right edge and the far half's left edge lies
  // background (but for each half's extension past its last samples, kMeshExtensionSteps grid
  // steps: 1 / focal at depth 1, 2 / focal at depth 2), and both halves are there.
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
  const double step_px = project.pixelsPerUnit() / focal;  // a grid step at depth 1
  const int row = static_cast<int>(middle_row);
  for (int x = static_cast<int>(near_right + kMeshExtensionSteps * step_px) + 2;
       x < static_cast<int>(far_left - 2 * kMeshExtensionSteps * step_px) - 1; ++x) {
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
    // The mesh alone, without the strips past its boundary.
    const ReferenceSurface surface = buildReferenceSurface(scan, kSplatRule, 0);
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
  // The mesh alone, without the strips past its boundary.
  const ReferenceSurface surface = buildReferenceSurface(scan, kSplatRule, 0);
  const std::size_t full = 2u * 9 * 7;
  EXPECT_LT(surface.triangles.size(), full);
  EXPECT_GE(surface.triangles.size(), full - 6);
  for (const auto& t : surface.triangles) {
    for (std::uint32_t v : t) EXPECT_LT(v, scan.positions.size());
  }
}

// kSplatRule closes a jittered plane (lab/reference_closure.h: one point anywhere in each of
// 200 x 200 cells, as a scanner's irregular samples) at every size 1x1..1920x1080 and zoom 0.25..8
// and spills no further than its largest disc. Its scale is the smallest that does (in steps of
// 0.05): 0.05 less opens holes. Fewer neighbours do not close it with discs as large: the 6th
// neighbour at scale 0.8 gives the same median disc (1.15 cells) and leaves holes
// (octopoint-reference-closure prints the whole measurement, docs/tradeoff.md).
TEST(ReferenceRender, UnorganizedSplatsCloseAJitteredPlane) {
  const PlaneCoverage coverage = jitteredPlaneCoverage(kSplatRule);
  EXPECT_EQ(coverage.holes, 0) << "first at " << coverage.first_hole;
  EXPECT_EQ(coverage.spills, 0);
  SplatRule smaller = kSplatRule;
  smaller.scale -= 0.05;
  EXPECT_GT(jitteredPlaneCoverage(smaller).holes, 0);
  const PlaneCoverage sixth = jitteredPlaneCoverage({6, 0.8, kSplatRule.cap_quantile});
  EXPECT_NEAR(sixth.median_radius, coverage.median_radius, 0.01);
  EXPECT_GT(sixth.holes, 0);
}

// A lone stray return is drawn as a disc no wider than the rule's outline disc: edge_scale x the
// cap quantile of the neighbour distances, whatever its own neighbours' distance (its neighbours
// all lie on one side, as an outline point's do: lab/reference_truth.h measured that the truth
// supports no wider disc there; before, it was scale x the cap).
TEST(ReferenceSurfaceTest, StrayPointGetsNoWiderSplatThanTheCap) {
  Scan scan;
  constexpr float kStep = 0.01f;
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 50; ++x) scan.positions.push_back({x * kStep, y * kStep, 0.0f});
  scan.positions.push_back({0.8f, 0.8f, 0.3f});  // 0.3 and more from everything
  const ReferenceSurface surface = buildReferenceSurface(scan);
  // On the square grid the 8th nearest neighbour is a diagonal one, sqrt(2) steps, for every point
  // but those on the border (2 steps; 196 of 2501, under 10%): that is the 0.9 quantile too.
  ASSERT_EQ(kSplatRule.neighbour, 8);
  ASSERT_EQ(kSplatRule.cap_quantile, 0.9);
  const float capped = kStep * std::sqrt(2.0f);
  EXPECT_NEAR(surface.splat_radius[25 * 50 + 25], kSplatRule.scale * capped, 1e-6f);
  const float cap = static_cast<float>(kSplatRule.edge_scale) * capped;
  EXPECT_NEAR(surface.splat_radius.back(), cap, 1e-6f);
  // Drawn, its disc spans 2 x cap x pixels per unit, give or take the pixel centres.
  const prepare::CubeFit fit = prepare::fitCube(scan.positions, "stray");
  const Camera camera = cameraFor(1920, 1080, 1);
  const ScreenProjection project(fit, camera);
  const auto centre = project(scan.positions.back());
  const double radius_px = cap * project.pixelsPerUnit();
  ASSERT_GT(radius_px, 4);
  cv::Mat covered;
  renderReference(surface, fit, camera, kBackground, &covered);
  int left = 1920, right = -1, top = 1080, bottom = -1;
  for (int y = 0; y < 1080; ++y) {
    for (int x = 0; x < 1920; ++x) {
      if (!covered.at<std::uint8_t>(y, x) ||
          std::hypot(x + 0.5 - centre[0], y + 0.5 - centre[1]) > 100)
        continue;
      left = std::min(left, x), right = std::max(right, x);
      top = std::min(top, y), bottom = std::max(bottom, y);
    }
  }
  ASSERT_GE(right, left) << "the stray point is not drawn";
  EXPECT_LE(right - left + 1, 2 * radius_px + 1);
  EXPECT_GE(right - left + 1, 2 * radius_px - 1);
  EXPECT_LE(bottom - top + 1, 2 * radius_px + 1);
}

// A sparse outlier, a point in a cluster sampled five times more coarsely than the scan (its 8th
// neighbour 5 x sqrt(2) steps away, over kSplatRule.sparse_factor x the median), is drawn as a
// stray return though its neighbours lie all round it, where the centroid test sees nothing; the
// plane's own points keep the surface disc, and without the sparse rule the outlier would too.
TEST(ReferenceSurfaceTest, SparseOutlierGetsTheStrayDisc) {
  Scan scan;
  constexpr float kStep = 0.01f;
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 50; ++x) scan.positions.push_back({x * kStep, y * kStep, 0.0f});
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      scan.positions.push_back({0.25f + 5 * kStep * x, 0.25f + 5 * kStep * y, 0.3f});
  const std::size_t outlier = scan.positions.size() - 5;  // the cluster's centre
  const float capped = kStep * std::sqrt(2.0f);           // as in the test above
  ASSERT_GT(5 * capped, kSplatRule.sparse_factor * capped);
  const ReferenceSurface surface = buildReferenceSurface(scan);
  EXPECT_NEAR(surface.splat_radius[outlier], kSplatRule.edge_scale * capped, 1e-6f);
  EXPECT_NEAR(surface.splat_radius[25 * 50 + 25], kSplatRule.scale * capped, 1e-6f);
  SplatRule no_sparse = kSplatRule;
  no_sparse.sparse_factor = 0;
  EXPECT_NEAR(buildReferenceSurface(scan, no_sparse).splat_radius[outlier],
              kSplatRule.scale * capped, 1e-6f);
}

}  // namespace
}  // namespace octopoint::tradeoff
