// The cell table's format (renderer/cell_table.h, docs/city.md "Visibility cells"): what is
// encoded decodes the same, the eye finds its cell, and every malformed table is refused with its
// reason, never read past its end.
#include "renderer/cell_table.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace octopoint {
namespace cell_table_test {
namespace {

constexpr std::int64_t kEdge = std::int64_t{1} << 24;

CellGrid smallGrid() {
  CellGrid grid;
  grid.instances = 1000;
  grid.nx = 3;
  grid.nz = 2;
  grid.ny = 2;
  grid.origin_x = -3 * kEdge;
  grid.origin_z = -2 * kEdge;
  grid.edge = 2 * kEdge;
  grid.y = {-4 * kEdge, -kEdge / 4, -kEdge / 64};
  return grid;
}

std::vector<std::vector<std::uint32_t>> smallSets() {
  std::vector<std::vector<std::uint32_t>> sets(12);
  sets[0] = {0, 1, 2, 3, 10, 999};
  sets[1] = {5};
  sets[3] = {200, 201, 202, 400, 998, 999};
  for (std::uint32_t i = 0; i < 1000; i += 3) sets[7].push_back(i);
  for (std::uint32_t i = 0; i < 1000; ++i) sets[11].push_back(i);
  return sets;
}

CellTableError parseError(const std::vector<std::uint8_t>& bytes, std::uint32_t instances = 1000) {
  CellTableError error;
  static_cast<void>(CellTable::parse(bytes, instances, &error));
  return error;
}

// The header's offsets (renderer/cell_table.h).
constexpr std::size_t kNxAt = 12, kEdgeAt = 40, kLayersAt = 48;

void put32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i)
    bytes[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

TEST(CellTable, DecodesWhatWasEncodedAndFindsTheEyesCell) {
  const std::vector<std::uint8_t> bytes = encodeCellTable(smallGrid(), smallSets());
  CellTableError error;
  const CellTable table = CellTable::parse(bytes, 1000, &error);
  ASSERT_EQ(error, CellTableError::kNone) << describe(error);
  EXPECT_EQ(table.largestSet(), 1000u);
  std::vector<std::uint32_t> out(1000);
  for (std::uint32_t cell = 0; cell < 12; ++cell) {
    const std::size_t count = table.decode(cell, out);
    EXPECT_EQ(
        std::vector<std::uint32_t>(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count)),
        smallSets()[cell])
        << "cell " << cell;
  }
  // x: cells from -3 edges by 2; z from -2 by 2; layers [-4, -1/4), [-1/4, -1/64).
  EXPECT_EQ(table.cellAt({-3 * kEdge, -kEdge, -2 * kEdge}), 0);
  EXPECT_EQ(table.cellAt({-kEdge, -kEdge, -2 * kEdge}), 1);
  EXPECT_EQ(table.cellAt({3 * kEdge - 1, -kEdge, 2 * kEdge - 1}), 5);
  EXPECT_EQ(table.cellAt({-3 * kEdge, -kEdge / 8, -2 * kEdge}), 6);
  EXPECT_EQ(table.cellAt({-3 * kEdge - 1, -kEdge, 0}), -1);  // outside in x
  EXPECT_EQ(table.cellAt({0, -kEdge, 2 * kEdge}), -1);       // outside in z
  EXPECT_EQ(table.cellAt({0, -kEdge / 64, 0}), -1);          // below the lowest layer
  EXPECT_EQ(table.cellAt({0, -4 * kEdge - 1, 0}), -1);       // above the highest
}

TEST(CellTable, RefusesEveryTruncationAndMalformedField) {
  const std::vector<std::uint8_t> good = encodeCellTable(smallGrid(), smallSets());
  for (std::size_t size = 0; size < good.size(); ++size) {
    const std::vector<std::uint8_t> cut(good.begin(),
                                        good.begin() + static_cast<std::ptrdiff_t>(size));
    EXPECT_NE(parseError(cut), CellTableError::kNone) << "cut at " << size;
  }
  EXPECT_EQ(parseError(good, 999), CellTableError::kWrongScene);
  std::vector<std::uint8_t> bad = good;
  bad[0] = 'X';
  EXPECT_EQ(parseError(bad), CellTableError::kBadMagic);
  bad = good;
  put32(bad, kNxAt, 0);
  EXPECT_EQ(parseError(bad), CellTableError::kBadGrid);
  bad = good;
  put32(bad, kNxAt, 4097);
  EXPECT_EQ(parseError(bad), CellTableError::kBadGrid);
  bad = good;
  put32(bad, kNxAt + 8, 65);  // ny
  EXPECT_EQ(parseError(bad), CellTableError::kBadGrid);
  bad = good;
  put32(bad, kNxAt, 4096);
  put32(bad, kNxAt + 4, 4096);  // 2^24 cells
  EXPECT_EQ(parseError(bad), CellTableError::kBadGrid);
  bad = good;
  for (std::size_t i = 0; i < 8; ++i) bad[kEdgeAt + i] = 0;
  EXPECT_EQ(parseError(bad), CellTableError::kBadGrid);
  bad = good;
  bad[kEdgeAt + 7] = 0x7f;  // an edge near 2^63: the grid's far corner would overflow
  EXPECT_EQ(parseError(bad), CellTableError::kBadGrid);
  bad = good;
  std::copy(good.begin() + kLayersAt, good.begin() + kLayersAt + 8, bad.begin() + kLayersAt + 8);
  EXPECT_EQ(parseError(bad), CellTableError::kBadLayers);
  // The offsets follow the three layer bounds; the payload follows the 13 offsets.
  const std::size_t offsets_at = kLayersAt + 3 * 8, payload_at = offsets_at + 13 * 4;
  bad = good;
  put32(bad, offsets_at + 4, 1000000);
  EXPECT_EQ(parseError(bad), CellTableError::kBadOffsets);
  bad = good;
  bad.push_back(0);  // the last offset no longer the payload's size
  EXPECT_EQ(parseError(bad), CellTableError::kBadOffsets);
  // Cell 0's runs: count 3, (gap 0, 3), (6, 0), (988, 0): its last id made 1000.
  bad = good;
  ASSERT_EQ(bad[payload_at], 3);
  bad[payload_at + 1 + 4] = static_cast<std::uint8_t>(0xdd);  // 988 is 0xdc 0x07: 989
  EXPECT_EQ(parseError(bad), CellTableError::kBadRun);
  bad = good;
  bad[payload_at] = 2;  // two runs read, the third's bytes left over
  EXPECT_EQ(parseError(bad), CellTableError::kTrailingBytes);
  bad = good;
  bad[payload_at] = 0x80;  // the run count's varint runs on into the next bytes
  bad[payload_at + 1] = 0x80;
  bad[payload_at + 2] = 0x80;
  bad[payload_at + 3] = 0x80;
  bad[payload_at + 4] = 0x80;
  EXPECT_EQ(parseError(bad), CellTableError::kBadRun);
}

}  // namespace
}  // namespace cell_table_test
}  // namespace octopoint
