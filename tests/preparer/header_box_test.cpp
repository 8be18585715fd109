// One pass on the header's box (codegen/streamed_prepare.h): a LAS or LAZ file whose header states
// its points' box is read (a LAZ chunk decoded) once, binned on the cube of that box while the
// points' own bounds, intensities and colours are tallied; the model is the one the two passes
// give (StreamOptions::header_box = false), byte for byte, and a box that lies (too large, too
// small) or colours that are all 0 cost a second reading, never another model.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "codegen/intensity_grey.h"
#include "codegen/las_reader.h"
#include "codegen/model_writer.h"
#include "codegen/point_source.h"
#include "codegen/point_tally.h"
#include "codegen/streamed_prepare.h"
#include "tests/support/file_bytes.h"
#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;
using testing::LasLayout;
using testing::LasWriter;

class HeaderBoxTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("octopoint_box_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
    options_.name = "box";
    options_.depths = {5, 9};
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const LasLayout& layout, std::size_t count) {
    return testing::writeLandscapeScan(dir_ / name, layout, landscape_, count);
  }

  // The model of `path`; one pass on the header's box if `header_box` (and the file allows it).
  std::vector<std::uint8_t> model(const fs::path& path, bool header_box, unsigned threads = 2,
                                  PrepareSummary* summary = nullptr) {
    StreamOptions stream;
    stream.memory_bytes = 1 << 20;  // spilled: the bins of a wrong box are in a file too
    stream.threads = threads;
    stream.header_box = header_box;
    stream.temp_dir = dir_;
    return serializeModel(
        prepareFromSource(*openPointSource(path), path.string(), options_, stream, summary));
  }

  // The header's stated box of `path`, axis by axis, moved by `low` and `high` scan units.
  static void moveStatedBox(const fs::path& path, const std::array<double, 3>& low,
                            const std::array<double, 3>& high) {
    std::string bytes = testing::fileBytes(path);
    for (std::size_t axis = 0; axis < 3; ++axis) {
      for (const auto& [at, by] :
           {std::pair{179 + 16 * axis, high[axis]}, std::pair{187 + 16 * axis, low[axis]}}) {
        double value = 0;
        std::memcpy(&value, bytes.data() + at, 8);
        value += by;
        std::memcpy(bytes.data() + at, &value, 8);
      }
    }
    testing::writeFileBytes(path.parent_path(), path.filename().string(), bytes);
  }

  // Expects the model of `path` in one pass (read once) to be the two passes'.
  void expectReadOnce(const fs::path& path, const std::vector<std::uint8_t>& expected) {
    for (unsigned threads : {1u, 3u}) {
      PrepareSummary summary;
      EXPECT_EQ(model(path, true, threads, &summary), expected) << path << ", " << threads;
      EXPECT_EQ(summary.source_passes, 1u) << path;
      EXPECT_EQ(summary.decoded_kept_bytes, 0u) << path;
      EXPECT_EQ(summary.header_box_note, "") << path;
    }
  }

  // Expects the model of `path` to be the two passes' after the one pass was tried and dropped.
  void expectReadTwice(const fs::path& path, const std::vector<std::uint8_t>& expected,
                       const std::string& note) {
    PrepareSummary summary;
    EXPECT_EQ(model(path, true, 2, &summary), expected) << path;
    EXPECT_EQ(summary.source_passes, 2u) << path;
    EXPECT_NE(summary.header_box_note.find(note), std::string::npos) << summary.header_box_note;
  }

  fs::path dir_;
  testing::Landscape landscape_;
  PrepareOptions options_;
};

// LAZ decoded once, without a decoded copy, to its LAS twin's model (read in two passes): colour
// (point-wise, format 3), intensity alone (format 1: exact percentiles in one pass), layered
// (format 7), the axes turned.
TEST_F(HeaderBoxTest, LazIsDecodedOnceToTheModelItsLasTwinGivesInTwoPasses) {
  for (const auto& [format, axes] :
       {std::pair{3, ScanAxes::kYDown}, std::pair{3, ScanAxes::kYUp},
        std::pair{1, ScanAxes::kYDown}, std::pair{7, ScanAxes::kYUp}}) {
    options_.axes = axes;
    LasLayout layout;
    layout.format = format;
    layout.laz_chunk_points = 2500;
    const std::string name = "f" + std::to_string(format) + (axes == ScanAxes::kYUp ? "up" : "");
    const fs::path las = write(name + ".las", layout, 20000);
    layout.laz = true;
    const fs::path laz = write(name + ".laz", layout, 20000);
    const std::vector<std::uint8_t> expected = model(las, false);
    EXPECT_EQ(model(laz, false), expected);
    expectReadOnce(laz, expected);
    expectReadOnce(las, expected);
  }
}

// A header whose box lies: larger or smaller than the points (on one side or both), or off by
// less than the coordinate grid's step (snapped: it still holds). Not an error: readers use the
// box for nothing else, and writers leave it loose; the points' own bounds decide.
TEST_F(HeaderBoxTest, AHeaderBoxThatLiesCostsASecondDecodingNotAnotherModel) {
  LasLayout layout;
  layout.format = 3;
  layout.laz = true;
  layout.laz_chunk_points = 2500;
  const fs::path reference = write("true.laz", layout, 20000);
  const std::vector<std::uint8_t> expected = model(reference, false);
  struct Lie {
    const char* name;
    std::array<double, 3> low, high;
  };
  for (const Lie& lie :
       {Lie{"larger", {-10, 0, 0}, {0, 0, 0}}, Lie{"smaller", {0, 0, 0}, {0, 0, -5}},
        Lie{"larger_and_smaller", {0, -3, 0}, {0, -3, 0}},
        Lie{"larger_by_a_step", {0, 0, 0}, {0, 0.001, 0}}}) {
    const fs::path path = write(std::string(lie.name) + ".laz", layout, 20000);
    moveStatedBox(path, lie.low, lie.high);
    expectReadTwice(path, expected, "the header's box is not the points'");
  }
  const fs::path near = write("near.laz", layout, 20000);  // 0.4 of a grid step off: snapped
  moveStatedBox(near, {-0.0004, 0.0004, 0}, {0, 0, 0.0004});
  expectReadOnce(near, expected);
  // A header of zeros (as some writers leave it) is no box: two passes, the decoded copy kept.
  const fs::path zeros = write("zeros.laz", layout, 20000);
  std::string bytes = testing::fileBytes(zeros);
  std::memset(bytes.data() + 179, 0, 48);
  testing::writeFileBytes(dir_, "zeros.laz", bytes);
  PrepareSummary summary;
  EXPECT_EQ(model(zeros, true, 2, &summary), expected);
  EXPECT_EQ(summary.header_box_note, "");
  EXPECT_GT(summary.decoded_kept_bytes, 0u);
}

// Whether LAS colour is 8- or 16-bit is the whole file's choice, unknown while it is binned: a
// piece whose channels all lie at or below 255 is binned as 8-bit, marked, and made what the
// file's choice gives it at the end: the same colour in an 8-bit file, black in a 16-bit one.
TEST_F(HeaderBoxTest, ColourLooking8BitInAPieceOfA16BitFileIsShownAsTheTwoPassesShowIt) {
  LasLayout layout;
  layout.format = 2;
  const fs::path sixteen = write("sixteen.las", layout, 70000);  // two pieces of 65,536 records
  {  // the first piece's channels cut to their top bytes: each 0..255, most of them not 0
    std::string bytes = testing::fileBytes(sixteen);
    const std::size_t stride = LasWriter::recordLength(layout);
    std::uint32_t point_offset = 0;
    std::memcpy(&point_offset, bytes.data() + testing::las_offsets::kPointOffset, 4);
    for (std::size_t i = 0; i < 65536; ++i) {
      for (std::size_t ch = 0; ch < 3; ++ch) {
        char* at = bytes.data() + point_offset + i * stride + 20 + 2 * ch;
        std::uint16_t value = 0;
        std::memcpy(&value, at, 2);
        value = static_cast<std::uint16_t>(value >> 8);
        std::memcpy(at, &value, 2);
      }
    }
    testing::writeFileBytes(dir_, "sixteen.las", bytes);
  }
  expectReadOnce(sixteen, model(sixteen, false));
  layout.colour_16bit = false;
  const fs::path eight = write("eight.las", layout, 70000);
  expectReadOnce(eight, model(eight, false));
}

// Colour fields that are all 0 show the intensity instead, which the one pass did not bin.
TEST_F(HeaderBoxTest, ColoursThatAreAll0AreBinnedAgainAsIntensity) {
  LasLayout layout;
  layout.format = 3;
  layout.laz = true;
  layout.laz_chunk_points = 2500;
  const fs::path path = dir_ / "black.laz";
  {
    LasWriter writer(path, layout);
    for (std::size_t i = 0; i < 20000; ++i) {
      testing::LandscapePoint p = landscape_.point(i);
      p.rgb = {0, 0, 0};
      writer.add(p);
    }
    writer.finish();
  }
  expectReadTwice(path, model(path, false), "every colour channel is 0");
}

// The exact counts of 16-bit intensities give the range the two histogram passes give.
TEST(ExactIntensityTest, GivesTheTwoPassPercentiles) {
  std::mt19937 random(7);
  for (const std::uint32_t spread : {1u, 3u, 300u, 65536u}) {
    IntensityPercentiles two_pass;
    ExactIntensity exact;
    exact.start();
    std::vector<float> values;
    for (int i = 0; i < 5000; ++i) {
      values.push_back(static_cast<float>(random() % spread + (spread == 1 ? 700 : 0)));
    }
    for (float v : values) {
      two_pass.addCoarse(v);
      exact.add(v);
    }
    two_pass.finishCoarse();
    IntensityPercentiles fine = two_pass.forFinePass();
    for (float v : values) fine.addFine(v);
    two_pass.merge(fine);
    const IntensityRange want = two_pass.range();
    const IntensityRange got = exact.range();
    EXPECT_EQ(got.low, want.low) << spread;
    EXPECT_EQ(got.high, want.high) << spread;
  }
  EXPECT_EQ(ExactIntensity().range().high, 0.0f);
}

}  // namespace
}  // namespace octopoint::prepare
