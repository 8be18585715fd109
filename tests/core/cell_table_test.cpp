// The cell table's format (renderer/cell_table.h, docs/city.md "Visibility cells"): what is
// encoded decodes the same, the eye finds its cell, and every malformed table is refused with its
// reason, never read past its end.
#include "renderer/cell_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

#include "renderer/cell_table_bytes.h"

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

constexpr CellTableEncoding kVersion1{true, false, false};

// Every cell's set, sorted (decode gives them in the table's order), decoded with `scratch` (else
// a scratch of its own).
std::vector<std::vector<std::uint32_t>> decodedSets(const CellTable& table,
                                                    CellTable::Scratch* scratch = nullptr) {
  CellTable::Scratch own = table.scratch();
  if (scratch == nullptr) scratch = &own;
  std::vector<std::uint32_t> out(table.largestSet());
  std::vector<std::vector<std::uint32_t>> sets;
  for (std::uint32_t cell = 0; cell < table.grid().cellCount(); ++cell) {
    const std::size_t count = table.decode(cell, out, *scratch);
    sets.emplace_back(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count));
    std::sort(sets.back().begin(), sets.back().end());
  }
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
  for (const CellTableEncoding encoding :
       {kVersion1, CellTableEncoding{false, false, false}, CellTableEncoding{false, true, false},
        CellTableEncoding{false, false, true}, CellTableEncoding{}}) {
    const std::vector<std::uint8_t> bytes = encodeCellTable(smallGrid(), smallSets(), encoding);
    CellTableError error;
    const CellTable table = CellTable::parse(bytes, 1000, &error);
    ASSERT_EQ(error, CellTableError::kNone) << describe(error);
    EXPECT_GE(table.largestSet(), 1000u);
    EXPECT_EQ(decodedSets(table), smallSets())
        << "version1 " << encoding.version1 << " reorder " << encoding.reorder << " references "
        << encoding.references;
  }
  CellTableError error;
  const CellTable table = CellTable::parse(encodeCellTable(smallGrid(), smallSets()), 1000, &error);
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

TEST(CellTable, RefusesEveryTruncationAndMalformedFieldOfVersion1) {
  const std::vector<std::uint8_t> good = encodeCellTable(smallGrid(), smallSets(), kVersion1);
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

// An OCTCELL2 table of `grid` from its parts as bytes: the order's and each cell's.
std::vector<std::uint8_t> version2(const CellGrid& grid, const std::vector<std::uint8_t>& order,
                                   const std::vector<std::vector<std::uint8_t>>& cells) {
  std::vector<std::uint8_t> out(cell_bytes::kMagic2, cell_bytes::kMagic2 + 8);
  for (const std::uint32_t v : {grid.instances, grid.nx, grid.nz, grid.ny})
    cell_bytes::writeLe(out, v, 4);
  for (const std::int64_t v : {grid.origin_x, grid.origin_z, grid.edge})
    cell_bytes::writeLe(out, static_cast<std::uint64_t>(v), 8);
  for (const std::int64_t v : grid.y) cell_bytes::writeLe(out, static_cast<std::uint64_t>(v), 8);
  cell_bytes::writeLe(out, order.size(), 4);
  out.insert(out.end(), order.begin(), order.end());
  std::uint32_t offset = 0;
  cell_bytes::writeLe(out, 0, 4);
  for (const auto& cell : cells)
    cell_bytes::writeLe(out, offset += static_cast<std::uint32_t>(cell.size()), 4);
  for (const auto& cell : cells) out.insert(out.end(), cell.begin(), cell.end());
  return out;
}

// A row of `cells` cells over 10 instances.
CellGrid rowGrid(std::uint32_t cells) {
  CellGrid grid = smallGrid();
  grid.instances = 10;
  grid.nx = cells;
  grid.nz = 1;
  grid.ny = 1;
  grid.y = {-kEdge, 0};
  return grid;
}

TEST(CellTable, Version2DecodesDifferencesAndOrder) {
  // Order 9, 8, 0..7 (runs: +9 [9], -2 [8], -9 [0..7]); cell 0 ranks 0..2 (ids 9, 8, 0); cell 1 =
  // cell 0 toggled at rank 2 and rank 5 (ids 9, 8, 3); cell 2 = cell 1 toggled at ranks 0..9 (all
  // but 9, 8, 3); cell 3 empty; cell 4 = cell 3 (empty) toggled at rank 9 (id 7).
  const std::vector<std::uint8_t> order = {3, 18, 0, 3, 0, 17, 7};
  const std::vector<std::vector<std::uint8_t>> cells = {
      {2, 0, 2}, {5, 1, 2, 0, 2, 0}, {3, 1, 0, 9}, {}, {3, 1, 9, 0}};
  CellTableError error;
  const CellTable table = CellTable::parse(version2(rowGrid(5), order, cells), 10, &error);
  ASSERT_EQ(error, CellTableError::kNone) << describe(error);
  const std::vector<std::vector<std::uint32_t>> expected = {
      {0, 8, 9}, {3, 8, 9}, {0, 1, 2, 4, 5, 6, 7}, {}, {7}};
  // Twice, in another order, with one scratch: its bits are left clear by every decode.
  CellTable::Scratch scratch = table.scratch();
  EXPECT_EQ(decodedSets(table, &scratch), expected);
  std::vector<std::uint32_t> out(10);
  EXPECT_EQ(table.decode(1, out, scratch), 3u);
  EXPECT_EQ(table.decode(2, out, scratch), 7u);
  EXPECT_EQ(decodedSets(table, &scratch), expected);
  // A buffer shorter than the set: filled, never past.
  std::vector<std::uint32_t> two(2);
  EXPECT_EQ(table.decode(2, two, scratch), 2u);
  EXPECT_EQ(decodedSets(table, &scratch), expected);
  // A scratch made for a table of another instance count: nothing decoded.
  CellTable::Scratch wrong{std::vector<std::uint64_t>(2)};
  EXPECT_EQ(table.decode(2, out, wrong), 0u);
}

TEST(CellTable, Version2RefusesMalformedOrderAndReferences) {
  const std::vector<std::uint8_t> identity = {1, 0, 9};  // one run: 0..9
  const std::vector<std::vector<std::uint8_t>> fine = {{2, 0, 0}, {3, 1, 0, 0}};
  EXPECT_EQ(parseError(version2(rowGrid(2), identity, fine), 10), CellTableError::kNone);
  EXPECT_EQ(parseError(version2(rowGrid(2), {}, fine), 10), CellTableError::kNone);  // no order
  for (const std::vector<std::uint8_t>& order :
       std::vector<std::vector<std::uint8_t>>{{1, 0, 10},       // 0..10: past the instances
                                              {1, 0, 8},        // 0..8: 9 missing
                                              {2, 0, 8, 1, 0},  // back to 8: twice
                                              {2, 0, 7, 3, 0},  // 0..7 then -2 + 8 = 6: twice
                                              {1, 1, 9},        // starts at -1
                                              {1, 0, 9, 0},     // a byte left over
                                              {1, 0},           // a run cut short
                                              {1, 0, 0x89}}) {  // a varint cut short
    EXPECT_EQ(parseError(version2(rowGrid(2), order, fine), 10), CellTableError::kBadOrder);
  }
  // Cut anywhere: refused.
  const std::vector<std::uint8_t> good = version2(rowGrid(2), identity, fine);
  for (std::size_t size = 0; size < good.size(); ++size) {
    EXPECT_NE(parseError({good.begin(), good.begin() + static_cast<std::ptrdiff_t>(size)}, 10),
              CellTableError::kNone)
        << "cut at " << size;
  }
  // A reference to the cell itself (d 0), before the first (d 2 from cell 1), or from cell 0.
  EXPECT_EQ(parseError(version2(rowGrid(2), identity, {{2, 0, 0}, {3, 0, 0, 0}}), 10),
            CellTableError::kBadReference);
  EXPECT_EQ(parseError(version2(rowGrid(2), identity, {{2, 0, 0}, {3, 2, 0, 0}}), 10),
            CellTableError::kBadReference);
  EXPECT_EQ(parseError(version2(rowGrid(2), identity, {{1, 1}, {2, 0, 0}}), 10),
            CellTableError::kBadReference);
  EXPECT_EQ(parseError(version2(rowGrid(2), identity, {{2, 0, 0}, {3}}), 10),
            CellTableError::kBadRun);  // its distance missing
  EXPECT_EQ(parseError(version2(rowGrid(2), identity, {{2, 0, 0}, {3, 1, 0, 0, 0}}), 10),
            CellTableError::kTrailingBytes);
  EXPECT_EQ(parseError(version2(rowGrid(2), identity, {{2, 0, 0}, {3, 1, 0, 10}}), 10),
            CellTableError::kBadRun);  // ranks 0..10: past the instances
  // Chains: each cell the one before with rank k toggled; kMaxCellChain cells are read, one more
  // is refused (decoding a cell never reads more than kMaxCellChain cells' runs).
  std::vector<std::vector<std::uint8_t>> chain = {{2, 0, 0}};
  for (std::uint8_t k = 1; k < kMaxCellChain; ++k) chain.push_back({3, 1, 0, 0});
  EXPECT_EQ(parseError(version2(rowGrid(kMaxCellChain), identity, chain), 10),
            CellTableError::kNone);
  chain.push_back({3, 1, 0, 0});
  EXPECT_EQ(parseError(version2(rowGrid(kMaxCellChain + 1), identity, chain), 10),
            CellTableError::kBadReference);
}

// 4096 instances whose ids are shuffled; each cell of a 16 x 16 grid sees a square of a 64 x 64
// plan of them around it: coherent in space, scattered in ids.
constexpr std::uint32_t kSide = 64, kCells = 16;

CellGrid scatteredGrid() {
  CellGrid grid = smallGrid();
  grid.instances = kSide * kSide;
  grid.nx = grid.nz = kCells;
  grid.ny = 1;
  grid.y = {-kEdge, 0};
  return grid;
}

std::vector<std::vector<std::uint32_t>> scatteredSets() {
  std::vector<std::uint32_t> id_at(kSide * kSide);
  std::iota(id_at.begin(), id_at.end(), 0u);
  std::shuffle(id_at.begin(), id_at.end(), std::mt19937(7));
  std::vector<std::vector<std::uint32_t>> sets(kCells * kCells);
  for (std::uint32_t cz = 0; cz < kCells; ++cz) {
    for (std::uint32_t cx = 0; cx < kCells; ++cx) {
      auto& set = sets[cz * kCells + cx];
      for (std::uint32_t z = 0; z < kSide; ++z)
        for (std::uint32_t x = 0; x < kSide; ++x)
          if (x + 16 >= 4 * cx && x < 4 * cx + 20 && z + 16 >= 4 * cz && z < 4 * cz + 20)
            set.push_back(id_at[z * kSide + x]);
      std::sort(set.begin(), set.end());
    }
  }
  return sets;
}

TEST(CellTable, OrderAndDifferencesMakeScatteredSetsSmall) {
  const CellGrid grid = scatteredGrid();
  const std::vector<std::vector<std::uint32_t>> sets = scatteredSets();
  const std::size_t v1 = encodeCellTable(grid, sets, kVersion1).size();
  const std::vector<std::uint8_t> both = encodeCellTable(grid, sets);
  const std::size_t order_only = encodeCellTable(grid, sets, {false, true, false}).size();
  const std::size_t differences_only = encodeCellTable(grid, sets, {false, false, true}).size();
  EXPECT_LT(order_only * 4, v1) << "the order";
  EXPECT_LT(differences_only * 3, v1 * 2) << "the differences";
  EXPECT_LT(both.size() * 8, v1) << "both";
  CellTableError error;
  const CellTable table = CellTable::parse(both, grid.instances, &error);
  ASSERT_EQ(error, CellTableError::kNone) << describe(error);
  EXPECT_EQ(decodedSets(table), sets);
}

TEST(CellTable, TwoThreadsDecodeOneTableEachWithItsScratch) {
  const std::vector<std::vector<std::uint32_t>> sets = scatteredSets();
  CellTableError error;
  const CellTable table =
      CellTable::parse(encodeCellTable(scatteredGrid(), sets), kSide * kSide, &error);
  ASSERT_EQ(error, CellTableError::kNone) << describe(error);
  std::vector<std::vector<std::uint32_t>> first, second;
  std::thread other([&] {
    for (int round = 0; round < 10; ++round) second = decodedSets(table);
  });
  for (int round = 0; round < 10; ++round) first = decodedSets(table);
  other.join();
  EXPECT_EQ(first, sets);
  EXPECT_EQ(second, sets);
}

}  // namespace
}  // namespace cell_table_test
}  // namespace octopoint
