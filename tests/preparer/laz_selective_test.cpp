// Selective decoding of layered LAZ chunks (codegen/record_fields.h, codegen/laz_layered.h): the
// fields asked for decode bit for bit as in a full decoding, for point formats 6, 7 and 8 with and
// without extra bytes, every field varied, over several chunks and scanner channels, whatever set
// of fields is asked; the layers left out are really not decoded (a corrupt one goes unread); and
// a chunk's layer sizes are checked whole, the left-out layers' too, with one line naming the
// chunk.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "codegen/las_reader.h"
#include "codegen/prepare_error.h"
#include "codegen/record_fields.h"
#include "tests/support/expect_refused.h"
#include "tests/support/file_bytes.h"
#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

// Where each field lies in a record of formats 6 to 10 (LAS 1.4 R15), written out here rather
// than taken from the decoder: [first, end) bytes and the bits of them that are the field's.
struct SelectiveFieldBytes {
  RecordField field;
  std::size_t first, end;
  std::uint8_t bits = 0xff;
};

std::vector<SelectiveFieldBytes> selectiveFieldBytes(int format, std::size_t record_bytes) {
  std::vector<SelectiveFieldBytes> fields = {
      {RecordField::kZ, 8, 12},
      {RecordField::kIntensity, 12, 14},
      {RecordField::kFlags, 15, 16, 0xcf},  // the channel (bits 4 and 5) is always decoded
      {RecordField::kClassification, 16, 17},
      {RecordField::kUserData, 17, 18},
      {RecordField::kScanAngle, 18, 20},
      {RecordField::kPointSource, 20, 22},
      {RecordField::kGpsTime, 22, 30}};
  std::size_t at = 30;
  if (format == 7 || format == 8 || format == 10) {
    fields.push_back({RecordField::kRgb, at, at + 6});
    at += 6;
  }
  if (format == 8 || format == 10) {
    fields.push_back({RecordField::kNir, at, at + 2});
    at += 2;
  }
  if (format == 9 || format == 10) {
    fields.push_back({RecordField::kWavePacket, at, at + 29});
    at += 29;
  }
  if (at < record_bytes) fields.push_back({RecordField::kExtraBytes, at, record_bytes});
  return fields;
}

constexpr RecordField kSelectiveEveryField[] = {
    RecordField::kZ,           RecordField::kClassification, RecordField::kFlags,
    RecordField::kIntensity,   RecordField::kScanAngle,      RecordField::kUserData,
    RecordField::kPointSource, RecordField::kGpsTime,        RecordField::kRgb,
    RecordField::kNir,         RecordField::kWavePacket,     RecordField::kExtraBytes};

class LazSelectiveTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("octopoint_laz_selective_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `count` points of the landscape as LAZ, every field varied; notes the chunks' byte sizes.
  fs::path writeLaz(const std::string& name, int format, int extra_bytes, std::size_t count,
                    std::uint32_t chunk_points) {
    testing::LasLayout layout;
    layout.format = format;
    layout.extra_bytes = extra_bytes;
    layout.varied_fields = true;
    layout.laz = true;
    layout.laz_chunk_points = chunk_points;
    const fs::path path = dir_ / name;
    testing::LasWriter writer(path, layout);
    writer.addLandscape(landscape_, count);
    writer.finish();
    chunk_bytes_ = writer.lazChunkBytes();
    point_offset_ = writer.pointOffset();
    return path;
  }

  // Every record of `path` with `fields` decoded, piece by piece as the preparer reads them.
  static std::vector<std::uint8_t> recordsWith(const fs::path& path, RecordFields fields) {
    const auto source = openLasSource(path, fields);
    std::vector<std::uint8_t> all;
    PointChunk chunk;
    for (std::size_t i = 0; i < source->pieceCount(); ++i) {
      const PointRange piece = source->piece(i);
      source->read(piece.first, piece.count, chunk);
      all.insert(all.end(), chunk.raw.begin(), chunk.raw.end());
    }
    return all;
  }

  fs::path dir_;
  testing::Landscape landscape_;
  std::vector<std::uint64_t> chunk_bytes_;
  std::uint64_t point_offset_ = 0;
};

// The bits of `selective` that `fields` promise (x, y, the returns and the channel always) must
// equal `full`'s. Returns how many bytes of the fields left out differ: that they were left out.
std::size_t expectAskedFieldsEqual(const std::vector<std::uint8_t>& full,
                                   const std::vector<std::uint8_t>& selective, int format,
                                   std::size_t record_bytes, RecordFields fields,
                                   const std::string& what) {
  EXPECT_EQ(selective.size(), full.size()) << what;
  std::vector<std::uint8_t> asked(record_bytes, 0xff);  // the bits a record must match in
  for (const SelectiveFieldBytes& field : selectiveFieldBytes(format, record_bytes)) {
    if (fields.has(field.field)) continue;
    for (std::size_t b = field.first; b < field.end; ++b)
      asked[b] = static_cast<std::uint8_t>(asked[b] & ~field.bits);
  }
  std::size_t left_out_differ = 0;
  for (std::size_t i = 0; i < full.size() && i < selective.size(); ++i) {
    const auto diff = static_cast<std::uint8_t>(full[i] ^ selective[i]);
    const std::size_t byte = i % record_bytes;
    if ((diff & asked[byte]) != 0) {
      ADD_FAILURE() << what << ": record " << i / record_bytes << " byte " << byte << " is "
                    << int{selective[i]} << ", a full decoding gives " << int{full[i]};
      return left_out_differ;
    }
    if (diff != 0) ++left_out_differ;
  }
  return left_out_differ;
}

TEST_F(LazSelectiveTest, AskedFieldsDecodeBitForBitAsInAFullDecoding) {
  for (int format : {6, 7, 8}) {
    for (int extra_bytes : {0, 4}) {
      const std::string name = "f" + std::to_string(format) + "_" + std::to_string(extra_bytes);
      // 4 chunks of 2000 (the last 1500), the writer's several scanner channels in each
      const fs::path path = writeLaz(name + ".laz", format, extra_bytes, 7500, 2000);
      testing::LasLayout layout;
      layout.format = format;
      layout.extra_bytes = extra_bytes;
      const std::size_t record_bytes = testing::LasWriter::recordLength(layout);
      const std::vector<std::uint8_t> full = recordsWith(path, RecordFields::all());
      ASSERT_EQ(full.size(), 7500 * record_bytes);
      std::vector<std::pair<std::string, RecordFields>> sets = {
          {"the preparer's", RecordFields::pointChunk()},
          {"x and y only", RecordFields::xyOnly()},
          {"x, y and GPS time", RecordFields::xyOnly().with(RecordField::kGpsTime)}};
      for (std::size_t i = 0; i < std::size(kSelectiveEveryField); ++i) {
        const RecordField field = kSelectiveEveryField[i];
        sets.push_back({"all but field " + std::to_string(i), RecordFields::all().without(field)});
        sets.push_back({"x, y and field " + std::to_string(i), RecordFields::xyOnly().with(field)});
      }
      for (const auto& [set_name, fields] : sets) {
        const std::size_t left_out_differ = expectAskedFieldsEqual(
            full, recordsWith(path, fields), format, record_bytes, fields, name + ", " + set_name);
        if (set_name == "the preparer's" || set_name == "x and y only") {
          // the GPS time (and more) of the varied fields changes: skipped, it differs
          EXPECT_GT(left_out_differ, 7500u) << name << ", " << set_name;
        }
      }
      // The preparer's decoded points (positions, colour, intensity) are a full decoding's.
      const auto selective_source = openLasSource(path);
      const auto full_source = openLasSource(path, RecordFields::all());
      PointChunk want, got;
      full_source->read(0, 7500, want);
      selective_source->read(0, 7500, got);
      EXPECT_EQ(got.xyz, want.xyz) << name;
      EXPECT_EQ(got.rgb, want.rgb) << name;
      EXPECT_EQ(got.intensity, want.intensity) << name;
    }
  }
}

// The first chunk's layers of 3000 points of format 7 in chunks of 1000: POINT14's 9 layers, then
// RGB14's, each a 32-bit size after the first point (36 bytes) and the point count.
constexpr std::uint64_t kSelectiveRecord = 36, kSelectiveLayers = 10, kSelectiveGpsLayer = 8;

TEST_F(LazSelectiveTest, ALayerLeftOutIsNeverDecoded) {
  const fs::path good = writeLaz("good.laz", 7, 0, 3000, 1000);
  std::string bytes = testing::fileBytes(good);
  const std::uint64_t sizes_at = point_offset_ + 8 + kSelectiveRecord + 4;
  std::uint64_t gps_at = sizes_at + 4 * kSelectiveLayers;
  std::uint32_t gps_bytes = 0;
  for (std::uint64_t layer = 0; layer <= kSelectiveGpsLayer; ++layer) {
    std::uint32_t size = 0;
    std::memcpy(&size, bytes.data() + sizes_at + 4 * layer, 4);
    if (layer < kSelectiveGpsLayer) gps_at += size;
    gps_bytes = size;
  }
  ASSERT_GT(gps_bytes, 100u);  // the varied GPS times take a layer
  for (std::uint64_t b = gps_at; b < gps_at + gps_bytes; ++b)
    bytes[b] = static_cast<char>(bytes[b] ^ 0x5a);
  const fs::path corrupt = testing::writeFileBytes(dir_, "corrupt_gps.laz", bytes);
  // Read whole, the corrupt layer is found; left out, it is never read and the rest is the good
  // file's, bit for bit.
  testing::expectRefusedInOneLine(corrupt, "POINT14 layer GPS time",
                                  [](const fs::path& p) { recordsWith(p, RecordFields::all()); });
  const RecordFields preparer = RecordFields::pointChunk();
  expectAskedFieldsEqual(recordsWith(good, RecordFields::all()), recordsWith(corrupt, preparer), 7,
                         kSelectiveRecord, preparer, "the corrupt GPS time layer left out");
}

TEST_F(LazSelectiveTest, LayerSizesThatLieAreRefusedNamingTheChunkLeftOutOrNot) {
  const fs::path good = writeLaz("good.laz", 7, 0, 3000, 1000);
  const std::string bytes = testing::fileBytes(good);
  // The second chunk's head: the table pointer, the first chunk, then its first point and count.
  const std::uint64_t chunk2 = point_offset_ + 8 + chunk_bytes_[0];
  const std::uint64_t sizes_at = chunk2 + kSelectiveRecord + 4;
  const auto lie = [&](const std::string& name, std::uint64_t layer, std::int64_t change,
                       const std::string& expected) {
    std::string lying = bytes;
    std::uint32_t size = 0;
    std::memcpy(&size, lying.data() + sizes_at + 4 * layer, 4);
    size = change == 0 ? 0xffffffffu : static_cast<std::uint32_t>(size + change);
    std::memcpy(lying.data() + sizes_at + 4 * layer, &size, 4);
    const fs::path path = testing::writeFileBytes(dir_, name, lying);
    for (const RecordFields fields : {RecordFields::all(), RecordFields::pointChunk()}) {
      testing::expectRefusedInOneLine(path, expected,
                                      [&](const fs::path& p) { recordsWith(p, fields); });
      testing::expectRefusedInOneLine(path, "LAZ chunk 2 at byte " + std::to_string(chunk2),
                                      [&](const fs::path& p) { recordsWith(p, fields); });
    }
  };
  // A size past the chunk's end, of a layer the preparer leaves out (GPS time) and of one it reads.
  lie("gps_huge.laz", kSelectiveGpsLayer, 0, "layer 9 of 10 has 4294967295 bytes");
  lie("z_huge.laz", 1, 0, "layer 2 of 10 has 4294967295 bytes");
  // Sizes that add up to less than the chunk, or to more.
  lie("gps_short.laz", kSelectiveGpsLayer, -1, "its layers end after");
  lie("gps_long.laz", kSelectiveGpsLayer, 1, "layer 10 of 10 has");
}

}  // namespace
}  // namespace octopoint::prepare
