// COPC (codegen/copc_hierarchy.h, codegen/laz_reader.cpp): a COPC file written by the tests' own
// writer (tests/support/copc_octree.h) prepares like the same points as plain LAZ; a crop reads
// only the nodes it meets, and prepares to the same model as the crop of the plain file; a
// hierarchy that lies is refused with one line.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "codegen/model_writer.h"
#include "codegen/point_source.h"
#include "codegen/prepare_error.h"
#include "codegen/streamed_prepare.h"
#include "tests/support/expect_refused.h"
#include "tests/support/file_bytes.h"
#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

template <typename T>
void patchCopc(std::string& bytes, std::uint64_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

template <typename T>
T readCopc(const std::string& bytes, std::uint64_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

// The landscape's 1 km square (the LAS layout's origin at its corner), a tenth of it on each side.
constexpr std::array<double, 3> kCropLow = {500400, 4100400, -100};
constexpr std::array<double, 3> kCropHigh = {500500, 4100500, 300};

class CopcReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("octopoint_copc_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, bool copc, std::size_t count = 60000,
                 std::uint32_t node_points = 1500) {
    LasLayout layout;
    layout.format = 7;
    layout.varied_fields = true;
    layout.laz = true;
    layout.copc = copc;
    layout.laz_chunk_points = node_points;
    const fs::path path = dir_ / name;
    testing::LasWriter writer(path, layout);
    writer.addLandscape(landscape_, count);
    writer.finish();
    return path;
  }

  // The model of `path`, cropped or not; `bytes_read` gets what the source read of the file.
  static std::vector<std::uint8_t> model(const fs::path& path, bool crop, unsigned threads = 0,
                                         std::uint64_t* bytes_read = nullptr) {
    PrepareOptions options;
    options.name = "copc";
    options.depths = {5, 8};
    if (crop) options.crop = CropBox{kCropLow, kCropHigh};
    StreamOptions stream;
    stream.memory_bytes = 1 << 20;
    stream.threads = threads;
    const auto source = openPointSource(path);
    std::vector<std::uint8_t> image =
        serializeModel(prepareFromSource(*source, path.string(), options, stream));
    if (bytes_read) *bytes_read = source->bytesRead();
    return image;
  }

  fs::path writeBytes(const std::string& name, const std::string& bytes) {
    return testing::writeFileBytes(dir_, name, bytes);
  }

  // Opening `path` must fail with one line that names the file and contains `expected`.
  static void expectRefused(const fs::path& path, const std::string& expected) {
    testing::expectRefusedInOneLine(path, expected, [](const fs::path& p) { openPointSource(p); });
  }

  fs::path dir_;
  testing::Landscape landscape_;
};

TEST_F(CopcReaderTest, PreparesToTheSameModelAsThePlainLaz) {
  const fs::path copc = write("a.copc.laz", true);
  const fs::path plain = write("a.laz", false);
  const auto source = openPointSource(copc);
  EXPECT_EQ(source->info().format,
            "LAZ 1.4, point format 7, 36-byte records, layered, variable chunks, COPC, " +
                std::to_string(source->pieceCount()) + " nodes to level 3 in 9 hierarchy pages");
  const std::vector<std::uint8_t> expected = model(plain, false);
  EXPECT_EQ(model(copc, false, 1), expected);
  EXPECT_EQ(model(copc, false, 3), expected);
}

TEST_F(CopcReaderTest, ACropReadsOnlyTheNodesItMeetsAndMakesTheCropOfThePlainFile) {
  const fs::path copc = write("b.copc.laz", true);
  const fs::path plain = write("b.laz", false);
  std::uint64_t plain_read = 0;
  std::uint64_t copc_read = 0;
  const std::vector<std::uint8_t> expected = model(plain, true, 0, &plain_read);
  EXPECT_EQ(model(copc, true, 2, &copc_read), expected);
  EXPECT_EQ(model(copc, true, 1), expected);
  // A hundredth of the area: the nodes above it (the root and a few coarse ones) and the fine ones
  // it meets, against every chunk (read once: not cropped, the points are binned on the header's
  // box in one pass).
  std::uint64_t whole_read = 0;
  model(copc, false, 0, &whole_read);
  EXPECT_GT(whole_read, fs::file_size(copc) * 9 / 10);
  EXPECT_GT(plain_read, fs::file_size(plain));
  EXPECT_LT(copc_read, whole_read / 5) << copc_read << " of " << whole_read << " bytes read";
}

TEST_F(CopcReaderTest, ACropThatMeetsNoNodeIsRefused) {
  const fs::path copc = write("c.copc.laz", true, 5000);
  PrepareOptions options;
  options.name = "copc";
  options.crop = CropBox{{0, 0, 0}, {1, 1, 1}};
  try {
    prepareFromSource(*openPointSource(copc), copc.string(), options, StreamOptions{});
    ADD_FAILURE() << "a crop far from every point was prepared";
  } catch (const PrepareError& error) {
    EXPECT_NE(
        std::string(error.what()).find("no point of the 5000 points lies inside the crop box"),
        std::string::npos)
        << error.what();
  }
}

// The damages below patch a good COPC file: its info VLR (the first, at byte 375 + 54) and its
// root hierarchy page (with child pages: more than 16 nodes).
class CopcBadInputTest : public CopcReaderTest {
 protected:
  void SetUp() override {
    CopcReaderTest::SetUp();
    bytes_ = testing::fileBytes(write("good.copc.laz", true, 20000, 500));
    root_ = readCopc<std::uint64_t>(bytes_, kInfo + 40);
    root_bytes_ = readCopc<std::uint64_t>(bytes_, kInfo + 48);
  }
  // Entry `e` of the root page: its field at byte `field` (0 key, 16 offset, 24 bytes, 28 points).
  std::uint64_t entry(std::size_t e, std::size_t field) const { return root_ + 32 * e + field; }
  // The first child page entry (point count -1) of the root page.
  std::size_t childPageEntry() const {
    for (std::size_t e = 0; e < root_bytes_ / 32; ++e) {
      if (readCopc<std::int32_t>(bytes_, entry(e, 28)) == -1) return e;
    }
    ADD_FAILURE() << "no child page";
    return 0;
  }

  static constexpr std::uint64_t kInfo = 375 + 54;
  std::string bytes_;
  std::uint64_t root_ = 0;
  std::uint64_t root_bytes_ = 0;
};

TEST_F(CopcBadInputTest, TheGoodFileIsReadWithChildPages) {
  ASSERT_NO_THROW(openPointSource(writeBytes("ok.laz", bytes_)));
  EXPECT_GT(root_bytes_, 32u);
  EXPECT_LT(root_bytes_, 32u * 10);
  childPageEntry();
}

TEST_F(CopcBadInputTest, AnAbsurdRootCubeIsRefused) {
  std::string bytes = bytes_;
  patchCopc<double>(bytes, kInfo + 24, -1.0);
  expectRefused(writeBytes("half.laz", bytes), "absurd COPC root cube: half size -1");
  bytes = bytes_;
  patchCopc<double>(bytes, kInfo, std::nan(""));
  expectRefused(writeBytes("centre.laz", bytes), "absurd COPC root cube: centre nan");
}

TEST_F(CopcBadInputTest, PagesOutsideTheFileOrOfPartEntriesAreRefused) {
  std::string bytes = bytes_;
  patchCopc<std::uint64_t>(bytes, kInfo + 40, bytes.size() - 16);
  expectRefused(writeBytes("root_past.laz", bytes), "inside the file's");
  bytes = bytes_;
  patchCopc<std::uint64_t>(bytes, kInfo + 48, root_bytes_ - 1);
  expectRefused(writeBytes("root_part.laz", bytes), "whole 32-byte entries");
  bytes = bytes_;
  patchCopc<std::int32_t>(bytes, entry(childPageEntry(), 24), 1 << 30);
  expectRefused(writeBytes("child_past.laz", bytes), "a hierarchy page of 1073741824 bytes");
}

TEST_F(CopcBadInputTest, APageListedTwiceIsRefused) {
  // A child page that points back at the root page: a cycle.
  std::string bytes = bytes_;
  patchCopc<std::uint64_t>(bytes, entry(childPageEntry(), 16), root_);
  patchCopc<std::int32_t>(bytes, entry(childPageEntry(), 24),
                          static_cast<std::int32_t>(root_bytes_));
  expectRefused(writeBytes("cycle.laz", bytes), "is listed twice");
}

TEST_F(CopcBadInputTest, KeysOutsideTheOctreeOrThePageAreRefused) {
  std::string bytes = bytes_;
  patchCopc<std::int32_t>(bytes, entry(0, 0), 99);
  expectRefused(writeBytes("level.laz", bytes), "octree level 99 (0 to 24 are read)");
  bytes = bytes_;
  patchCopc<std::int32_t>(bytes, entry(childPageEntry(), 4), 2);
  expectRefused(writeBytes("cell.laz", bytes), "the key lies outside the octree");
  // A child page's first entry is its own node; move it under another node of level 1.
  const auto child = readCopc<std::uint64_t>(bytes_, entry(childPageEntry(), 16));
  bytes = bytes_;
  patchCopc<std::int32_t>(bytes, child + 4, 1 - readCopc<std::int32_t>(bytes_, child + 4));
  expectRefused(writeBytes("stray.laz", bytes), "is not under the page's node");
}

TEST_F(CopcBadInputTest, NodesThatDisagreeWithTheChunkTableAreRefused) {
  std::string bytes = bytes_;
  patchCopc<std::int32_t>(bytes, entry(0, 28), readCopc<std::int32_t>(bytes_, entry(0, 28)) + 1);
  expectRefused(writeBytes("count.laz", bytes), "the hierarchy gives the chunk");
  bytes = bytes_;
  patchCopc<std::uint64_t>(bytes, entry(0, 16), readCopc<std::uint64_t>(bytes_, entry(0, 16)) + 1);
  expectRefused(writeBytes("offset.laz", bytes), "the chunk table does not list");
  bytes = bytes_;
  patchCopc<std::uint64_t>(bytes, entry(0, 16), 1);
  expectRefused(writeBytes("outside.laz", bytes), "lies outside the point data");
  // The root node dropped (0 points): its chunk belongs to no node.
  bytes = bytes_;
  patchCopc<std::int32_t>(bytes, entry(0, 28), 0);
  expectRefused(writeBytes("dropped.laz", bytes), "nodes with points");
  // The root listed twice (the child page entry turned into the root's entry).
  bytes = bytes_;
  bytes.replace(entry(childPageEntry(), 0), 32, bytes_.substr(entry(0, 0), 32));
  expectRefused(writeBytes("twice.laz", bytes), "the node is listed twice");
}

TEST_F(CopcBadInputTest, EveryTruncationOfTheHierarchyIsRefusedWithOneLine) {
  for (std::uint64_t length = bytes_.size() - 1; length >= root_ - 64; length -= 5) {
    try {
      openPointSource(writeBytes("cut.laz", bytes_.substr(0, length)));
      ADD_FAILURE() << "a COPC file cut to " << length << " bytes was opened";
    } catch (const PrepareError& error) {
      ASSERT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace octopoint::prepare
