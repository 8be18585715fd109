// The fixture of the loadScan tests (tests/preparer/scan_loader_test.cpp and
// scan_loader_errors_test.cpp): a fresh temporary directory per test, scans written into it by PCL
// in each encoding or byte by byte, and the expectations both files share.

#pragma once

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <utility>

#include "codegen/prepare.h"
#include "codegen/prepare_error.h"
#include "codegen/scan_loader.h"

namespace octopoint::prepare {

namespace fs = std::filesystem;

inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
inline constexpr float kInf = std::numeric_limits<float>::infinity();

// How a cloud is written to disk; each loads through a different reader path.
enum class Encoding { kPcdAscii, kPcdBinary, kPcdCompressed, kPlyAscii, kPlyBinary };
inline constexpr Encoding kAllEncodings[] = {Encoding::kPcdAscii, Encoding::kPcdBinary,
                                             Encoding::kPcdCompressed, Encoding::kPlyAscii,
                                             Encoding::kPlyBinary};

inline const char* encodingName(Encoding encoding) {
  switch (encoding) {
    case Encoding::kPcdAscii:
      return "pcd_ascii";
    case Encoding::kPcdBinary:
      return "pcd_binary";
    case Encoding::kPcdCompressed:
      return "pcd_binary_compressed";
    case Encoding::kPlyAscii:
      return "ply_ascii";
    case Encoding::kPlyBinary:
      return "ply_binary";
  }
  return "?";
}

inline bool isPly(Encoding encoding) {
  return encoding == Encoding::kPlyAscii || encoding == Encoding::kPlyBinary;
}

class ScanLoaderTest : public ::testing::Test {
 public:  // its helpers are called from the tests' own helper templates too
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("octopoint_scan_loader_" + std::string(info->name()) + "_" +
                                        std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path file(const std::string& name) const { return dir_ / name; }

  template <typename PointT>
  fs::path write(const pcl::PointCloud<PointT>& cloud, Encoding encoding,
                 const std::string& stem = "scan") const {
    const fs::path path =
        file(stem + "_" + encodingName(encoding) + (isPly(encoding) ? ".ply" : ".pcd"));
    int result = -1;
    switch (encoding) {
      case Encoding::kPcdAscii:
        result = pcl::io::savePCDFileASCII(path.string(), cloud);
        break;
      case Encoding::kPcdBinary:
        result = pcl::io::savePCDFileBinary(path.string(), cloud);
        break;
      case Encoding::kPcdCompressed:
        result = pcl::io::savePCDFileBinaryCompressed(path.string(), cloud);
        break;
      case Encoding::kPlyAscii:
        result = pcl::io::savePLYFile(path.string(), cloud, false);
        break;
      case Encoding::kPlyBinary:
        result = pcl::io::savePLYFile(path.string(), cloud, true);
        break;
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

inline std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return std::move(bytes).str();
}

// The message of the PrepareError that loading `path` throws ("" and a test failure if none).
inline std::string loadError(const fs::path& path) {
  try {
    loadScan(path);
  } catch (const PrepareError& error) {
    return error.what();
  }
  ADD_FAILURE() << "loadScan(" << path << ") did not throw PrepareError";
  return "";
}

// Expects the one-line "PATH: what (where)" message to name the file and contain `problem`.
inline void expectError(const fs::path& path, const std::string& problem) {
  const std::string message = loadError(path);
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << "'" << problem << "' not in: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.back(), ')') << message;
}

// Positions with fractions that print exactly in PCL's ascii output (8 significant digits).
inline std::array<float, 3> positionOf(int i) {
  return {0.25f * static_cast<float>(i) - 1.5f, -1234.5f + static_cast<float>(i),
          0.125f * static_cast<float>(i * i)};
}

// Distinct R, G and B for every point, so a byte-order mistake shows.
inline std::array<uint8_t, 3> colourOf(int i) {
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

inline constexpr int kPoints = 12;

inline void expectPositions(const Scan& scan) {
  ASSERT_EQ(scan.positions.size(), static_cast<std::size_t>(kPoints));
  for (int i = 0; i < kPoints; ++i) EXPECT_EQ(scan.positions[i], positionOf(i)) << "point " << i;
  EXPECT_EQ(scan.points_in_file, static_cast<std::size_t>(kPoints));
  EXPECT_EQ(scan.dropped_non_finite, 0u);
  EXPECT_FALSE(scan.organized);
}

}  // namespace octopoint::prepare
