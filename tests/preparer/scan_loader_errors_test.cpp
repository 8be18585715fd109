// Tests of loadScan on bad input: every kind ends in one PrepareError line naming the file and
// the problem, never a crash, and a huge declared size is refused quickly. The scans are written by
// PCL or byte by byte into a fresh temporary directory (tests/support/scan_loader_fixture.h).

#include <gtest/gtest.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <random>
#include <string>

#include "cli/text.h"
#include "codegen/scan_loader.h"
#include "tests/support/scan_loader_fixture.h"

namespace octopoint::prepare {
namespace {

// ---- failures: each one PrepareError line naming the file and the problem ----

TEST_F(ScanLoaderTest, MissingFileIsRefused) {
  expectError(file("nothing_here.pcd"), "no such file");
}

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
  expectError(path, "corrupt: binary_compressed data refers 225 bytes back after 0 bytes");
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
  expectError(
      writeBytes("huge_binary.pcd", pcdHeader(kXyzFields, huge, "binary") + std::string(120, '\0')),
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
                         "end_header\n" +
                             std::string(12, '\0')),
              "truncated");
  // Items without properties occupy no bytes, so no file length bounds their count.
  expectError(writeBytes("propertyless.ply",
                         "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                         "property float x\nproperty float y\nproperty float z\n"
                         "element face 4000000000\nend_header\n" +
                             std::string(12, '\0')),
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
  expectError(
      writeBytes("size.pcd",
                 pcdHeader("FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\n", "1", "ascii") + "1 2 3\n"),
      "field 'z' has invalid SIZE/TYPE 3/F");
  expectError(writeBytes("data.pcd", pcdHeader(kXyzFields, "1", "zipped") + "1 2 3\n"),
              "PCD DATA is 'zipped'");
  expectError(
      writeBytes("nofields.pcd", "VERSION 0.7\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n"),
      "PCD header has no FIELDS line");
}

TEST_F(ScanLoaderTest, MissingOrWronglyTypedXyzFieldsAreRefused) {
  const std::string abc = "FIELDS a b c\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  expectError(writeBytes("abc.pcd", pcdHeader(abc, "1", "ascii") + "1 2 3\n"),
              "no float32 'x' field: x, y and z are required (field list: a b c)");
  const std::string doubles = "FIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\n";
  expectError(writeBytes("double.pcd", pcdHeader(doubles, "1", "ascii") + "1 2 3\n"),
              "no float32 'x' field");
  expectError(writeBytes("noz.ply",
                         "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
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
  expectError(writeBytes("empty_cloud.ply",
                         "ply\nformat ascii 1.0\nelement vertex 0\n"
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
  expectError(write(cloud, Encoding::kPcdBinary), "absurd coordinate y = -2500000");
  expectError(write(cloud, Encoding::kPcdBinary), "(point 2)");
  // Just past the limit, the value shown is the one in the file, every digit of it.
  for (const float x : {1000000.0625f, -1000000.125f, 1.5e30f}) {
    pcl::PointCloud<pcl::PointXYZ> near;
    near.push_back(pcl::PointXYZ(x, 0.0f, 0.0f));
    const std::string shown = cli::realText(x);
    EXPECT_EQ(std::stof(shown), x) << shown;
    expectError(write(near, Encoding::kPcdBinary), "absurd coordinate x = " + shown + ", beyond");
  }
}

// ---- truncation: every cut ends in PrepareError, never a crash or a silently short cloud ----

// Loads every prefix of `full` (lengths 0 .. size-1); each must throw a PrepareError naming the
// file, and cuts past the header must say "truncated".
void expectEveryPrefixRefused(const fs::path& path, const std::string& full,
                              std::size_t header_end) {
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
  for (std::size_t length :
       {std::size_t{20}, data - 3, data, second_line, last_line, full.find(' ', last_line) + 1}) {
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
