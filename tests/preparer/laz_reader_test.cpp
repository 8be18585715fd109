// The LAZ reader (codegen/laz_reader.h) against the LAS reader: a LAZ file written by the tests'
// encoder (tests/support/laz_encoder.h) decodes to exactly the records of the LAS file written from
// the same points, for every point format the encoder writes, with extra bytes, every field varied,
// fixed chunks of any size and variable ones, read in the reader's own pieces or in ranges that
// cross chunks; and it prepares to the same model, byte for byte, on any number of threads.

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "codegen/las_reader.h"
#include "codegen/model_writer.h"
#include "codegen/point_source.h"
#include "codegen/prepare_error.h"
#include "codegen/streamed_prepare.h"
#include "tests/support/expect_refused.h"
#include "tests/support/file_bytes.h"
#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"
#include "tests/support/laz_encoder.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;
using testing::Landscape;
using testing::LasLayout;
using testing::LasWriter;

class LazReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("octopoint_laz_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const LasLayout& layout, std::size_t count) {
    return testing::writeLandscapeScan(dir_ / name, layout, landscape_, count);
  }

  // The LAS and the LAZ file of the same points and layout.
  std::pair<fs::path, fs::path> twins(const std::string& name, LasLayout layout,
                                      std::size_t count) {
    layout.laz = false;
    const fs::path las = write(name + ".las", layout, count);
    layout.laz = true;
    return {las, write(name + ".laz", layout, count)};
  }

  // Every record of `path`, read piece by piece as the preparer does, every field decoded.
  static std::vector<std::uint8_t> records(const fs::path& path, std::size_t* pieces = nullptr) {
    const auto source = openLasSource(path, RecordFields::all());
    std::vector<std::uint8_t> all;
    PointChunk chunk;
    std::uint64_t next = 0;
    for (std::size_t i = 0; i < source->pieceCount(); ++i) {
      const PointRange piece = source->piece(i);
      EXPECT_EQ(piece.first, next);  // the pieces cover the records in order, once
      next += piece.count;
      source->read(piece.first, piece.count, chunk);
      all.insert(all.end(), chunk.raw.begin(), chunk.raw.end());
    }
    EXPECT_EQ(next, source->info().points);
    if (pieces) *pieces = source->pieceCount();
    return all;
  }

  std::vector<std::uint8_t> model(const fs::path& path, unsigned threads = 0) {
    PrepareOptions options;
    options.name = "laz";
    options.depths = {6, 9};
    StreamOptions stream;
    stream.memory_bytes = 1 << 20;
    stream.threads = threads;
    return serializeModel(
        prepareFromSource(*openPointSource(path), path.string(), options, stream));
  }

  fs::path writeBytes(const std::string& name, const std::string& bytes) {
    return testing::writeFileBytes(dir_, name, bytes);
  }

  // Opening and reading every record of `path` must fail with one line that names the file and
  // contains `expected`.
  static void expectRefused(const fs::path& path, const std::string& expected) {
    testing::expectRefusedInOneLine(path, expected, [](const fs::path& p) { records(p); });
  }

  fs::path dir_;
  Landscape landscape_;
};

// A small LAZ file and where its parts lie.
struct LazParts {
  std::string bytes;
  std::uint64_t point_offset;  // the chunk table pointer, then the chunks
  std::uint64_t table;         // the chunk table
};

template <typename T>
void patchAt(std::string& bytes, std::uint64_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

template <typename T>
T readAt(const std::string& bytes, std::uint64_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

TEST_F(LazReaderTest, EveryFormatDecodesToTheRecordsOfItsLasTwin) {
  // 0 to 3 point-wise, 6 to 8 layered (several scanner channels, every layer changing)
  for (int format : {0, 1, 2, 3, 6, 7, 8}) {
    for (int extra_bytes : {0, 5}) {
      LasLayout layout;
      layout.format = format;
      layout.extra_bytes = extra_bytes;
      layout.varied_fields = true;
      layout.laz_chunk_points = 5000;
      const auto [las, laz] = twins("f" + std::to_string(format), layout, 12345);
      std::size_t pieces = 0;
      const std::vector<std::uint8_t> decoded = records(laz, &pieces);
      EXPECT_EQ(pieces, 3u);  // the reader reads its chunks whole: 5000, 5000, 2345
      ASSERT_TRUE(decoded == records(las))
          << "format " << format << ", extra bytes " << extra_bytes;
      EXPECT_LT(fs::file_size(laz), fs::file_size(las) * 3 / 4) << format;  // it did compress
    }
  }
}

TEST_F(LazReaderTest, ChunksOfAnySizeFixedOrVariableDecodeTheSame) {
  for (int format : {3, 8}) {  // point-wise and layered
    LasLayout layout;
    layout.format = format;
    layout.extra_bytes = format == 8 ? 2 : 0;
    layout.varied_fields = true;
    const auto [las, reference] = twins("chunks", layout, 4000);
    const std::vector<std::uint8_t> expected = records(las);
    for (std::uint32_t chunk_points : {1u, 2u, 3u, 999u, 4000u, 50000u}) {
      for (bool variable : {false, true}) {
        layout.laz = true;
        layout.laz_chunk_points = chunk_points;
        layout.laz_variable_chunks = variable;
        const fs::path laz = write("c.laz", layout, 4000);
        EXPECT_TRUE(records(laz) == expected)
            << "format " << format << ", " << chunk_points << (variable ? " variable" : " fixed");
      }
    }
  }
}

TEST_F(LazReaderTest, RangesAcrossChunksReadTheSameRecords) {
  for (int format : {1, 7}) {
    LasLayout layout;
    layout.format = format;
    layout.varied_fields = true;
    layout.laz_chunk_points = 700;
    const auto [las, laz] = twins("ranges", layout, 5000);
    const auto las_source = openPointSource(las);
    const auto laz_source = openLasSource(laz, RecordFields::all());
    PointChunk want, got;
    std::mt19937 random(3);
    for (int i = 0; i < 40; ++i) {
      const std::uint64_t first = random() % 5000;
      const std::size_t count = 1 + random() % (5000 - first);
      las_source->read(first, count, want);
      laz_source->read(first, count, got);
      ASSERT_TRUE(got.raw == want.raw) << format << ": " << first << " + " << count;
      ASSERT_EQ(got.xyz, want.xyz);
      ASSERT_EQ(got.rgb, want.rgb);
      ASSERT_EQ(got.intensity, want.intensity);
    }
  }
}

TEST_F(LazReaderTest, PreparesToTheSameModelAsItsLasTwinOnAnyThreads) {
  LasLayout layout;
  layout.format = 3;
  layout.laz_chunk_points = 3000;
  const auto [las, laz] = twins("model", layout, 30000);
  const std::vector<std::uint8_t> expected = model(las);
  EXPECT_EQ(model(laz, 1), expected);
  EXPECT_EQ(model(laz, 3), expected);
  const auto source = openPointSource(laz);
  EXPECT_EQ(source->info().format,
            "LAZ 1.2, point format 3, 34-byte records, point-wise, chunks of 3000");
}

// Pass 1 keeps the decoded points on disk and pass 2 reads them back (codegen/decoded_points.h):
// the model is the one decoding twice gives, with a crop and turned axes (which pass 1 applies to
// its points in place) too; a LAS file is read twice, as it costs no decoding.
TEST_F(LazReaderTest, DecodedOnceItPreparesTheModelDecodingTwiceGives) {
  LasLayout layout;
  layout.format = 3;  // colour and intensity: 34 bytes a point kept
  layout.laz_chunk_points = 2500;
  const auto [las, laz] = twins("once", layout, 20000);
  PrepareOptions options;
  options.name = "once";
  options.depths = {5, 8};
  options.axes = ScanAxes::kYUp;
  const LasLayout placed;  // the west half of the landscape, where the writer places it
  options.crop = CropBox{{placed.offset[0], -1e7, -1e7},
                         {placed.offset[0] + testing::kLandscapeSize / 2, 1e8, 1e7}};
  const auto prepared = [&](const fs::path& path, bool decode_once, PrepareSummary* summary,
                            const fs::path& temp_dir = {}) {
    StreamOptions stream;
    stream.memory_bytes = temp_dir.empty() ? 1 << 20 : 64 << 20;  // the latter needs no spill
    stream.threads = 2;
    stream.decode_once = decode_once;
    stream.temp_dir = temp_dir;
    return serializeModel(
        prepareFromSource(*openPointSource(path), path.string(), options, stream, summary));
  };
  PrepareSummary twice, once, plain, nowhere;
  const std::vector<std::uint8_t> expected = prepared(laz, false, &twice);
  EXPECT_EQ(prepared(laz, true, &once), expected);
  EXPECT_EQ(prepared(las, true, &plain), expected);
  // No temporary directory, and points that fit the budget: decoded twice, as before.
  EXPECT_EQ(prepared(laz, true, &nowhere, dir_ / "missing"), expected);
  EXPECT_EQ(twice.decoded_kept_bytes, 0u);
  EXPECT_EQ(once.decoded_kept_bytes, 20000u * 34);
  EXPECT_EQ(plain.decoded_kept_bytes, 0u);
  EXPECT_EQ(nowhere.decoded_kept_bytes, 0u);
}

TEST_F(LazReaderTest, LayeredPreparesToTheSameModelAsItsLasTwinOnAnyThreads) {
  LasLayout layout;
  layout.format = 8;
  layout.varied_fields = true;
  layout.laz_chunk_points = 3000;
  const auto [las, laz] = twins("layered_model", layout, 30000);
  const std::vector<std::uint8_t> expected = model(las);
  EXPECT_EQ(model(laz, 1), expected);
  EXPECT_EQ(model(laz, 3), expected);
  EXPECT_EQ(openPointSource(laz)->info().format,
            "LAZ 1.4, point format 8, 38-byte records, layered, chunks of 3000");
}

LazParts smallLaz(const fs::path& path) {
  LazParts parts;
  parts.bytes = testing::fileBytes(path);
  parts.point_offset = readAt<std::uint32_t>(parts.bytes, 96);
  parts.table = readAt<std::uint64_t>(parts.bytes, parts.point_offset);
  return parts;
}

class LazBadInputTest : public LazReaderTest {
 protected:
  // 3000 points of `format` in chunks of 1000, every field varied; notes the chunks' sizes.
  fs::path good(int format = 3) {
    LasLayout layout;
    layout.format = format;
    layout.varied_fields = true;
    layout.laz = true;
    layout.laz_chunk_points = 1000;
    const fs::path path = dir_ / ("good" + std::to_string(format) + ".laz");
    LasWriter writer(path, layout);
    writer.addLandscape(landscape_, 3000);
    writer.finish();
    chunk_bytes_ = writer.lazChunkBytes();
    return path;
  }

  // `parts` with its chunk table replaced by one listing these chunk sizes.
  static std::string withTable(const LazParts& parts, const std::vector<std::uint64_t>& points,
                               const std::vector<std::uint64_t>& bytes, bool variable) {
    const std::vector<std::uint8_t> table = testing::lazChunkTable(points, bytes, variable);
    return parts.bytes.substr(0, parts.table) + std::string(table.begin(), table.end());
  }

  // A byte flipped every `step` bytes from `from` to the chunk table, one file each: each read
  // whole or refused with one line (never a crash, a hang or a second line). Returns how many
  // were refused, of how many.
  std::pair<std::size_t, std::size_t> flipEvery(const LazParts& parts, std::uint64_t from,
                                                std::uint64_t step) {
    std::size_t refused = 0;
    std::size_t flips = 0;
    for (std::uint64_t at = from; at < parts.table; at += step) {
      std::string bytes = parts.bytes;
      bytes[at] = static_cast<char>(bytes[at] ^ 0x5a);
      ++flips;
      try {
        records(writeBytes("flip.laz", bytes));
      } catch (const PrepareError& error) {
        EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
        ++refused;
      }
    }
    return {refused, flips};
  }

  std::vector<std::uint64_t> chunk_bytes_;
};

TEST_F(LazBadInputTest, EveryTruncationIsRefusedWithOneLine) {
  const LazParts parts = smallLaz(good());
  ASSERT_NO_THROW(records(good()));
  // Every length in the chunk table and around the chunks' starts; a stride through the rest.
  for (std::uint64_t length = parts.point_offset; length < parts.bytes.size();
       length += length + 64 >= parts.table && length < parts.point_offset + 64 ? 1
                 : length + 64 >= parts.table                                   ? 1
                                                                                : 29) {
    const fs::path cut = writeBytes("cut.laz", parts.bytes.substr(0, length));
    try {
      records(cut);
      ADD_FAILURE() << "a LAZ file cut to " << length << " of " << parts.bytes.size()
                    << " bytes was read";
    } catch (const PrepareError& error) {
      ASSERT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    }
  }
}

TEST_F(LazBadInputTest, AMissingChunkTableIsRefused) {
  const LazParts parts = smallLaz(good());
  std::string interrupted = parts.bytes.substr(0, parts.table);
  patchAt<std::int64_t>(interrupted, parts.point_offset,
                        static_cast<std::int64_t>(parts.point_offset));
  expectRefused(writeBytes("interrupted.laz", interrupted), "no chunk table");
  std::string at_end = parts.bytes;  // -1: the pointer is in the file's last 8 bytes, here garbage
  patchAt<std::int64_t>(at_end, parts.point_offset, -1);
  expectRefused(writeBytes("at_end.laz", at_end), "lies outside the point data");
  std::string past_end = parts.bytes;
  patchAt<std::int64_t>(past_end, parts.point_offset, 1ll << 50);
  expectRefused(writeBytes("past_end.laz", past_end), "lies outside the point data");
  std::string version = parts.bytes;
  patchAt<std::uint32_t>(version, parts.table, 7);
  expectRefused(writeBytes("version.laz", version), "unknown chunk table version 7");
}

TEST_F(LazBadInputTest, AChunkTableThatLiesIsRefused) {
  const LazParts parts = smallLaz(good());
  const std::vector<std::uint64_t> sizes = chunk_bytes_;
  ASSERT_EQ(sizes.size(), 3u);
  ASSERT_EQ(withTable(parts, {1000, 1000, 1000}, sizes, false), parts.bytes);  // the true table
  const auto lie = [&](const std::string& name, std::vector<std::uint64_t> points,
                       std::vector<std::uint64_t> bytes, bool variable,
                       const std::string& expected) {
    expectRefused(writeBytes(name, withTable(parts, points, bytes, variable)), expected);
  };
  // A chunk one byte longer or shorter: each chunk's code must end where the table says.
  lie("longer.laz", {1000, 1000, 1000}, {sizes[0] + 1, sizes[1] - 1, sizes[2]}, false,
      "corrupt LAZ");
  lie("shorter.laz", {1000, 1000, 1000}, {sizes[0] - 1, sizes[1] + 1, sizes[2]}, false,
      "corrupt LAZ");
  lie("too_few.laz", {1000, 1000}, {sizes[0], sizes[1]}, false, "the chunk table lists 2");
  lie("beyond.laz", {1000, 1000, 1000}, {sizes[0], sizes[1], sizes[2] + 100}, false,
      "does not fit between");
  lie("zero_bytes.laz", {1000, 1000, 1000}, {0, sizes[1], sizes[2]}, false, "a chunk of 0 bytes");
}

TEST_F(LazBadInputTest, MorePointsDeclaredThanTheChunksHoldIsRefused) {
  LasLayout layout;
  layout.format = 1;
  layout.laz = true;
  layout.laz_chunk_points = 1000;
  layout.laz_variable_chunks = true;  // the table's counts must add up to the header's
  const fs::path path = write("variable.laz", layout, 2500);
  ASSERT_NO_THROW(records(path));
  std::string bytes = testing::fileBytes(path);
  patchAt<std::uint32_t>(bytes, 107, 2600);
  expectRefused(writeBytes("more.laz", bytes), "the header declares 2600 points, the");
  patchAt<std::uint32_t>(bytes, 107, 2400);
  expectRefused(writeBytes("fewer.laz", bytes), "the header declares 2400 points, the");
  layout.laz_variable_chunks = false;  // fixed chunks: the count of chunks must fit the points
  bytes = testing::fileBytes(write("fixed.laz", layout, 2500));
  patchAt<std::uint32_t>(bytes, 107, 3001);
  expectRefused(writeBytes("fixed_more.laz", bytes), "which take 4 chunks of 1000");
}

TEST_F(LazBadInputTest, CorruptArithmeticCodeIsRefusedOrDecodesToPoints) {
  // A flipped byte in a chunk's code: the chunk's code no longer ends where it should (or decodes
  // to other points, as any arithmetic code may); never a crash, a hang or a second line.
  const LazParts parts = smallLaz(good());
  const auto [refused, flips] = flipEvery(parts, parts.point_offset + 8 + 40, 97);
  EXPECT_GT(refused, flips * 9 / 10) << refused << " of " << flips;
}

TEST_F(LazBadInputTest, UnknownItemsAndCompressorsAreRefusedByName) {
  const LazParts parts = smallLaz(good());
  // LASzip's VLR: after the 54-byte VLR header; its items start 34 bytes in, 6 bytes each.
  const std::uint64_t vlr = parts.bytes.find("laszip encoded") - 2 + 54;
  const auto damaged = [&](std::uint64_t at, std::uint16_t value) {
    std::string bytes = parts.bytes;
    patchAt<std::uint16_t>(bytes, at, value);
    return bytes;
  };
  expectRefused(writeBytes("version9.laz", damaged(vlr + 34 + 4, 9)),
                "unknown LAZ item POINT10 version 9");
  expectRefused(writeBytes("gps3.laz", damaged(vlr + 34 + 6 + 4, 3)),
                "unknown LAZ item GPSTIME11 version 3");
  expectRefused(writeBytes("type.laz", damaged(vlr + 34 + 12, 77)), "item type 77");
  expectRefused(writeBytes("compressor.laz", damaged(vlr, 9)), "unknown LASzip compressor 9");
  expectRefused(writeBytes("layered.laz", damaged(vlr, 3)),
                "LASzip compressor 3 for point format 3: formats 0 to 5 are read point-wise");
  expectRefused(writeBytes("items.laz", damaged(vlr + 32, 40)), "the VLR lists 40 items");
  expectRefused(writeBytes("chunk_huge.laz",
                           [&] {
                             std::string bytes = parts.bytes;
                             patchAt<std::uint32_t>(bytes, vlr + 12, 1u << 30);
                             return bytes;
                           }()),
                "chunks of 1073741824 points are not read");
}

// A layered chunk: the first point raw (record bytes), the point count, a 32-bit size per layer,
// the layers. good() here is 3000 points of format 7 (POINT14's 9 layers, RGB14's 1) in chunks of
// 1000.
class LazLayeredBadInputTest : public LazBadInputTest {
 protected:
  static constexpr std::uint64_t kRecord = 36;
  static constexpr std::uint64_t kLayers = 10;

  fs::path goodLayered() { return good(7); }
  // Where the first chunk's layer sizes start.
  static std::uint64_t sizesAt(const LazParts& parts) {
    return parts.point_offset + 8 + kRecord + 4;
  }
  static std::vector<std::uint32_t> layerSizes(const LazParts& parts) {
    std::vector<std::uint32_t> sizes;
    for (std::uint64_t i = 0; i < kLayers; ++i)
      sizes.push_back(readAt<std::uint32_t>(parts.bytes, sizesAt(parts) + 4 * i));
    return sizes;
  }
};

TEST_F(LazLayeredBadInputTest, ALayerSizeThatLiesIsRefused) {
  const LazParts parts = smallLaz(goodLayered());
  ASSERT_NO_THROW(records(goodLayered()));
  const std::vector<std::uint32_t> sizes = layerSizes(parts);
  ASSERT_GT(sizes[1], 4u);  // the z layer is there: z changes
  const auto lie = [&](const std::string& name, std::uint64_t layer, std::uint32_t size,
                       const std::string& expected) {
    std::string bytes = parts.bytes;
    patchAt<std::uint32_t>(bytes, sizesAt(parts) + 4 * layer, size);
    expectRefused(writeBytes(name, bytes), expected);
  };
  // More bytes than the chunk has left: refused before any layer is read.
  lie("huge_layer.laz", 0, 1000000000u, "layer 1 of 10 has 1000000000 bytes");
  lie("huge_z.laz", 1, 0xffffffffu, "layer 2 of 10 has 4294967295 bytes");
  // Sizes that add up to less than the chunk.
  lie("short_layer.laz", 9, sizes[9] - 1, "its layers end after");
  // Sizes that add up but cut the layers elsewhere: a layer's code runs past its bytes or ends
  // before them.
  {
    std::string bytes = parts.bytes;
    patchAt<std::uint32_t>(bytes, sizesAt(parts) + 4, sizes[1] - 3);
    patchAt<std::uint32_t>(bytes, sizesAt(parts) + 8, sizes[2] + 3);
    expectRefused(writeBytes("shifted.laz", bytes), "corrupt LAZ: the POINT14 layer z");
  }
  // A chunk whose point count is not the chunk table's.
  std::string count = parts.bytes;
  patchAt<std::uint32_t>(count, parts.point_offset + 8 + kRecord, 999);
  expectRefused(writeBytes("count.laz", count), "the chunk says it has 999 points");
}

TEST_F(LazLayeredBadInputTest, ATruncatedLayerIsRefused) {
  // The z layer of the first chunk cut short by 5 bytes, its size and the chunk table telling the
  // truth about the cut: the layer's code runs out.
  const LazParts parts = smallLaz(goodLayered());
  const std::vector<std::uint32_t> sizes = layerSizes(parts);
  const std::uint64_t z_end = sizesAt(parts) + 4 * kLayers + sizes[0] + sizes[1];
  std::string cut_bytes = parts.bytes.substr(0, z_end - 5) + parts.bytes.substr(z_end);
  patchAt<std::uint32_t>(cut_bytes, sizesAt(parts) + 4, sizes[1] - 5);
  const std::vector<std::uint64_t> chunk_bytes = {chunk_bytes_[0] - 5, chunk_bytes_[1],
                                                  chunk_bytes_[2]};
  LazParts cut = parts;
  cut.bytes = cut_bytes;
  cut.table = parts.table - 5;
  patchAt<std::uint64_t>(cut.bytes, parts.point_offset, cut.table);
  expectRefused(writeBytes("cut_layer.laz", withTable(cut, {1000, 1000, 1000}, chunk_bytes, false)),
                "corrupt LAZ: the POINT14 layer z");
  // A chunk table that ends the first chunk inside its head (the point count, the layer sizes)
  // or its layers, the rest given to the second chunk: the first is refused.
  for (std::uint64_t size = kRecord; size < kRecord + 4 + 4 * kLayers + 40; size += 3) {
    const std::string bytes =
        withTable(parts, {1000, 1000, 1000},
                  {size, chunk_bytes_[0] + chunk_bytes_[1] - size, chunk_bytes_[2]}, false);
    expectRefused(writeBytes("head.laz", bytes), "corrupt LAZ");
  }
}

TEST_F(LazLayeredBadInputTest, CorruptLayerStreamsAreRefusedOrDecodeToPoints) {
  const LazParts parts = smallLaz(goodLayered());
  const auto [refused, flips] = flipEvery(parts, sizesAt(parts) + 4 * kLayers, 61);
  EXPECT_GT(refused, flips * 3 / 4) << refused << " of " << flips;
}

}  // namespace
}  // namespace octopoint::prepare
