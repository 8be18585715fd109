// Tests of loadScan: every supported format and field combination round-trips exactly (the bad
// inputs are in scan_loader_errors_test.cpp). The scans are written by PCL or byte by byte into a
// fresh temporary directory (tests/support/scan_loader_fixture.h).

#include "codegen/scan_loader.h"

#include <gtest/gtest.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "tests/support/scan_loader_fixture.h"

namespace octopoint::prepare {
namespace {

TEST_F(ScanLoaderTest, XyzLoadsExactPositionsWithoutColoursInEveryEncoding) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < kPoints; ++i) setPosition(cloud.emplace_back(), i);
  for (Encoding encoding : kAllEncodings) {
    SCOPED_TRACE(encodingName(encoding));
    const Scan scan = loadScan(write(cloud, encoding));
    expectPositions(scan);
    EXPECT_EQ(scan.shading, ScanShading::kNone);
    EXPECT_TRUE(scan.colours.empty());
  }
}

// kPoints points, each at positionOf(i) with colourOf(i) (alpha, where the point has one, varies).
template <typename Point>
pcl::PointCloud<Point> colouredCloud() {
  pcl::PointCloud<Point> cloud;
  for (int i = 0; i < kPoints; ++i) {
    Point& point = cloud.emplace_back();
    setPosition(point, i);
    const auto rgb = colourOf(i);
    point.r = rgb[0];
    point.g = rgb[1];
    point.b = rgb[2];
    if constexpr (requires { point.a; }) point.a = static_cast<uint8_t>(17 * i);
  }
  return cloud;
}

// Every encoding of colouredCloud<Point>() loads with its exact positions and colours.
template <typename Point>
void expectExactColoursInEveryEncoding(const ScanLoaderTest& test) {
  const pcl::PointCloud<Point> cloud = colouredCloud<Point>();
  for (Encoding encoding : kAllEncodings) {
    SCOPED_TRACE(encodingName(encoding));
    const Scan scan = loadScan(test.write(cloud, encoding));
    expectPositions(scan);
    EXPECT_EQ(scan.shading, ScanShading::kColour);
    ASSERT_EQ(scan.colours.size(), static_cast<std::size_t>(kPoints));
    for (int i = 0; i < kPoints; ++i) EXPECT_EQ(scan.colours[i], colourOf(i)) << "point " << i;
  }
}

TEST_F(ScanLoaderTest, PackedFloatRgbLoadsExactColoursInEveryEncoding) {
  expectExactColoursInEveryEncoding<pcl::PointXYZRGB>(*this);
}

TEST_F(ScanLoaderTest, Uint32RgbaLoadsExactColoursIgnoringAlphaInEveryEncoding) {
  expectExactColoursInEveryEncoding<pcl::PointXYZRGBA>(*this);
}

TEST_F(ScanLoaderTest, HandWrittenRgbFieldAsUint32IsReadAsPackedColour) {
  // R in bits 16..23, G 8..15, B 0..7: 0x123456 is (0x12, 0x34, 0x56).
  const fs::path path = writeBytes("rgb_uint.pcd",
                                   "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\n"
                                   "COUNT 1 1 1 1\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
                                   "POINTS 1\nDATA ascii\n1 2 3 1193046\n");
  const Scan scan = loadScan(path);
  ASSERT_EQ(scan.colours.size(), 1u);
  EXPECT_EQ(scan.shading, ScanShading::kColour);
  EXPECT_EQ(scan.colours[0], (std::array<uint8_t, 3>{0x12, 0x34, 0x56}));
}

TEST_F(ScanLoaderTest, IntensityLoadsAsGreyInEveryEncoding) {
  // Intensities 0..100 (101 points): the 1st percentile is 1 and the 99th is 99, so 1 -> 0,
  // 99 -> 255, 50 -> 127.5 rounds to 128, and 0 and 100 clamp. A min..max mapping would give
  // 1 -> 3 and fail.
  pcl::PointCloud<pcl::PointXYZI> cloud;
  std::vector<int> order(101);
  for (int i = 0; i < 101; ++i) order[i] = (i * 37) % 101;  // shuffled: percentiles need sorting
  for (int i = 0; i < 101; ++i) {
    pcl::PointXYZI& point = cloud.emplace_back();
    point.x = static_cast<float>(i);
    point.y = 0.0f;
    point.z = 0.0f;
    point.intensity = static_cast<float>(order[i]);
  }
  const auto expected_grey = [](int intensity) -> uint8_t {
    if (intensity <= 1) return 0;
    if (intensity >= 99) return 255;
    return static_cast<uint8_t>(std::lround((intensity - 1) / 98.0 * 255.0));
  };
  for (Encoding encoding : kAllEncodings) {
    SCOPED_TRACE(encodingName(encoding));
    const Scan scan = loadScan(write(cloud, encoding));
    EXPECT_EQ(scan.shading, ScanShading::kIntensity);
    ASSERT_EQ(scan.colours.size(), 101u);
    for (int i = 0; i < 101; ++i) {
      const uint8_t grey = expected_grey(order[i]);
      EXPECT_EQ(scan.colours[i], (std::array<uint8_t, 3>{grey, grey, grey}))
          << "intensity " << order[i];
    }
  }
}

TEST_F(ScanLoaderTest, AFewHotIntensityReturnsDoNotDarkenTheRest) {
  pcl::PointCloud<pcl::PointXYZI> cloud;
  for (int i = 0; i < 200; ++i) {
    pcl::PointXYZI& point = cloud.emplace_back();
    point.x = static_cast<float>(i);
    point.y = point.z = 0.0f;
    point.intensity = i == 0 ? 1.0e9f : static_cast<float>(i % 100);  // one retro-reflector
  }
  const Scan scan = loadScan(write(cloud, Encoding::kPcdBinary));
  EXPECT_EQ(scan.colours[0][0], 255);
  EXPECT_GE(scan.colours[50][0], 120);  // intensity 50 stays mid-grey, not black
  EXPECT_LE(scan.colours[50][0], 136);
}

TEST_F(ScanLoaderTest, NonFiniteIntensityOfAKeptPointBecomesBlack) {
  pcl::PointCloud<pcl::PointXYZI> cloud;
  for (int i = 0; i < 4; ++i) {
    pcl::PointXYZI& point = cloud.emplace_back();
    point.x = static_cast<float>(i);
    point.y = point.z = 0.0f;
    point.intensity = i == 2 ? kNaN : static_cast<float>(i);
  }
  const Scan scan = loadScan(write(cloud, Encoding::kPcdBinary));
  ASSERT_EQ(scan.colours.size(), 4u);
  EXPECT_EQ(scan.colours[2], (std::array<uint8_t, 3>{0, 0, 0}));
  EXPECT_EQ(scan.colours[3], (std::array<uint8_t, 3>{255, 255, 255}));
}

TEST_F(ScanLoaderTest, ConstantIntensityBecomesMidGrey) {
  pcl::PointCloud<pcl::PointXYZI> cloud;
  for (int i = 0; i < 3; ++i) {
    pcl::PointXYZI& point = cloud.emplace_back();
    point.x = static_cast<float>(i);
    point.y = point.z = 0.0f;
    point.intensity = 7.0f;
  }
  const Scan scan = loadScan(write(cloud, Encoding::kPcdBinary));
  for (const auto& grey : scan.colours) EXPECT_EQ(grey, (std::array<uint8_t, 3>{128, 128, 128}));
}

TEST_F(ScanLoaderTest, NanAndInfinitePointsAreDroppedAndCountedWithTheirColours) {
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  const float bad[][3] = {{kNaN, 0, 0}, {0, kInf, 0}, {0, 0, -kInf}, {kNaN, kNaN, kNaN}};
  for (int i = 0; i < 8; ++i) {
    pcl::PointXYZRGB& point = cloud.emplace_back();
    setPosition(point, i);
    point.r = static_cast<uint8_t>(i);
    if (i % 2 == 1) {  // odd points are bad
      point.x = bad[i / 2][0];
      point.y = bad[i / 2][1];
      point.z = bad[i / 2][2];
    }
  }
  for (Encoding encoding : {Encoding::kPcdAscii, Encoding::kPcdBinary, Encoding::kPcdCompressed,
                            Encoding::kPlyBinary}) {
    SCOPED_TRACE(encodingName(encoding));
    const Scan scan = loadScan(write(cloud, encoding));
    EXPECT_EQ(scan.points_in_file, 8u);
    EXPECT_EQ(scan.dropped_non_finite, 4u);
    ASSERT_EQ(scan.positions.size(), 4u);
    ASSERT_EQ(scan.colours.size(), 4u);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(scan.positions[k], positionOf(2 * k));
      EXPECT_EQ(scan.colours[k][0], 2 * k);
    }
  }
}

TEST_F(ScanLoaderTest, OrganizedScanKeepsItsGridAndEachPointsPlaceInIt) {
  pcl::PointCloud<pcl::PointXYZ> organized(3, 2);
  for (int i = 0; i < 6; ++i) setPosition(organized[i], i);
  organized[4].x = kNaN;  // organized scans keep NaN placeholders
  for (Encoding encoding : {Encoding::kPcdAscii, Encoding::kPcdBinary, Encoding::kPcdCompressed}) {
    SCOPED_TRACE(encodingName(encoding));
    const Scan scan = loadScan(write(organized, encoding, "organized"));
    EXPECT_TRUE(scan.organized);
    EXPECT_EQ(scan.points_in_file, 6u);
    EXPECT_EQ(scan.positions.size(), 5u);
    EXPECT_EQ(scan.grid_width, 3u);
    EXPECT_EQ(scan.grid_height, 2u);
    EXPECT_EQ(scan.grid_index, (std::vector<std::uint32_t>{0, 1, 2, 3, 5}));  // 4 was NaN

    // Cropping keeps each survivor's place in the grid.
    CropBox box;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      box.low[axis] = positionOf(1)[axis];
      box.high[axis] = positionOf(3)[axis];
    }
    const Scan cropped = cropScan(scan, box, "organized.pcd");
    EXPECT_EQ(cropped.grid_width, 3u);
    EXPECT_EQ(cropped.grid_index, (std::vector<std::uint32_t>{1, 2, 3}));

    pcl::PointCloud<pcl::PointXYZ> flat = organized;
    flat.width = 6;
    flat.height = 1;
    const Scan flat_scan = loadScan(write(flat, encoding, "flat"));
    EXPECT_FALSE(flat_scan.organized);
    EXPECT_EQ(flat_scan.grid_width, 0u);
    EXPECT_TRUE(flat_scan.grid_index.empty());
  }
}

TEST_F(ScanLoaderTest, IdenticalPointsAreLoadedNotRefused) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 5; ++i) cloud.push_back(pcl::PointXYZ(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(loadScan(write(cloud, Encoding::kPcdBinary)).positions.size(), 5u);
}

TEST_F(ScanLoaderTest, ExtensionIsCaseInsensitive) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back(pcl::PointXYZ(1.0f, 2.0f, 3.0f));
  const fs::path pcd = write(cloud, Encoding::kPcdBinary);
  const fs::path upper = file("SCAN.PCD");
  fs::copy_file(pcd, upper);
  EXPECT_EQ(loadScan(upper).positions.size(), 1u);
  const fs::path ply = write(cloud, Encoding::kPlyBinary);
  const fs::path mixed = file("scan.Ply");
  fs::copy_file(ply, mixed);
  EXPECT_EQ(loadScan(mixed).positions.size(), 1u);
}

TEST_F(ScanLoaderTest, CoordinateAtTheLimitIsAccepted) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back(pcl::PointXYZ(kMaxAbsCoordinate, -kMaxAbsCoordinate, 0.0f));
  EXPECT_EQ(loadScan(write(cloud, Encoding::kPcdBinary)).positions.size(), 1u);
}

}  // namespace
}  // namespace octopoint::prepare
