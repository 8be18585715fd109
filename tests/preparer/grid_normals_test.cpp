// Normals of organized scans of every shape (codegen/normal_estimation.h): PCL's integral images
// skip a border as wide as their window and read windows around each point unchecked, so grids
// narrower than twice the window (1xN, 2xN, 3x3) and scans in millimetres (a window 100 cells
// wider) made them run past the grid. Each scan here is a real organized PCD file, a tilted plane
// with or without NaN holes, loaded as octopoint-prepare loads it; every normal found must be the
// plane's.
#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "codegen/normal_estimation.h"
#include "codegen/scan_loader.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

// The plane z = depth * (1 + kSlopeX x + kSlopeY y), seen from the origin one pixel a milliradian.
constexpr double kSlopeX = 0.3;
constexpr double kSlopeY = -0.2;
constexpr double kPixelRadians = 0.001;
constexpr double kMaxErrorDegrees = 5;

class GridNormalsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("octopoint_grid_normals_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A width x height organized PCD of the plane at `depth` scan units; with `holes`, every fifth
  // cell in a diagonal pattern is NaN, as a sensor leaves where nothing came back.
  fs::path writeGrid(std::uint32_t width, std::uint32_t height, double depth, bool holes) const {
    pcl::PointCloud<pcl::PointXYZ> cloud(width, height);
    for (std::uint32_t y = 0; y < height; ++y) {
      for (std::uint32_t x = 0; x < width; ++x) {
        const double u = (x - width / 2.0) * kPixelRadians;
        const double v = (y - height / 2.0) * kPixelRadians;
        const double z = depth / (1 - kSlopeX * u - kSlopeY * v);  // the ray (u, v, 1) meets it
        const float nan = std::numeric_limits<float>::quiet_NaN();
        cloud(x, y) = holes && (7 * x + 3 * y) % 5 == 0
                          ? pcl::PointXYZ(nan, nan, nan)
                          : pcl::PointXYZ(static_cast<float>(u * z), static_cast<float>(v * z),
                                          static_cast<float>(z));
      }
    }
    cloud.is_dense = !holes;
    const fs::path path = dir_ / ("grid_" + std::to_string(width) + "x" + std::to_string(height) +
                                  (holes ? "_holes" : "") + ".pcd");
    EXPECT_EQ(pcl::io::savePCDFileBinary(path.string(), cloud), 0);
    return path;
  }

  // Loads the grid and estimates its normals with the preparer's defaults for a depth-10 model.
  // Where the points span a plane (two rows and two columns at least) some normals must be found,
  // each within kMaxErrorDegrees of the plane's; a single row or column has no normal to find.
  void expectPlaneNormals(std::uint32_t width, std::uint32_t height, double depth, bool holes) {
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height) + " at depth " +
                 std::to_string(depth) + (holes ? " with holes" : ""));
    const fs::path path = writeGrid(width, height, depth, holes);
    const Scan scan = loadScan(path);
    ASSERT_EQ(scan.organized, height > 1);  // a single row is read as an unorganized scan
    if (scan.positions.size() < 3) return;  // refused by estimateNormals, its own test
    const double extent = std::max(width, height) * kPixelRadians * depth;
    const auto normals = estimateNormals(scan, extent / 1024, NormalOptions{}, path.string());
    ASSERT_EQ(normals.size(), scan.positions.size());
    const double plane[3] = {-kSlopeX, -kSlopeY, 1};
    const double plane_length = std::sqrt(kSlopeX * kSlopeX + kSlopeY * kSlopeY + 1);
    const bool spans_a_plane = width >= 2 && height >= 2;
    if (!spans_a_plane) return;
    std::size_t found = 0;
    for (const auto& n : normals) {
      if (!std::isfinite(n[0])) continue;
      ++found;
      const double cosine =
          std::fabs(n[0] * plane[0] + n[1] * plane[1] + n[2] * plane[2]) / plane_length;
      EXPECT_GE(cosine, std::cos(kMaxErrorDegrees * 3.14159265358979 / 180));
    }
    EXPECT_GT(found, 0u);
  }

  fs::path dir_;
};

TEST_F(GridNormalsTest, TheShapesThatCrashed) {
  const std::uint32_t shapes[][2] = {{2, 2},   {3, 3}, {1, 100}, {2, 100},
                                     {100, 2}, {1, 3}, {1, 640}};
  for (const auto& shape : shapes) {
    for (const bool holes : {false, true}) expectPlaneNormals(shape[0], shape[1], 1.0, holes);
  }
}

// Every grid narrower than the widest window in one direction (1..12 cells: the window is at
// least 4 cells each side), against every length up to past it, and squares up to 12x12.
TEST_F(GridNormalsTest, EveryNarrowGrid) {
  for (std::uint32_t narrow = 1; narrow <= 12; ++narrow) {
    for (const std::uint32_t length : {2u, 3u, 5u, 8u, 9u, 13u, 40u, 200u}) {
      for (const bool holes : {false, true}) {
        expectPlaneNormals(narrow, length, 1.0, holes);
        expectPlaneNormals(length, narrow, 1.0, holes);
      }
    }
    expectPlaneNormals(narrow, narrow, 1.0, false);
  }
}

// PCL widens the window by depth / 10 cells: a scan in millimetres or centimetres, of any size.
TEST_F(GridNormalsTest, ScansInMillimetres) {
  for (const double depth : {30.0, 100.0, 1000.0, 5000.0}) {
    for (const bool holes : {false, true}) {
      expectPlaneNormals(160, 120, depth, holes);
      expectPlaneNormals(12, 300, depth, holes);
    }
  }
}

}  // namespace
}  // namespace octopoint::prepare
