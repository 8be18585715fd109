#pragma once
// Visibility cells of a scene (docs/city.md, "Visibility cells"): a grid of view cells over the
// space the eye may occupy, and per cell the instances visible from anywhere in it, computed
// beforehand (tools/cell_build.h) and stored beside the scene. The renderer draws only the eye's
// cell's set (SceneRenderer::setVisibleSet). Integer only.
//
// The file (little-endian), at most kMaxCellTableBytes, "OCTCELL2" (OCTCELL1, the same without
// the order and the references, is still read):
//   "OCTCELL2"                    8 bytes
//   u32 instances                 the scene's instance count (every id below it)
//   u32 nx, nz, ny                cells along x and z, and layers along y (each at least 1)
//   i64 origin_x, origin_z, edge  the grid's corner and its cells' edge in x and z, Q.24 scene
//                                 edges
//   i64 y[ny + 1]                 the layers' bounds, increasing (y down: the highest first)
//   u32 order_bytes, order        the instances in the table's order (rank 0 first), as runs of
//                                 consecutive ids: LEB128 varints, the run count, then per run
//                                 its first id less the previous run's end (zigzag: it may go
//                                 back) and its length - 1; every id exactly once. No bytes: the
//                                 ids' own order. Sets are runs of ranks in this order, chosen so
//                                 that instances seen from the same cells stand together.
//   u32 offset[nx nz ny + 1]      each cell's bytes in the payload: offset[0] = 0, non-decreasing,
//                                 the last the payload's size
//   payload                       per cell (index (layer nz + z) nx + x), LEB128 varints: h; when
//                                 h is odd, d: the cell's set is that of the cell d before it
//                                 (1 <= d <= index) with the runs' ranks toggled (added when
//                                 absent, removed when present); when h is even, the runs' ranks
//                                 alone. Then h / 2 runs: the gap from the previous run's end (the
//                                 first from 0) and the run's length - 1. No bytes: empty. A chain
//                                 of references is at most kMaxCellChain cells long, so decoding
//                                 a cell reads at most that many cells' runs.
// An eye outside the grid has no cell: everything is drawn.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "octopoint/camera.h"

namespace octopoint {

inline constexpr std::uint64_t kMaxCellTableBytes = std::uint64_t{64} << 20;
inline constexpr std::uint32_t kMaxCellsPerAxis = 4096;
inline constexpr std::uint32_t kMaxCellLayers = 64;
inline constexpr std::uint32_t kMaxCells = std::uint32_t{1} << 20;
// The longest chain of cells coded as differences: a cell and the cells it refers to, in turn.
inline constexpr int kMaxCellChain = 8;

enum class CellTableError : std::uint8_t {
  kNone,
  kTooLarge,       // past kMaxCellTableBytes
  kTruncated,      // shorter than its header, bounds, offsets or a cell's runs say
  kBadMagic,       // not "OCTCELL2" or "OCTCELL1"
  kWrongScene,     // its instance count is not the scene's
  kBadGrid,        // counts outside 1..the limits, an edge not positive, a bound past 2^44
  kBadLayers,      // layer bounds not increasing
  kBadOffsets,     // offsets decreasing or past the payload, or the last not its size
  kBadRun,         // a varint too long, an id past the instances, a cell's bytes not all runs
  kTrailingBytes,  // bytes after a cell's runs, within its offsets' span
  kBadOrder,       // the order's runs malformed, an id past the instances, missing or twice
  kBadReference,   // a cell referring to itself, a later cell or none, or a chain too long
};
const char* describe(CellTableError error);

struct CellGrid {
  std::uint32_t instances = 0;
  std::uint32_t nx = 0, nz = 0, ny = 0;
  std::int64_t origin_x = 0, origin_z = 0, edge = 0;  // Q.24 scene edges
  std::vector<std::int64_t> y;                        // ny + 1 bounds, increasing
  std::uint32_t cellCount() const { return nx * nz * ny; }
};

class CellTable {
 public:
  // Validates every field and every cell's runs (cost bounded by the bytes); *error says why not.
  static CellTable parse(std::span<const std::uint8_t> bytes, std::uint32_t scene_instances,
                         CellTableError* error);

  const CellGrid& grid() const { return grid_; }
  std::size_t bytes() const { return bytes_.size(); }
  // The cell holding `eye` (Q.24 scene edges), or -1 outside the grid.
  std::int64_t cellAt(const Point3<std::int64_t>& eye) const;
  // Decoding's work space for this table: a bit per rank, all clear between decodes. Each thread
  // that decodes holds its own, made once, so that decoding allocates nothing.
  struct Scratch {
    std::vector<std::uint64_t> bits;
  };
  Scratch scratch() const;
  // Cell `cell`'s ids, distinct, in the table's order (not sorted), into `out`: their count, at
  // most out.size() (room for largestSet() holds every set); 0 with a scratch made for another
  // table. Work: the runs of at most kMaxCellChain cells and, for a cell coded as a difference, a
  // pass over its words.
  std::size_t decode(std::uint32_t cell, std::span<std::uint32_t> out, Scratch& scratch) const;
  // At least the largest set of any cell, at most the instance count.
  std::size_t largestSet() const { return largest_; }

 private:
  CellGrid grid_;
  std::vector<std::uint8_t> bytes_;
  std::vector<std::uint32_t> order_;  // rank -> id
  bool references_ = false;           // OCTCELL2: cells may be differences
  std::size_t offsets_at_ = 0, payload_at_ = 0, largest_ = 0;
  std::uint32_t offset(std::uint32_t i) const;
};

struct CellTableEncoding {
  bool version1 = false;   // OCTCELL1: ids' own order, no differences (for old readers and tests)
  bool reorder = true;     // an order that keeps instances seen from the same cells together
  bool references = true;  // a cell as its difference from a neighbour when that is smaller
};

// The file of `grid` and per cell its sorted, distinct ids (each below grid.instances).
std::vector<std::uint8_t> encodeCellTable(const CellGrid& grid,
                                          const std::vector<std::vector<std::uint32_t>>& sets,
                                          const CellTableEncoding& encoding = {});

}  // namespace octopoint
