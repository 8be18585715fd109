// Writes cell tables (renderer/cell_table.h, docs/city.md "Visibility cells"): host side, at
// build time of the cells. Two choices make the table small whatever the sets are:
//  - the order: instances sorted by the cells that see them (their membership bits read as a
//    reflected Gray code, cells in index order), so that an instance seen from the same cells as
//    its neighbour in the order stands beside it, and a cell's set is a few long runs;
//  - per cell, its own runs or its difference from the cell west of it, north of it or in the
//    layer before (neighbours' sets differ little), whichever is fewer bytes, with chains of at
//    most kMaxCellChain cells.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "renderer/cell_table.h"
#include "renderer/cell_table_bytes.h"

namespace octopoint {
namespace {

using cell_bytes::writeLe;
using cell_bytes::writeVarint;

// A cell: its head (OCTCELL1: the run count; OCTCELL2: the run count doubled, plus one and `back`
// for a difference) and its sorted, distinct ranks as runs (gap from the previous run's end,
// length - 1). An empty cell of its own: no bytes.
void writeCell(std::vector<std::uint8_t>& out, const std::vector<std::uint32_t>& ranks,
               bool version2, std::uint32_t back) {
  const bool reference = back != 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;  // first, length - 1
  for (const std::uint32_t rank : ranks) {
    if (!runs.empty() && runs.back().first + runs.back().second + 1 == rank) {
      ++runs.back().second;
    } else {
      runs.push_back({rank, 0});
    }
  }
  if (runs.empty() && !reference) return;  // an empty cell: no bytes
  const std::uint32_t count = static_cast<std::uint32_t>(runs.size());
  writeVarint(out, version2 ? count << 1 | (reference ? 1u : 0u) : count);
  if (reference) writeVarint(out, back);
  std::uint32_t next = 0;
  for (const auto& [first, extra] : runs) {
    writeVarint(out, first - next);
    writeVarint(out, extra);
    next = first + extra + 1;
  }
}

// The instances sorted by their membership bits (cell 0 the most significant) in reflected Gray
// order: the order in which each bit, and so each cell's set, changes least often. Its key is the
// bits' prefix parity; ties in id order.
std::vector<std::uint32_t> membershipOrder(std::uint32_t instances,
                                           const std::vector<std::vector<std::uint32_t>>& sets) {
  const std::size_t words = (sets.size() + 63) / 64;
  std::vector<std::uint64_t> bits(std::size_t{instances} * words);
  for (std::size_t cell = 0; cell < sets.size(); ++cell) {
    for (const std::uint32_t id : sets[cell])
      bits[id * words + cell / 64] |= std::uint64_t{1} << (63 - cell % 64);
  }
  for (std::uint32_t id = 0; id < instances; ++id) {  // Gray to binary: each bit xor all before
    std::uint64_t carry = 0;
    for (std::size_t w = 0; w < words; ++w) {
      std::uint64_t v = bits[id * words + w];
      for (int shift = 1; shift < 64; shift <<= 1) v ^= v >> shift;
      if (carry != 0) v = ~v;
      bits[id * words + w] = v;
      carry = v & 1;
    }
  }
  std::vector<std::uint32_t> order(instances);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::lexicographical_compare(
        bits.begin() + static_cast<std::ptrdiff_t>(a * words),
        bits.begin() + static_cast<std::ptrdiff_t>((a + 1) * words),
        bits.begin() + static_cast<std::ptrdiff_t>(b * words),
        bits.begin() + static_cast<std::ptrdiff_t>((b + 1) * words));
  });
  return order;
}

// The order as runs of consecutive ids (zigzag step from the previous run's end, length - 1).
void writeOrder(std::vector<std::uint8_t>& out, const std::vector<std::uint32_t>& order) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;
  for (const std::uint32_t id : order) {
    if (!runs.empty() && runs.back().first + runs.back().second + 1 == id) {
      ++runs.back().second;
    } else {
      runs.push_back({id, 0});
    }
  }
  writeVarint(out, static_cast<std::uint32_t>(runs.size()));
  std::int64_t next = 0;
  for (const auto& [first, extra] : runs) {
    writeVarint(out, cell_bytes::zigzag(std::int64_t{first} - next));
    writeVarint(out, extra);
    next = std::int64_t{first} + extra + 1;
  }
}

}  // namespace

std::vector<std::uint8_t> encodeCellTable(const CellGrid& grid,
                                          const std::vector<std::vector<std::uint32_t>>& sets,
                                          const CellTableEncoding& encoding) {
  const bool version2 = !encoding.version1;
  std::vector<std::uint32_t> order;  // rank -> id; empty: the ids' own
  if (version2 && encoding.reorder) order = membershipOrder(grid.instances, sets);
  std::vector<std::uint32_t> rank_of(grid.instances);
  for (std::uint32_t r = 0; r < order.size(); ++r) rank_of[order[r]] = r;
  if (order.empty()) std::iota(rank_of.begin(), rank_of.end(), 0u);
  std::vector<std::vector<std::uint32_t>> ranked(sets.size());
  for (std::size_t cell = 0; cell < sets.size(); ++cell) {
    for (const std::uint32_t id : sets[cell]) ranked[cell].push_back(rank_of[id]);
    std::sort(ranked[cell].begin(), ranked[cell].end());
  }
  std::vector<std::uint8_t> payload, best, trial;
  std::vector<std::uint32_t> offsets{0}, difference;
  std::vector<int> chain(sets.size(), 1);
  const std::uint32_t plane = grid.nx * grid.nz;
  for (std::uint32_t cell = 0; cell < sets.size(); ++cell) {
    best.clear();
    writeCell(best, ranked[cell], version2, 0);
    const std::uint32_t x = cell % grid.nx, z = cell / grid.nx % grid.nz;
    for (const std::uint32_t back : {1u, grid.nx, plane}) {
      const bool earlier = back == 1 ? x > 0 : back == grid.nx ? z > 0 : cell >= plane;
      if (!version2 || !encoding.references || !earlier || chain[cell - back] >= kMaxCellChain)
        continue;
      difference.clear();
      std::set_symmetric_difference(ranked[cell].begin(), ranked[cell].end(),
                                    ranked[cell - back].begin(), ranked[cell - back].end(),
                                    std::back_inserter(difference));
      trial.clear();
      writeCell(trial, difference, true, back);
      if (trial.size() < best.size()) {
        best = trial;
        chain[cell] = chain[cell - back] + 1;
      }
    }
    payload.insert(payload.end(), best.begin(), best.end());
    offsets.push_back(static_cast<std::uint32_t>(payload.size()));
  }
  std::vector<std::uint8_t> out(version2 ? cell_bytes::kMagic2 : cell_bytes::kMagic1,
                                (version2 ? cell_bytes::kMagic2 : cell_bytes::kMagic1) + 8);
  for (const std::uint32_t v : {grid.instances, grid.nx, grid.nz, grid.ny}) writeLe(out, v, 4);
  for (const std::int64_t v : {grid.origin_x, grid.origin_z, grid.edge})
    writeLe(out, static_cast<std::uint64_t>(v), 8);
  for (const std::int64_t v : grid.y) writeLe(out, static_cast<std::uint64_t>(v), 8);
  if (version2) {
    std::vector<std::uint8_t> order_bytes;
    if (!order.empty()) writeOrder(order_bytes, order);
    writeLe(out, order_bytes.size(), 4);
    out.insert(out.end(), order_bytes.begin(), order_bytes.end());
  }
  for (const std::uint32_t v : offsets) writeLe(out, v, 4);
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

}  // namespace octopoint
