// The LAS reader (codegen/las_reader.h): every point format read back exactly as written, the
// corners of the format (1.4 counts, 8- and 16-bit colour, VLRs, EVLRs, records longer than their
// format), and every kind of lying or cut header refused with one line before anything is read.
// The files are written by tests/support/las_writer.h and then damaged byte by byte.

#include "codegen/las_reader.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <utility>
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
using testing::Landscape;
using testing::LandscapePoint;
using testing::LasLayout;
using testing::LasWriter;
namespace las = testing::las_offsets;

std::string readAll(const fs::path& path) {
  std::string bytes(fs::file_size(path), '\0');
  std::ifstream(path, std::ios::binary)
      .read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return bytes;
}

template <typename T>
void patch(std::string& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

class LasReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("octopoint_las_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const LasLayout& layout, std::size_t count,
                 const LandscapePoint* override_point = nullptr) {
    const fs::path path = dir_ / name;
    LasWriter writer(path, layout);
    for (std::size_t i = 0; i < count; ++i)
      writer.add(override_point ? *override_point : landscape_.point(i));
    writer.finish();
    return path;
  }

  fs::path writeBytes(const std::string& name, const std::string& bytes) {
    return testing::writeFileBytes(dir_, name, bytes);
  }

  // Opening `path` must fail with one line that names the file and contains `expected`.
  static void expectRefused(const fs::path& path, const std::string& expected) {
    testing::expectRefusedInOneLine(path, expected, [](const fs::path& p) { openPointSource(p); });
  }

  std::vector<std::uint8_t> model(const fs::path& path, PrepareSummary* summary = nullptr) {
    PrepareOptions options;
    options.name = "las";
    options.depths = {6, 9};
    StreamOptions stream;
    stream.memory_bytes = 1 << 20;
    return serializeModel(
        prepareFromSource(*openPointSource(path), path.string(), options, stream, summary));
  }

  fs::path dir_;
  Landscape landscape_;
};

TEST_F(LasReaderTest, EveryPointFormatReadsBackWhatWasWritten) {
  constexpr std::size_t kPoints = 3000;
  for (int format = 0; format <= 10; ++format) {
    LasLayout layout;
    layout.format = format;
    const auto source =
        openPointSource(write("format" + std::to_string(format) + ".las", layout, kPoints));
    const SourceInfo& info = source->info();
    const bool colour =
        format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
    EXPECT_EQ(info.points, kPoints);
    EXPECT_EQ(info.payload, colour ? PointPayload::kRgb : PointPayload::kIntensity) << format;
    PointChunk chunk;
    source->read(0, kPoints, chunk);
    for (std::size_t i = 0; i < kPoints; ++i) {
      const LandscapePoint p = landscape_.point(i);
      for (std::size_t axis = 0; axis < 3; ++axis) {
        const double stored = static_cast<double>(std::lround(p.xyz[axis] / layout.scale[axis])) *
                                  layout.scale[axis] +
                              layout.offset[axis];
        ASSERT_EQ(chunk.xyz[i][axis], stored) << "format " << format << " point " << i;
      }
      ASSERT_EQ(chunk.intensity[i], p.intensity) << format;
      for (std::size_t ch = 0; colour && ch < 3; ++ch)
        ASSERT_EQ(chunk.rgb[i][ch], p.rgb[ch] * 257) << format;
    }
  }
}

TEST_F(LasReaderTest, EightBitColourInSixteenBitFieldsIsDetectedAndGivesTheSameModel) {
  LasLayout layout;
  layout.format = 3;
  PrepareSummary wide, narrow;
  const auto sixteen = model(write("16bit.las", layout, 20000), &wide);
  layout.colour_16bit = false;
  EXPECT_EQ(model(write("8bit.las", layout, 20000), &narrow), sixteen);  // v * 257 >> 8 == v
  EXPECT_EQ(wide.colour_note, "16-bit colour");
  EXPECT_EQ(narrow.colour_note, "8-bit colour in 16-bit fields");
  EXPECT_EQ(wide.shading, ScanShading::kColour);
}

TEST_F(LasReaderTest, VlrsEvlrsExtraBytesAndVersionsChangeNothing) {
  LasLayout plain;
  plain.format = 7;
  plain.vlrs = 0;
  const auto expected = model(write("plain.las", plain, 20000));
  LasLayout rich = plain;
  rich.vlrs = 5;
  rich.evlrs = 3;
  rich.extra_bytes = 13;
  EXPECT_EQ(model(write("rich.las", rich, 20000)), expected);
  // Format 2 carries the same colours and coordinates in every version from 1.0 to 1.4.
  LasLayout old = plain;
  old.format = 2;
  const auto format2 = model(write("v12.las", old, 20000));
  EXPECT_EQ(format2, expected);
  for (int minor : {0, 1, 3, 4}) {
    old.version_minor = minor;
    EXPECT_EQ(model(write("v1" + std::to_string(minor) + ".las", old, 20000)), format2) << minor;
  }
}

TEST_F(LasReaderTest, ExtendedPointCountOfLas14IsUsedAndMustAgreeWithTheLegacyOne) {
  LasLayout layout;
  layout.format = 6;  // 1.4: the legacy count is 0
  const fs::path path = write("f6.las", layout, 5000);
  std::string bytes = readAll(path);
  EXPECT_EQ(bytes[las::kLegacyCount], 0);
  EXPECT_EQ(openPointSource(path)->info().points, 5000u);
  layout.format = 1;  // formats 0-5 in 1.4 keep the legacy count too
  layout.version_minor = 4;
  bytes = readAll(write("f1.las", layout, 5000));
  patch<std::uint32_t>(bytes, las::kLegacyCount, 4999);
  expectRefused(writeBytes("lying_legacy.las", bytes),
                "legacy point count 4999 differs from the 1.4 point count 5000");
}

TEST_F(LasReaderTest, AllZeroColourFallsBackToTheIntensity) {
  LandscapePoint point = landscape_.point(7);
  point.rgb = {0, 0, 0};
  LasLayout layout;
  layout.format = 2;
  const fs::path path = dir_ / "black.las";
  {
    LasWriter writer(path, layout);
    for (std::size_t i = 0; i < 5000; ++i) {
      LandscapePoint p = landscape_.point(i);
      p.rgb = {0, 0, 0};
      writer.add(p);
    }
    writer.finish();
  }
  PrepareSummary summary;
  model(path, &summary);
  EXPECT_EQ(summary.shading, ScanShading::kIntensity);
}

// LAS coordinates are doubles far beyond float precision (a UTM northing of 4,100,000 m): a crop
// box there is compared in double, to the millimetre the file stores.
TEST_F(LasReaderTest, CropBoxWorksInSurveyCoordinates) {
  LasLayout layout;
  const fs::path path = write("utm.las", layout, 60000);
  PrepareOptions options;
  options.name = "las";
  options.depths = {8};
  // Rounded to float (0.5 m apart up there), the y bounds would move by 0.2 m.
  options.crop = CropBox{{500200.3, 4100300.3, 0}, {500600.3, 4100700.3, 1000}};
  PrepareSummary summary;
  prepareFromSource(*openPointSource(path), path.string(), options, StreamOptions{}, &summary);
  std::uint64_t inside = 0;
  for (std::size_t i = 0; i < 60000; ++i) {
    const LandscapePoint p = landscape_.point(i);
    bool in = true;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const double stored =
          static_cast<double>(std::lround(p.xyz[axis] / layout.scale[axis])) * layout.scale[axis] +
          layout.offset[axis];
      in = in && stored >= options.crop->low[axis] && stored <= options.crop->high[axis];
    }
    inside += in ? 1 : 0;
  }
  EXPECT_GT(inside, 1000u);
  EXPECT_EQ(summary.model_points, inside);
}

// Intensity is turned grey per point before summing; a voxel with more points than a thread's
// share of the budget is summed a buffer at a time. Both must agree with the all-in-memory run.
TEST_F(LasReaderTest, IntensityModelIsTheSameWhateverTheBudgetAndThreadCount) {
  LasLayout layout;
  layout.format = 1;
  const fs::path path = dir_ / "crowded.las";
  {
    LasWriter writer(path, layout);
    for (std::size_t i = 0; i < 20000; ++i) {
      LandscapePoint p = landscape_.point(i);
      if (i % 5 == 0) p.xyz = {500.0, 500.0, 80.0};  // 4000 returns from one spot
      writer.add(p);
    }
    writer.finish();
  }
  const auto source = openPointSource(path);
  PrepareOptions options;
  options.name = "las";
  options.depths = {3, 10};
  std::vector<std::uint8_t> expected;
  for (std::uint64_t memory : {std::uint64_t{1} << 30, std::uint64_t{1}}) {
    for (unsigned threads : {1u, 3u}) {
      StreamOptions stream;
      stream.memory_bytes = memory;
      stream.threads = threads;
      const auto image = serializeModel(prepareFromSource(*source, "crowded.las", options, stream));
      if (expected.empty()) expected = image;
      EXPECT_EQ(image, expected) << memory << " bytes, " << threads << " threads";
    }
  }
}

// A damaged header: what to write where, and the message expected.
struct Damage {
  const char* name;
  std::function<void(std::string&)> apply;
  const char* expected;
};

// Damage to the signature, the version, the compression and the point records' format and place.
std::vector<Damage> formatDamages() {
  return {
      {"signature", [](std::string& b) { b[0] = 'X'; }, "not a LAS file"},
      {"version 2.0",
       [](std::string& b) {
         b[24] = 2;
         b[25] = 0;
       },
       "LAS version 2.0 is not supported"},
      {"version 1.5", [](std::string& b) { b[25] = 5; }, "LAS version 1.5 is not supported"},
      {"laz bit", [](std::string& b) { b[las::kFormat] = static_cast<char>(0x87); },
       "the point format byte says LAZ (compressed), but no LASzip VLR"},
      {"format 11", [](std::string& b) { b[las::kFormat] = 11; }, "unknown point format 11"},
      {"format 7 in 1.2", [](std::string& b) { b[25] = 2; }, "point format 7 needs LAS 1.4"},
      {"short records", [](std::string& b) { patch<std::uint16_t>(b, las::kRecordLength, 30); },
       "shorter than format 7's 36"},
      {"small header", [](std::string& b) { patch<std::uint16_t>(b, las::kHeaderSize, 300); },
       "header size 300 is below"},
      {"points in header", [](std::string& b) { patch<std::uint32_t>(b, las::kPointOffset, 100); },
       "would start inside"},
      {"points past end",
       [](std::string& b) { patch<std::uint32_t>(b, las::kPointOffset, 4000000000u); },
       "truncated"},
  };
}

// Damage to the (E)VLRs, the point count, the scales and offsets; `points_end`: the offset after
// the last point record.
std::vector<Damage> extentDamages(std::uint64_t points_end) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {
      {"many vlrs", [](std::string& b) { patch<std::uint32_t>(b, las::kVlrCount, 70000); },
       "70000 VLRs, but only"},
      {"long vlr", [](std::string& b) { patch<std::uint16_t>(b, 375 + 20, 60000); },
       "runs into the point data"},
      {"count + 1",
       [](std::string& b) {
         patch<std::uint64_t>(b, las::kCount, 1001);
         patch<std::uint32_t>(b, las::kLegacyCount, 0);
       },
       "lies inside the point data"},
      {"count 2^64-1",
       [](std::string& b) {
         patch<std::uint64_t>(b, las::kCount, ~std::uint64_t{0});
         patch<std::uint32_t>(b, las::kLegacyCount, 0);
       },
       "truncated: header declares 18446744073709551615 points"},
      {"no points",
       [](std::string& b) {
         patch<std::uint64_t>(b, las::kCount, 0);
         patch<std::uint32_t>(b, las::kLegacyCount, 0);
       },
       "empty cloud"},
      {"scale 0", [](std::string& b) { patch<double>(b, las::kScale, 0.0); },
       "absurd X scale factor 0"},
      {"scale -1", [](std::string& b) { patch<double>(b, las::kScale + 8, -1.0); },
       "absurd Y scale factor -1"},
      {"scale 1e300", [](std::string& b) { patch<double>(b, las::kScale + 16, 1e300); },
       "absurd Z scale factor 1e+300"},
      {"scale NaN", [nan](std::string& b) { patch<double>(b, las::kScale, nan); },
       "absurd X scale factor nan"},
      {"offset NaN", [nan](std::string& b) { patch<double>(b, las::kOffset + 8, nan); },
       "absurd Y offset nan"},
      {"offset inf",
       [](std::string& b) {
         patch<double>(b, las::kOffset, std::numeric_limits<double>::infinity());
       },
       "absurd X offset inf"},
      {"offset 1e300", [](std::string& b) { patch<double>(b, las::kOffset + 16, 1e300); },
       "absurd Z offset 1e+300"},
      {"evlr inside points",
       [=](std::string& b) { patch<std::uint64_t>(b, las::kEvlrStart, points_end - 36); },
       "lies inside the point data"},
      {"many evlrs", [](std::string& b) { patch<std::uint32_t>(b, las::kEvlrCount, 1000000); },
       "1000000 EVLR"},
      {"long evlr",
       [=](std::string& b) { patch<std::uint64_t>(b, points_end + 20, ~std::uint64_t{0} / 2); },
       "truncated: the record declares"},
      {"count - 1",
       [](std::string& b) {
         patch<std::uint64_t>(b, las::kCount, 999);
         patch<std::uint32_t>(b, las::kLegacyCount, 0);
       },
       "between the last of the 999 points and the first EVLR"},
  };
}

TEST_F(LasReaderTest, HeadersThatLieAreRefusedWithOneLine) {
  LasLayout layout;
  layout.format = 7;
  layout.vlrs = 2;
  layout.evlrs = 2;
  const std::string good = readAll(write("good.las", layout, 1000));
  const std::uint64_t point_offset = 375 + 2 * (54 + 16);
  const std::uint64_t points_end = point_offset + 1000 * 36;
  std::vector<Damage> damages = formatDamages();
  for (Damage& damage : extentDamages(points_end)) damages.push_back(std::move(damage));
  for (const Damage& damage : damages) {
    std::string bytes = good;
    damage.apply(bytes);
    SCOPED_TRACE(damage.name);
    expectRefused(writeBytes("damaged.las", bytes), damage.expected);
  }
}

TEST_F(LasReaderTest, EveryTruncationIsRefused) {
  LasLayout layout;
  layout.format = 8;
  layout.vlrs = 1;
  layout.evlrs = 1;
  const std::string good = readAll(write("good.las", layout, 40));
  ASSERT_NO_THROW(openPointSource(dir_ / "good.las"));
  for (std::size_t length = 0; length < good.size(); ++length) {
    const fs::path path = writeBytes("cut.las", good.substr(0, length));
    EXPECT_THROW(openPointSource(path), PrepareError) << length;
  }
}

TEST_F(LasReaderTest, SparseTerabyteFilesAreRefusedWithoutReadingThem) {
  LasLayout layout;
  layout.format = 2;
  const fs::path path = write("sparse.las", layout, 100);
  // 1: a valid header and 100 points, then a terabyte of nothing.
  ASSERT_EQ(::truncate(path.c_str(), off_t{1} << 40), 0);
  expectRefused(path, "bytes follow the last of the 100 points");
  // 2: a header that declares the terabyte as points: holes, not point data.
  layout.version_minor = 4;
  std::string head = readAll(write("sparse2.las", layout, 100));
  const std::uint64_t offset = 375 + 54 + 16;
  const std::uint64_t count = ((std::uint64_t{1} << 40) - offset) / 26;
  patch<std::uint32_t>(head, las::kLegacyCount, 0);
  patch<std::uint64_t>(head, las::kCount, count);
  const fs::path big = writeBytes("sparse3.las", head);
  ASSERT_EQ(::truncate(big.c_str(), static_cast<off_t>(offset + count * 26)), 0);
  expectRefused(big, "the point data has a hole");
}

}  // namespace
}  // namespace octopoint::prepare
