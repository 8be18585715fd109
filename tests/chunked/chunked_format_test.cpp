// The chunked format, version 3 (octopoint/progressive.h, docs/format.md), frozen by a golden
// file written out byte by byte with literal offsets and CRCs (computed with zlib's crc32, not with
// our own), which must read and draw as worked out by hand; then every check of the head, the
// record tables and the chunks, each reached by a file that breaks exactly that rule.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "octopoint/progressive.h"
#include "renderer/crc32.h"
#include "tests/support/chunked_test_support.h"

namespace octopoint {
namespace {

using octopoint::testing::Bytes;

// Three levels. Palette: red, green, blue. Base, depth 1: the root's children 0 (x-, y-, z-; red)
// and 7 (x+, y+, z+; blue). Level 1, depth 2, regions at tree level 0: one chunk refining both base
// voxels, voxel 0 to its child 0 (green), voxel 7 to its child 7 (blue). Level 2, depth 3, regions
// at tree level 1: region 0 refines the green voxel to its child 1 (z+; red); region 7 refines the
// blue voxel to nothing (its first mask is 0), so it has no voxel at depth 3.
const Bytes kGolden = {
    // Fixed header: magic, version 3, 3 levels, flags 0, cube edge 10^12 pm (1 m),
    0x4f, 0x43, 0x54, 0x50, 0x03, 0x00, 0x03, 0x00, 0x00, 0x10, 0xa5, 0xd4, 0xe8, 0x00, 0x00, 0x00,
    // 3 colours, no normals, head 116 bytes, file 183 bytes, base: 1 node byte, 2 leaves.
    0x03, 0x00, 0x00, 0x00, 0x74, 0x00, 0x00, 0x00, 0xb7, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x01, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0xff, 0x00, 0x00, 0x00, 0xff, 0x00, 0x00, 0x00,
    0xff,  // palette (offset 40)
    // Level table (offset 49): the base row, depth 1.
    0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00,
    // Level 1: depth 2, region level 0, 1 chunk, table CRC 0xc4bc2434, chunks at 176.
    0x02, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x34, 0x24, 0xbc, 0xc4, 0xb0, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00,
    // Level 2: depth 3, region level 1, 2 chunks, table CRC 0x95944a8d, chunks at 180.
    0x03, 0x01, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x8d, 0x4a, 0x94, 0x95, 0xb4, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x81, 0x00, 0x02,  // base (offset 109): root mask, leaves red and blue
    0xda, 0xd2, 0xe7, 0xdc,                    // head CRC-32 of bytes 0..111
    // Record table of level 1 (offset 116): region 0, 4 bytes, 2 points, refines 2, CRC.
    0x00, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00,
    0x94, 0xf3, 0xd8, 0x8f,
    // Record table of level 2 (offset 136): region 0, 2 bytes, 1 point, refines 1; region 7,
    // 1 byte, no point, refines 1.
    0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00,
    0x7d, 0x70, 0xef, 0x73, 0x07, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x01, 0x00, 0x00, 0x00, 0x8d, 0xef, 0x02, 0xd2, 0x01, 0x80, 0x01,
    0x02,        // level 1's chunk (offset 176): masks 0x01, 0x80; green, blue
    0x02, 0x00,  // level 2, region 0 (offset 180): mask 0x02; red
    0x00};       // level 2, region 7 (offset 182): nothing

constexpr std::size_t kHeadBytes = 116;
constexpr std::size_t kRow1 = 69, kRow2 = 89;        // level table rows
constexpr std::size_t kTable1 = 116, kTable2 = 136;  // record tables
constexpr std::size_t kChunk1 = 176;

Camera eightByEight() {
  Camera camera;
  camera.width = 8;
  camera.height = 8;
  return camera;
}

// The lit pixels of a frame, as (x, y, palette index).
std::vector<std::array<int, 3>> litPixels(ProgressiveModel& model) {
  Framebuffer frame(8, 8);
  frame.clear();
  EXPECT_TRUE(model.draw(eightByEight(), Variant::kFixedBaseline, frame));
  std::vector<std::array<int, 3>> lit;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      if (frame.covered(x, y)) lit.push_back({x, y, frame.colourIndexAt(x, y)});
    }
  }
  return lit;
}

FetchItem chunk(int level, std::uint32_t index, std::uint64_t offset, std::uint64_t bytes) {
  return {FetchItem::Kind::kChunk, level, index, offset, bytes, true};
}

std::span<const std::uint8_t> at(const Bytes& image, std::size_t offset, std::size_t size) {
  return std::span(image).subspan(offset, size);
}

TEST(ChunkedFormat, Crc32IsZlibs) {
  const std::uint8_t check[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(crc32(check), 0xCBF43926u);
  EXPECT_EQ(crc32(std::span(check).subspan(4), crc32(std::span(check).first(4))), 0xCBF43926u);
}

TEST(ChunkedFormat, GoldenHeadReadsAsWrittenByHand) {
  ChunkedIssue issue;
  EXPECT_EQ(chunkedHeadBytes(kGolden, &issue), std::optional<std::uint64_t>(kHeadBytes));
  const std::optional<ChunkedHead> head =
      parseChunkedHead(std::span(kGolden).first(kHeadBytes), &issue);
  ASSERT_TRUE(head.has_value()) << describe(issue.error);
  EXPECT_EQ(head->cube_edge_pm, 1'000'000'000'000u);
  EXPECT_EQ(head->flags, 0);
  EXPECT_EQ(head->palette_count, 3);
  EXPECT_EQ(head->file_bytes, 183u);
  ASSERT_EQ(head->level_count, 3);
  EXPECT_EQ(head->levels[0].depth, 1);
  EXPECT_EQ(head->levels[1].depth, 2);
  EXPECT_EQ(head->levels[1].table_offset, kTable1);
  EXPECT_EQ(head->levels[1].chunks_offset, kChunk1);
  EXPECT_EQ(head->levels[2].region_level, 1);
  EXPECT_EQ(head->levels[2].table_offset, kTable2);
  EXPECT_EQ(head->levels[2].chunks_end, 183u);
  EXPECT_EQ(head->base_nodes, Bytes({0x81}));
  EXPECT_EQ(head->base_leaves, Bytes({0x00, 0x02}));
}

TEST(ChunkedFormat, GoldenDrawsCoarseToFineAsWorkedOutByHand) {
  std::optional<ProgressiveModel> model =
      ProgressiveModel::fromHead(std::span(kGolden).first(kHeadBytes), nullptr);
  ASSERT_TRUE(model.has_value());
  model->useEveryStoredDepth(true);  // 2, 2 and 1 voxels: no depth samples "densely"
  // An 8 x 8 frame at zoom 1 wants depth 3 (one pixel per voxel). The base alone: its voxels'
  // centres are 2 pixels from the cube's centre (4, 4) on each axis.
  using Lit = std::vector<std::array<int, 3>>;
  EXPECT_EQ(litPixels(*model), (Lit{{2, 2, 0}, {6, 6, 2}}));
  ASSERT_EQ(model->accept(model->recordTableItem(1), at(kGolden, kTable1, 20)).error,
            ChunkedError::kNone);
  ASSERT_EQ(model->accept(chunk(1, 0, kChunk1, 4), at(kGolden, kChunk1, 4)).error,
            ChunkedError::kNone);
  EXPECT_EQ(litPixels(*model), (Lit{{1, 1, 1}, {7, 7, 2}}));  // depth 2: one more pixel out
  ASSERT_EQ(model->accept(model->recordTableItem(2), at(kGolden, kTable2, 40)).error,
            ChunkedError::kNone);
  EXPECT_EQ(litPixels(*model), (Lit{{1, 1, 1}, {7, 7, 2}}));  // level 2 known, none of it held
  ASSERT_EQ(model->chunkCount(2), 2u);
  EXPECT_EQ(model->record(2, 1).region, 7u);
  EXPECT_EQ(model->record(2, 1).points, 0u);
  ASSERT_EQ(model->accept(chunk(2, 1, 182, 1), at(kGolden, 182, 1)).error, ChunkedError::kNone);
  EXPECT_EQ(litPixels(*model), (Lit{{1, 1, 1}}));  // the blue voxel has nothing at depth 3
  ASSERT_EQ(model->accept(chunk(2, 0, 180, 2), at(kGolden, 180, 2)).error, ChunkedError::kNone);
  EXPECT_EQ(litPixels(*model), (Lit{{0, 0, 0}}));  // (0, 0, 1) at depth 3: centre (0.5, 0.5)
  EXPECT_TRUE(model->viewComplete(eightByEight()));
}

// A copy of the golden file with `change` applied and, when `seal`, every CRC recomputed.
Bytes altered(std::size_t offset, std::vector<std::uint8_t> bytes, bool seal = true) {
  Bytes image = kGolden;
  for (std::size_t i = 0; i < bytes.size(); ++i) image[offset + i] = bytes[i];
  if (seal) octopoint::testing::reseal(image);
  return image;
}

ChunkedError headError(const Bytes& image) {
  ChunkedIssue issue;
  const std::optional<ChunkedHead> head = parseChunkedHead(image, &issue);
  EXPECT_EQ(head.has_value(), issue.error == ChunkedError::kNone);
  return issue.error;
}

TEST(ChunkedFormat, EveryHeadRuleIsChecked) {
  EXPECT_EQ(headError(Bytes(kGolden.begin(), kGolden.begin() + 39)), ChunkedError::kTruncatedHead);
  EXPECT_EQ(headError(Bytes(kGolden.begin(), kGolden.begin() + kHeadBytes - 1)),
            ChunkedError::kTruncatedHead);
  EXPECT_EQ(headError(altered(0, {'X'})), ChunkedError::kBadMagic);
  EXPECT_EQ(headError(altered(4, {1})), ChunkedError::kUnsupportedVersion);
  EXPECT_EQ(headError(altered(6, {1})), ChunkedError::kBadLevelCount);
  EXPECT_EQ(headError(altered(6, {10})), ChunkedError::kBadLevelCount);
  EXPECT_EQ(headError(altered(7, {1})), ChunkedError::kBadFlags);  // normals: not read yet
  EXPECT_EQ(headError(altered(7, {4})), ChunkedError::kBadFlags);
  EXPECT_EQ(headError(altered(7, {2})), ChunkedError::kNone);  // synthetic colour
  EXPECT_EQ(headError(altered(18, {1})),
            ChunkedError::kBadReservedField);  // normals without the flag
  EXPECT_EQ(headError(altered(16, {0})), ChunkedError::kBadPaletteCount);
  EXPECT_EQ(headError(altered(20, {117})), ChunkedError::kBadHeadSize);
  EXPECT_EQ(headError(altered(29, {0x02})), ChunkedError::kBadFileSize);  // 2^41 bytes
  EXPECT_EQ(headError(altered(24, {181})),
            ChunkedError::kBadFileSize);  // level 2's 2 chunks in 1 byte
  EXPECT_EQ(headError(altered(110, {0x01}, false)), ChunkedError::kBadHeadCrc);
  EXPECT_EQ(headError(altered(49 + 2, {1})), ChunkedError::kBadReservedField);  // base row
  EXPECT_EQ(headError(altered(49 + 1, {1})),
            ChunkedError::kBadReservedField);  // base row region level
  EXPECT_EQ(headError(altered(kRow2, {17})), ChunkedError::kBadDepth);
  EXPECT_EQ(headError(altered(kRow2, {2})), ChunkedError::kDepthsNotAscending);
  EXPECT_EQ(headError(altered(kRow2 + 1, {2})),
            ChunkedError::kBadRegionLevel);  // not coarser than depth 2
  EXPECT_EQ(headError(altered(kRow1 + 1, {1})),
            ChunkedError::kBadRegionLevel);  // 1, then 1 >= depth 1
  EXPECT_EQ(headError(altered(kRow1 + 4, {2})),
            ChunkedError::kTooManyChunks);  // 2 regions at level 0
  EXPECT_EQ(headError(altered(kRow2 + 4, {0})), ChunkedError::kTooManyChunks);
  EXPECT_EQ(headError(altered(kRow1 + 12, {0xb1})),
            ChunkedError::kBadFileSize);  // chunks not after the tables
  EXPECT_EQ(headError(altered(109, {0x00})), ChunkedError::kBadBase);  // an empty root
  EXPECT_EQ(headError(altered(111, {0x03})), ChunkedError::kBadBase);  // a leaf past the palette
}

ChunkedError tableError(const Bytes& image, int level, std::size_t size) {
  std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(image, nullptr);
  EXPECT_TRUE(model.has_value());
  if (level == 2) {
    EXPECT_EQ(model->accept(model->recordTableItem(1), at(image, kTable1, 20)).error,
              ChunkedError::kNone);
  }
  FetchItem item = model->recordTableItem(level);
  return model->accept(item, at(image, static_cast<std::size_t>(item.offset), size)).error;
}

TEST(ChunkedFormat, EveryRecordTableRuleIsChecked) {
  EXPECT_EQ(tableError(kGolden, 1, 20), ChunkedError::kNone);
  EXPECT_EQ(tableError(kGolden, 2, 40), ChunkedError::kNone);
  EXPECT_EQ(tableError(kGolden, 1, 19), ChunkedError::kBadTableSize);
  EXPECT_EQ(tableError(altered(kTable1 + 8, {3}, false), 1, 20), ChunkedError::kBadTableCrc);
  // Regions 7 then 0: swapped records.
  Bytes swapped = kGolden;
  std::copy(kGolden.begin() + kTable2, kGolden.begin() + kTable2 + 20,
            swapped.begin() + kTable2 + 20);
  std::copy(kGolden.begin() + kTable2 + 20, kGolden.begin() + kTable2 + 40,
            swapped.begin() + kTable2);
  octopoint::testing::reseal(swapped);
  EXPECT_EQ(tableError(swapped, 2, 40), ChunkedError::kRegionsNotAscending);
  EXPECT_EQ(tableError(altered(kTable2 + 20, {8}), 2, 40), ChunkedError::kRegionOutsideLevel);
  // Region 0 said to refine 2 voxels (3 bytes: 2 masks, 1 point): plausible, but level 1 has 2 in
  // all.
  EXPECT_EQ(tableError(altered(kTable2 + 4, {3, 0, 0, 0, 1, 0, 0, 0, 2}), 2, 40),
            ChunkedError::kCoarseCountMismatch);
  EXPECT_EQ(tableError(altered(kTable1 + 4, {1}), 1, 20),
            ChunkedError::kImplausibleChunk);  // 2 points in 1 byte
  EXPECT_EQ(tableError(altered(kTable2 + 4, {1}), 2, 40),
            ChunkedError::kImplausibleChunk);  // no mask byte
  // Level 1's chunk said to be 5 bytes with 3 points: plausible, but the chunks then overrun the
  // level.
  EXPECT_EQ(tableError(altered(kTable1 + 4, {5, 0, 0, 0, 3}), 1, 20),
            ChunkedError::kChunkBytesMismatch);
  // A table before the one above it.
  std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(kGolden, nullptr);
  EXPECT_EQ(model->accept(model->recordTableItem(2), at(kGolden, kTable2, 40)).error,
            ChunkedError::kTableOutOfOrder);
}

ChunkedError chunkError(const Bytes& image, std::vector<std::uint8_t> level1_chunk) {
  std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(image, nullptr);
  EXPECT_EQ(model->accept(model->recordTableItem(1), at(image, kTable1, 20)).error,
            ChunkedError::kNone);
  return model->accept(chunk(1, 0, kChunk1, 4), level1_chunk).error;
}

TEST(ChunkedFormat, EveryChunkRuleIsChecked) {
  EXPECT_EQ(chunkError(kGolden, {0x01, 0x80, 0x01, 0x02}), ChunkedError::kNone);
  EXPECT_EQ(chunkError(kGolden, {0x01, 0x80, 0x01}), ChunkedError::kWrongChunkLength);
  EXPECT_EQ(chunkError(kGolden, {0x01, 0x80, 0x01, 0x03}), ChunkedError::kBadChunkCrc);
  // The same bytes with their CRC in the record (and the tables and head resealed): the walk
  // decides.
  const auto sealed = [](std::vector<std::uint8_t> bytes) {
    Bytes image = altered(kChunk1, bytes);
    return chunkError(image, bytes);
  };
  EXPECT_EQ(sealed({0x01, 0x80, 0x01, 0x03}), ChunkedError::kChunkLeafOutsidePalette);
  EXPECT_EQ(sealed({0x03, 0x80, 0x01, 0x02}), ChunkedError::kChunkLeafCountMismatch);
  EXPECT_EQ(sealed({0x00, 0x80, 0x01, 0x02}), ChunkedError::kChunkLeafCountMismatch);
  // An unknown chunk: level 2 before its table.
  std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(kGolden, nullptr);
  EXPECT_EQ(model->accept(chunk(2, 0, 180, 2), at(kGolden, 180, 2)).error,
            ChunkedError::kUnknownChunk);
}

TEST(ChunkedFormat, AChunkContradictingTheFinerTableIsDroppedAndItsRegionStaysCoarse) {
  // Level 2 says its second region is 6, but level 1's chunk puts its blue voxel in region 7.
  const Bytes image = altered(kTable2 + 20, {6});
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(image, nullptr);
  ASSERT_TRUE(model.has_value());
  EXPECT_EQ(model->chunkState(1, 0), ChunkState::kUnavailable);
  using Lit = std::vector<std::array<int, 3>>;
  EXPECT_EQ(litPixels(*model),
            (Lit{{2, 2, 0}, {6, 6, 2}}));  // the base, as before anything arrived
}

TEST(ChunkedFormat, DescriptionsAreDistinct) {
  std::vector<std::string> seen;
  for (int e = 0; e <= static_cast<int>(ChunkedError::kChunkDisagrees); ++e) {
    const std::string text = describe(static_cast<ChunkedError>(e));
    EXPECT_FALSE(text.empty());
    EXPECT_EQ(std::count(seen.begin(), seen.end(), text), 0) << text;
    seen.push_back(text);
  }
}

}  // namespace
}  // namespace octopoint
