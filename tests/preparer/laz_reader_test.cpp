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

#include "codegen/model_writer.h"
#include "codegen/point_source.h"
#include "codegen/prepare_error.h"
#include "codegen/streamed_prepare.h"
#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"
#include "tests/support/laz_encoder.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;
using testing::Landscape;
using testing::LasLayout;
using testing::LasWriter;

std::string lazFileBytes(const fs::path& path) {
  std::string bytes(fs::file_size(path), '\0');
  std::ifstream(path, std::ios::binary)
      .read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return bytes;
}

class LazReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("octopoint_laz_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const LasLayout& layout, std::size_t count) {
    const fs::path path = dir_ / name;
    LasWriter writer(path, layout);
    for (std::size_t i = 0; i < count; ++i) writer.add(landscape_.point(i));
    writer.finish();
    return path;
  }

  // The LAS and the LAZ file of the same points and layout.
  std::pair<fs::path, fs::path> twins(const std::string& name, LasLayout layout,
                                      std::size_t count) {
    layout.laz = false;
    const fs::path las = write(name + ".las", layout, count);
    layout.laz = true;
    return {las, write(name + ".laz", layout, count)};
  }

  // Every record of `path`, read piece by piece as the preparer does.
  static std::vector<std::uint8_t> records(const fs::path& path, std::size_t* pieces = nullptr) {
    const auto source = openPointSource(path);
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
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  // Opening and reading every record of `path` must fail with one line that names the file and
  // contains `expected`.
  static void expectRefused(const fs::path& path, const std::string& expected) {
    try {
      records(path);
      ADD_FAILURE() << path << " was read; expected '" << expected << "'";
    } catch (const PrepareError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(expected), std::string::npos) << message;
      EXPECT_EQ(message.rfind(path.string(), 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
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
  for (int format = 0; format <= 3; ++format) {
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
  LasLayout layout;
  layout.format = 3;
  layout.varied_fields = true;
  const auto [las, reference] = twins("chunks", layout, 4000);
  const std::vector<std::uint8_t> expected = records(las);
  for (std::uint32_t chunk_points : {1u, 2u, 3u, 999u, 4000u, 50000u}) {
    for (bool variable : {false, true}) {
      layout.laz = true;
      layout.laz_chunk_points = chunk_points;
      layout.laz_variable_chunks = variable;
      const fs::path laz = write("c.laz", layout, 4000);
      EXPECT_TRUE(records(laz) == expected) << chunk_points << (variable ? " variable" : " fixed");
    }
  }
}

TEST_F(LazReaderTest, RangesAcrossChunksReadTheSameRecords) {
  LasLayout layout;
  layout.format = 1;
  layout.varied_fields = true;
  layout.laz_chunk_points = 700;
  const auto [las, laz] = twins("ranges", layout, 5000);
  const auto las_source = openPointSource(las);
  const auto laz_source = openPointSource(laz);
  PointChunk want, got;
  std::mt19937 random(3);
  for (int i = 0; i < 40; ++i) {
    const std::uint64_t first = random() % 5000;
    const std::size_t count = 1 + random() % (5000 - first);
    las_source->read(first, count, want);
    laz_source->read(first, count, got);
    ASSERT_TRUE(got.raw == want.raw) << first << " + " << count;
    ASSERT_EQ(got.xyz, want.xyz);
    ASSERT_EQ(got.rgb, want.rgb);
    ASSERT_EQ(got.intensity, want.intensity);
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

LazParts smallLaz(const fs::path& path) {
  LazParts parts;
  parts.bytes = lazFileBytes(path);
  parts.point_offset = readAt<std::uint32_t>(parts.bytes, 96);
  parts.table = readAt<std::uint64_t>(parts.bytes, parts.point_offset);
  return parts;
}

class LazBadInputTest : public LazReaderTest {
 protected:
  // 3000 points of format 3 in chunks of 1000, every field varied; notes the chunks' sizes.
  fs::path good() {
    LasLayout layout;
    layout.format = 3;
    layout.varied_fields = true;
    layout.laz = true;
    layout.laz_chunk_points = 1000;
    const fs::path path = dir_ / "good.laz";
    LasWriter writer(path, layout);
    for (std::size_t i = 0; i < 3000; ++i) writer.add(landscape_.point(i));
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
  std::string bytes = lazFileBytes(path);
  patchAt<std::uint32_t>(bytes, 107, 2600);
  expectRefused(writeBytes("more.laz", bytes), "the header declares 2600 points, the");
  patchAt<std::uint32_t>(bytes, 107, 2400);
  expectRefused(writeBytes("fewer.laz", bytes), "the header declares 2400 points, the");
  layout.laz_variable_chunks = false;  // fixed chunks: the count of chunks must fit the points
  bytes = lazFileBytes(write("fixed.laz", layout, 2500));
  patchAt<std::uint32_t>(bytes, 107, 3001);
  expectRefused(writeBytes("fixed_more.laz", bytes), "which take 4 chunks of 1000");
}

TEST_F(LazBadInputTest, CorruptArithmeticCodeIsRefusedOrDecodesToPoints) {
  // A flipped byte in a chunk's code: the chunk's code no longer ends where it should (or decodes
  // to other points, as any arithmetic code may); never a crash, a hang or a second line.
  const LazParts parts = smallLaz(good());
  std::size_t refused = 0;
  std::size_t flips = 0;
  for (std::uint64_t at = parts.point_offset + 8 + 40; at < parts.table; at += 97) {
    std::string bytes = parts.bytes;
    bytes[at] = static_cast<char>(bytes[at] ^ 0x5a);
    ++flips;
    try {
      records(writeBytes("flip.laz", bytes));
    } catch (const PrepareError& error) {
      ASSERT_EQ(std::string(error.what()).find('\n'), std::string::npos);
      ++refused;
    }
  }
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
                "layered compressor (LAS 1.4 items version 3) is not read yet");
  expectRefused(writeBytes("items.laz", damaged(vlr + 32, 40)), "the VLR lists 40 items");
  expectRefused(writeBytes("chunk_huge.laz",
                           [&] {
                             std::string bytes = parts.bytes;
                             patchAt<std::uint32_t>(bytes, vlr + 12, 1u << 30);
                             return bytes;
                           }()),
                "chunks of 1073741824 points are not read");
}

}  // namespace
}  // namespace octopoint::prepare
