// Tests of loadScan: every supported format and field combination round-trips exactly, and every
// kind of bad input ends in one PrepareError line naming the file and the problem, never a crash.
// The scans are written here, by PCL or byte by byte, into a fresh temporary directory.

#include "codegen/scan_loader.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "codegen/prepare.h"
#include "codegen/prepare_error.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// How a cloud is written to disk; each loads through a different reader path.
enum class Encoding { kPcdAscii, kPcdBinary, kPcdCompressed, kPlyAscii, kPlyBinary };
constexpr Encoding kAllEncodings[] = {Encoding::kPcdAscii, Encoding::kPcdBinary,
                                      Encoding::kPcdCompressed, Encoding::kPlyAscii,
                                      Encoding::kPlyBinary};

const char* encodingName(Encoding encoding) {
  switch (encoding) {
    case Encoding::kPcdAscii: return "pcd_ascii";
    case Encoding::kPcdBinary: return "pcd_binary";
    case Encoding::kPcdCompressed: return "pcd_binary_compressed";
    case Encoding::kPlyAscii: return "ply_ascii";
    case Encoding::kPlyBinary: return "ply_binary";
  }
  return "?";
}

bool isPly(Encoding encoding) {
  return encoding == Encoding::kPlyAscii || encoding == Encoding::kPlyBinary;
}

class ScanLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("octopoint_scan_loader_" + std::string(info->name()) + "_" +
            std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path file(const std::string& name) const { return dir_ / name; }

  template <typename PointT>
  fs::path write(const pcl::PointCloud<PointT>& cloud, Encoding encoding,
                 const std::string& stem = "scan") const {
    const fs::path path = file(stem + "_" + encodingName(encoding) + (isPly(encoding) ? ".ply" : ".pcd"));
    int result = -1;
    switch (encoding) {
      case Encoding::kPcdAscii: result = pcl::io::savePCDFileASCII(path.string(), cloud); break;
      case Encoding::kPcdBinary: result = pcl::io::savePCDFileBinary(path.string(), cloud); break;
      case Encoding::kPcdCompressed:
        result = pcl::io::savePCDFileBinaryCompressed(path.string(), cloud);
        break;
      case Encoding::kPlyAscii: result = pcl::io::savePLYFile(path.string(), cloud, false); break;
      case Encoding::kPlyBinary: result = pcl::io::savePLYFile(path.string(), cloud, true); break;
    }
    EXPECT_EQ(result, 0) << "writing " << path;
    return path;
  }

  fs::path writeBytes(const std::string& name, const std::string& bytes) const {
    const fs::path path = file(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  fs::path dir_;
};

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return std::move(bytes).str();
}

// The message of the PrepareError that loading `path` throws ("" and a test failure if none).
std::string loadError(const fs::path& path) {
  try {
    loadScan(path);
  } catch (const PrepareError& error) {
    return error.what();
  }
  ADD_FAILURE() << "loadScan(" << path << ") did not throw PrepareError";
  return "";
}

// Expects the one-line "PATH: what (where)" message to name the file and contain `problem`.
void expectError(const fs::path& path, const std::string& problem) {
  const std::string message = loadError(path);
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << "'" << problem << "' not in: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.back(), ')') << message;
}

// Positions with fractions that print exactly in PCL's ascii output (8 significant digits).
std::array<float, 3> positionOf(int i) {
  return {0.25f * static_cast<float>(i) - 1.5f, -1234.5f + static_cast<float>(i),
          0.125f * static_cast<float>(i * i)};
}

// Distinct R, G and B for every point, so a byte-order mistake shows.
std::array<uint8_t, 3> colourOf(int i) {
  return {static_cast<uint8_t>(10 + i), static_cast<uint8_t>(100 + 3 * i),
          static_cast<uint8_t>(250 - 7 * i)};
}

template <typename PointT>
void setPosition(PointT& point, int i) {
  const auto position = positionOf(i);
  point.x = position[0];
  point.y = position[1];
  point.z = position[2];
}

constexpr int kPoints = 12;

void expectPositions(const Scan& scan) {
  ASSERT_EQ(scan.positions.size(), static_cast<std::size_t>(kPoints));
  for (int i = 0; i < kPoints; ++i) EXPECT_EQ(scan.positions[i], positionOf(i)) << "point " << i;
  EXPECT_EQ(scan.points_in_file, static_cast<std::size_t>(kPoints));
  EXPECT_EQ(scan.dropped_non_finite, 0u);
  EXPECT_FALSE(scan.organized);
}

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

TEST_F(ScanLoaderTest, PackedFloatRgbLoadsExactColoursInEveryEncoding) {
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  for (int i = 0; i < kPoints; ++i) {
    pcl::PointXYZRGB& point = cloud.emplace_back();
    setPosition(point, i);
    const auto rgb = colourOf(i);
    point.r = rgb[0];
    point.g = rgb[1];
    point.b = rgb[2];
  }
  for (Encoding encoding : kAllEncodings) {
    SCOPED_TRACE(encodingName(encoding));
    const Scan scan = loadScan(write(cloud, encoding));
    expectPositions(scan);
    EXPECT_EQ(scan.shading, ScanShading::kColour);
    ASSERT_EQ(scan.colours.size(), static_cast<std::size_t>(kPoints));
    for (int i = 0; i < kPoints; ++i) EXPECT_EQ(scan.colours[i], colourOf(i)) << "point " << i;
  }
}

TEST_F(ScanLoaderTest, Uint32RgbaLoadsExactColoursIgnoringAlphaInEveryEncoding) {
  pcl::PointCloud<pcl::PointXYZRGBA> cloud;
  for (int i = 0; i < kPoints; ++i) {
    pcl::PointXYZRGBA& point = cloud.emplace_back();
    setPosition(point, i);
    const auto rgb = colourOf(i);
    point.r = rgb[0];
    point.g = rgb[1];
    point.b = rgb[2];
    point.a = static_cast<uint8_t>(17 * i);
  }
  for (Encoding encoding : kAllEncodings) {
    SCOPED_TRACE(encodingName(encoding));
    const Scan scan = loadScan(write(cloud, encoding));
    expectPositions(scan);
    EXPECT_EQ(scan.shading, ScanShading::kColour);
    ASSERT_EQ(scan.colours.size(), static_cast<std::size_t>(kPoints));
    for (int i = 0; i < kPoints; ++i) EXPECT_EQ(scan.colours[i], colourOf(i)) << "point " << i;
  }
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

// ---- failures: each one PrepareError line naming the file and the problem ----

TEST_F(ScanLoaderTest, MissingFileIsRefused) { expectError(file("nothing_here.pcd"), "no such file"); }

TEST_F(ScanLoaderTest, DirectoryIsRefused) {
  fs::create_directory(file("folder.pcd"));
  expectError(file("folder.pcd"), "is a directory");
}

TEST_F(ScanLoaderTest, UnknownExtensionIsRefused) {
  expectError(writeBytes("scan.xyz", "1 2 3\n"), "unknown extension '.xyz'");
  expectError(writeBytes("scan", "1 2 3\n"), "unknown extension ''");
}

TEST_F(ScanLoaderTest, EmptyFileIsRefused) {
  expectError(writeBytes("empty.pcd", ""), "empty file");
  expectError(writeBytes("empty.ply", ""), "empty file");
}

TEST_F(ScanLoaderTest, GarbagePcdIsRefused) {
  // Without our header check PCL 1.13 dereferences a null pointer on this.
  std::mt19937 random(7);
  std::string garbage(3000, '\0');
  for (char& c : garbage) c = static_cast<char>(random());
  expectError(writeBytes("garbage.pcd", garbage), "not a PCD");
  expectError(writeBytes("text.pcd", "hello\nworld\nDATA ascii\n1 2 3\n"),
              "not a PCD header: unknown keyword 'hello' (header line 1)");
}

TEST_F(ScanLoaderTest, GarbagePlyIsRefused) {
  std::mt19937 random(8);
  std::string garbage(3000, '\0');
  for (char& c : garbage) c = static_cast<char>(random());
  expectError(writeBytes("garbage.ply", garbage), "not a PLY file");
  expectError(writeBytes("garbage_after_magic.ply", "ply\n" + garbage), "not a PLY file");
  expectError(writeBytes("bad_keyword.ply", "ply\nformat ascii 1.0\nbanana 3\nend_header\n"),
              "unknown keyword 'banana'");
}

TEST_F(ScanLoaderTest, GarbageCompressedDataIsRefusedAndPclStaysSilent) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < kPoints; ++i) setPosition(cloud.emplace_back(), i);
  std::string bytes = readBytes(write(cloud, Encoding::kPcdCompressed));
  const std::size_t lzf_start = bytes.find("binary_compressed\n") + 18 + 8;
  for (std::size_t i = lzf_start; i < bytes.size(); ++i) bytes[i] = static_cast<char>(0xE0);
  const fs::path path = writeBytes("scrambled.pcd", bytes);
  ::testing::internal::CaptureStderr();
  expectError(path, "PCL's PCD reader rejected it");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");  // PCL_ERROR output is silenced
}

TEST_F(ScanLoaderTest, CompressedSizeDisagreeingWithHeaderIsRefused) {
  // PCL would allocate the stored uncompressed size (here 4 GB) without checking it.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < kPoints; ++i) setPosition(cloud.emplace_back(), i);
  std::string bytes = readBytes(write(cloud, Encoding::kPcdCompressed));
  const std::size_t sizes = bytes.find("binary_compressed\n") + 18;
  std::memset(&bytes[sizes + 4], 0xFF, 4);
  expectError(writeBytes("bad_size.pcd", bytes), "corrupt: binary_compressed data says 4294967295");
}

std::string pcdHeader(const std::string& fields_lines, const std::string& points,
                      const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n" + fields_lines + "WIDTH " +
         points + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + points + "\nDATA " + data + "\n";
}
const std::string kXyzFields = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";

TEST_F(ScanLoaderTest, HugeDeclaredPointCountWithLittleDataIsRefusedQuickly) {
  // PCL 1.13 would resize its buffer to POINTS x 12 bytes (48 GB) before noticing.
  const auto started = std::chrono::steady_clock::now();
  const std::string huge = "4000000000";
  expectError(writeBytes("huge_binary.pcd", pcdHeader(kXyzFields, huge, "binary") +
                                                std::string(120, '\0')),
              "truncated: header declares 4000000000 points needing 48000000000 bytes");
  expectError(writeBytes("huge_ascii.pcd", pcdHeader(kXyzFields, huge, "ascii") + "1 2 3\n"),
              "truncated: header declares 4000000000 points but the ascii data has 1 data line");
  std::string compressed_body(8 + 4, '\0');
  compressed_body[0] = 4;  // 4 compressed bytes, 12 uncompressed: one point's worth
  compressed_body[4] = 12;
  expectError(writeBytes("huge_compressed.pcd",
                         pcdHeader(kXyzFields, huge, "binary_compressed") + compressed_body),
              "needing 48000000000");
  expectError(writeBytes("huge.ply",
                         "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                         "property float x\nproperty float y\nproperty float z\nend_header\n" +
                             std::string(120, '\0')),
              "truncated: header declares 4000000000 vertices");
  expectError(writeBytes("huge_faces.ply",
                         "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                         "property float x\nproperty float y\nproperty float z\n"
                         "element face 4000000000\nproperty list uchar int vertex_indices\n"
                         "end_header\n" + std::string(12, '\0')),
              "truncated");
  // Items without properties occupy no bytes, so no file length bounds their count.
  expectError(writeBytes("propertyless.ply",
                         "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                         "property float x\nproperty float y\nproperty float z\n"
                         "element face 4000000000\nend_header\n" + std::string(12, '\0')),
              "PLY element 'face' has 4000000000 items but no properties");
  expectError(writeBytes("negative.ply",
                         "ply\nformat ascii 1.0\nelement vertex -5\nproperty float x\n"
                         "property float y\nproperty float z\nend_header\n1 2 3\n"),
              "PLY element line without a non-negative count (header line 3)");
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(2));
}

TEST_F(ScanLoaderTest, HugeFieldCountIsRefused) {
  const std::string fields = "FIELDS x y z h\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1000000000\n";
  expectError(writeBytes("huge_count.pcd", pcdHeader(fields, "1", "ascii") + "1 2 3 4\n"),
              "field 'h' has invalid COUNT 1000000000");
}

TEST_F(ScanLoaderTest, InconsistentPcdHeadersAreRefused) {
  expectError(writeBytes("wh.pcd", "VERSION 0.7\n" + kXyzFields +
                                       "WIDTH 3\nHEIGHT 1\nPOINTS 2\nDATA ascii\n1 2 3\n4 5 6\n"),
              "WIDTH x HEIGHT (3 x 1) differs from POINTS 2");
  expectError(writeBytes("size.pcd", pcdHeader("FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\n", "1",
                                               "ascii") + "1 2 3\n"),
              "field 'z' has invalid SIZE/TYPE 3/F");
  expectError(writeBytes("data.pcd", pcdHeader(kXyzFields, "1", "zipped") + "1 2 3\n"),
              "PCD DATA is 'zipped'");
  expectError(writeBytes("nofields.pcd", "VERSION 0.7\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n"),
              "PCD header has no FIELDS line");
}

TEST_F(ScanLoaderTest, MissingOrWronglyTypedXyzFieldsAreRefused) {
  const std::string abc = "FIELDS a b c\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  expectError(writeBytes("abc.pcd", pcdHeader(abc, "1", "ascii") + "1 2 3\n"),
              "no float32 'x' field: x, y and z are required (field list: a b c)");
  const std::string doubles = "FIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\n";
  expectError(writeBytes("double.pcd", pcdHeader(doubles, "1", "ascii") + "1 2 3\n"),
              "no float32 'x' field");
  expectError(writeBytes("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                    "property float y\nend_header\n1 2\n"),
              "no float32 'z' field");
}

TEST_F(ScanLoaderTest, ColourOrIntensityFieldOfAnUnreadableTypeIsRefused) {
  const std::string fields = "FIELDS x y z intensity\nSIZE 4 4 4 2\nTYPE F F F U\nCOUNT 1 1 1 1\n";
  expectError(writeBytes("int16.pcd", pcdHeader(fields, "1", "ascii") + "1 2 3 4\n"),
              "field 'intensity' is not one float32");
  const std::string rgb = "FIELDS x y z rgb\nSIZE 4 4 4 1\nTYPE F F F U\nCOUNT 1 1 1 3\n";
  expectError(writeBytes("rgb3.pcd", pcdHeader(rgb, "1", "ascii") + "1 2 3 4 5 6\n"),
              "field 'rgb' is not one float32 or uint32");
}

TEST_F(ScanLoaderTest, EmptyCloudIsRefused) {
  expectError(writeBytes("empty_cloud.pcd", pcdHeader(kXyzFields, "0", "ascii")),
              "empty cloud (0 points)");
  expectError(writeBytes("empty_cloud.ply", "ply\nformat ascii 1.0\nelement vertex 0\n"
                                            "property float x\nproperty float y\n"
                                            "property float z\nend_header\n"),
              "empty cloud (0 points)");
}

TEST_F(ScanLoaderTest, AllNonFinitePointsAreRefused) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back(pcl::PointXYZ(kNaN, kNaN, kNaN));
  cloud.push_back(pcl::PointXYZ(1.0f, kNaN, 2.0f));
  cloud.push_back(pcl::PointXYZ(kInf, 1.0f, 2.0f));
  expectError(write(cloud, Encoding::kPcdBinary),
              "no finite points: all 3 points have a NaN or infinite coordinate");
}

TEST_F(ScanLoaderTest, AbsurdCoordinateIsRefusedNamingPointAndValue) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back(pcl::PointXYZ(kNaN, 0.0f, 0.0f));
  cloud.push_back(pcl::PointXYZ(1.0f, 2.0f, 3.0f));
  cloud.push_back(pcl::PointXYZ(1.0f, -2.5e6f, 3.0f));
  expectError(write(cloud, Encoding::kPcdBinary), "absurd coordinate y = -2.5e+06");
  expectError(write(cloud, Encoding::kPcdBinary), "(point 2)");
}

// ---- truncation: every cut ends in PrepareError, never a crash or a silently short cloud ----

// Loads every prefix of `full` (lengths 0 .. size-1); each must throw a PrepareError naming the
// file, and cuts past the header must say "truncated".
void expectEveryPrefixRefused(const fs::path& path, const std::string& full, std::size_t header_end) {
  for (std::size_t length = 0; length < full.size(); ++length) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << full.substr(0, length);
    SCOPED_TRACE("prefix of " + std::to_string(length) + " of " + std::to_string(full.size()) +
                 " bytes");
    const std::string message = loadError(path);
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    if (length >= header_end) {
      EXPECT_NE(message.find("truncated"), std::string::npos) << message;
    }
  }
}

pcl::PointCloud<pcl::PointXYZRGB> smallColouredCloud() {
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  for (int i = 0; i < 6; ++i) {
    pcl::PointXYZRGB& point = cloud.emplace_back();
    setPosition(point, i);
    point.r = point.g = point.b = static_cast<uint8_t>(i);
  }
  return cloud;
}

TEST_F(ScanLoaderTest, EveryTruncationOfABinaryPcdIsRefused) {
  const std::string full = readBytes(write(smallColouredCloud(), Encoding::kPcdBinary));
  expectEveryPrefixRefused(file("cut.pcd"), full, full.find("DATA binary\n") + 12);
}

TEST_F(ScanLoaderTest, EveryTruncationOfABinaryCompressedPcdIsRefused) {
  const std::string full = readBytes(write(smallColouredCloud(), Encoding::kPcdCompressed));
  expectEveryPrefixRefused(file("cut.pcd"), full, full.find("DATA binary_compressed\n") + 23);
}

TEST_F(ScanLoaderTest, EveryTruncationOfABinaryPlyIsRefused) {
  const std::string full = readBytes(write(smallColouredCloud(), Encoding::kPlyBinary));
  expectEveryPrefixRefused(file("cut.ply"), full, full.find("end_header\n") + 11);
}

TEST_F(ScanLoaderTest, TruncatedAsciiPcdIsRefusedAtSeveralLengths) {
  // Whole lines missing, and a line cut after its first value (PCL alone accepts a short last
  // line). A cut inside the very last number cannot be told from a shorter number in ascii.
  const std::string full = readBytes(write(smallColouredCloud(), Encoding::kPcdAscii));
  const std::size_t data = full.find("DATA ascii\n") + 11;
  const std::size_t second_line = full.find('\n', data) + 1;
  const std::size_t last_line = full.rfind('\n', full.size() - 2) + 1;
  const fs::path path = file("cut_ascii.pcd");
  for (std::size_t length : {std::size_t{20}, data - 3, data, second_line, last_line,
                             full.find(' ', last_line) + 1}) {
    SCOPED_TRACE("prefix of " + std::to_string(length) + " bytes");
    std::ofstream(path, std::ios::binary | std::ios::trunc) << full.substr(0, length);
    expectError(path, "truncated");
  }
}

TEST_F(ScanLoaderTest, TruncatedAsciiPlyIsRefusedAtSeveralLengths) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 6; ++i) setPosition(cloud.emplace_back(), i);
  const std::string full = readBytes(write(cloud, Encoding::kPlyAscii));
  const std::size_t data = full.find("end_header\n") + 11;
  const fs::path path = file("cut_ascii.ply");
  for (std::size_t length : {std::size_t{30}, data - 3, data, data + 1, full.find('\n', data) + 1,
                             (data + full.size()) / 2}) {
    SCOPED_TRACE("prefix of " + std::to_string(length) + " bytes");
    std::ofstream(path, std::ios::binary | std::ios::trunc) << full.substr(0, length);
    expectError(path, "truncated");
  }
}

}  // namespace
}  // namespace octopoint::prepare
