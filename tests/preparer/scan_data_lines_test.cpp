// Scan data that PCL would read into silently wrong points, and sizes that would cost far more than
// the file weighs (docs/robustness.md, classes 1 and 5): every ascii data line must parse as its
// header declares, and a binary_compressed size must be one LZF can reach from the bytes present.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "codegen/prepare_error.h"
#include "codegen/scan_loader.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

class ScanDataLinesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("octopoint_scan_lines_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& bytes) const {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  // The message of loading `bytes` as `name`, which must fail.
  std::string errorOf(const std::string& name, const std::string& bytes) const {
    const fs::path path = write(name, bytes);
    try {
      loadScan(path);
    } catch (const PrepareError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
      return message.substr(path.string().size() + 2);
    }
    ADD_FAILURE() << name << " was accepted";
    return "";
  }

  fs::path dir_;
};

std::string pcd(const std::string& fields, int points, const std::string& data,
                const std::string& body) {
  return "VERSION 0.7\n" + fields + "WIDTH " + std::to_string(points) +
         "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(points) + "\nDATA " +
         data + "\n" + body;
}
const std::string kXyz = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
const std::string kXyzLabel = "FIELDS x y z label\nSIZE 4 4 4 1\nTYPE F F F U\nCOUNT 1 1 1 1\n";

std::string ply(const std::string& body) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
         "float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
         body;
}

TEST_F(ScanDataLinesTest, AsciiPcdValuesThatDoNotParseAreRefusedNamingTheLine) {
  // Line 11 is the first data line (10 header lines).
  EXPECT_EQ(errorOf("oops.pcd", pcd(kXyz, 3, "ascii", "1 2 3\n10.5 10.5 oops\n4 5 6\n")),
            "'oops' is not a float32 (field 'z') (line 12)");
  EXPECT_EQ(errorOf("comma.pcd", pcd(kXyz, 2, "ascii", "1 2 3\n1,5 2 3\n")),
            "'1,5' is not a float32 (field 'x') (line 12)");
  EXPECT_EQ(errorOf("huge.pcd", pcd(kXyz, 1, "ascii", "1 2 1e39\n")),
            "'1e39' is not a float32 (field 'z') (line 11)");
  EXPECT_EQ(errorOf("label.pcd", pcd(kXyzLabel, 2, "ascii", "1 2 3 255\n1 2 3 256\n")),
            "'256' is not a uint8 (field 'label') (line 12)");
  EXPECT_EQ(errorOf("negative.pcd", pcd(kXyzLabel, 1, "ascii", "1 2 3 -1\n")),
            "'-1' is not a uint8 (field 'label') (line 11)");
  EXPECT_EQ(errorOf("nul.pcd", pcd(kXyz, 1, "ascii", std::string("1 2 3\0junk\n", 11))),
            "'3?junk' is not a float32 (field 'z') (line 11)");
}

TEST_F(ScanDataLinesTest, AsciiPcdLinesOfTheWrongLengthOrNumberAreRefused) {
  EXPECT_EQ(
      errorOf("short.pcd", pcd(kXyz, 2, "ascii", "1 2 3\n4 5\n6 7 8\n")),
      "a data line of 2 values, short of what the header declares for a point item (line 12)");
  EXPECT_EQ(errorOf("long.pcd", pcd(kXyz, 2, "ascii", "1 2 3 4\n5 6 7\n")),
            "more values than the header declares for a point item (line 11)");
  EXPECT_EQ(errorOf("extra.pcd", pcd(kXyz, 1, "ascii", "1 2 3\n4 5 6\n")),
            "more data lines than the header declares (line 12)");
  EXPECT_EQ(errorOf("cut.pcd", pcd(kXyz, 2, "ascii", "1 2 3\n4 5")),
            "truncated: a data line of 2 values, short of what the header declares for a point "
            "item (line 12)");
  EXPECT_EQ(errorOf("few.pcd", pcd(kXyz, 3, "ascii", "1 2 3\n4 5 6\n")),
            "truncated: header declares 3 points but the ascii data has 2 data lines (line 13)");
}

// Blank lines are skipped (PCL skips them too), so a blank line where a point was meant leaves
// the data a point short: that is not a truncated file, and the first blank line is named.
TEST_F(ScanDataLinesTest, ABlankLineWhereAPointWasMeantIsNamedNotCalledTruncated) {
  EXPECT_EQ(errorOf("blank.pcd", pcd(kXyz, 3, "ascii", "1 2 3\n\n7 8 9\n")),
            "header declares 3 points but the ascii data has 2 data lines and 1 blank line, which "
            "holds no point "
            "(line 12)");
  EXPECT_EQ(errorOf("blanks.pcd", pcd(kXyz, 4, "ascii", "1 2 3\n  \n7 8 9\r\n\r\n\n")),
            "header declares 4 points but the ascii data has 2 data lines and 3 blank lines, which "
            "hold no point "
            "(the first at line 12)");
}

TEST_F(ScanDataLinesTest, GoodAsciiPcdWithBlankLinesAndNanIsRead) {
  const Scan scan =
      loadScan(write("good.pcd", pcd(kXyz, 3, "ascii", "1 2 3\n\n+4 5e0 6\nnan 1 2\n\n")));
  ASSERT_EQ(scan.positions.size(), 2u);
  EXPECT_EQ(scan.positions[1], (std::array<float, 3>{4, 5, 6}));
  EXPECT_EQ(scan.dropped_non_finite, 1u);
}

TEST_F(ScanDataLinesTest, AsciiPlyValuesAndListsAreCheckedToo) {
  // PCL's PLY reader turned 'oops' into NaN: the point vanished without a word.
  EXPECT_EQ(errorOf("oops.ply", ply("1 2 3\n10.5 10.5 oops\n4 5 6\n3 0 1 2\n")),
            "'oops' is not a float32 (property 'z') (line 11)");
  EXPECT_EQ(errorOf("list.ply", ply("1 2 3\n1 2 3\n4 5 6\n3 0 1\n")),
            "a data line of 3 values, short of what the header declares for a face item (line 13)");
  EXPECT_EQ(errorOf("count.ply", ply("1 2 3\n1 2 3\n4 5 6\n-3 0 1 2\n")),
            "'-3' is not a list length, a uint8 (property 'vertex_indices') (line 13)");
  const Scan scan = loadScan(write("good.ply", ply("1 2 3\n1 2 4\n4 5 6\n3 0 1 2\n")));
  EXPECT_EQ(scan.positions.size(), 3u);
}

// 188 bytes whose POINTS and uncompressed size agree asked PCL for 8.4 GB: LZF turns one byte
// into at most 88, so the declared size is refused before anything is allocated.
TEST_F(ScanDataLinesTest, BinaryCompressedSizeBeyondLzfsRatioIsRefusedAtOnce) {
  const auto le32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16),
                       static_cast<char>(v >> 24)};
  };
  const int points = 357913941;  // x 12 bytes = 4294967292, just below 2^32
  const std::string body = le32(40) + le32(12u * points) + std::string(40, '\0');
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NE(errorOf("lzf.pcd", pcd(kXyz, points, "binary_compressed", body))
                .find("more than LZF's largest ratio (88x)"),
            std::string::npos);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  // At the bound itself the size is possible, and the data decides (here: truncated).
  const std::string at_bound = le32(36) + le32(88 * 36) + std::string(20, '\0');
  EXPECT_EQ(errorOf("bound.pcd", pcd(kXyz, 88 * 36 / 12, "binary_compressed", at_bound)),
            "truncated: header declares 36 bytes of compressed data, but 20 bytes follow (data at "
            "byte 136)");
}

}  // namespace
}  // namespace octopoint::prepare
