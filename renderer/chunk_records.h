#pragma once
// The record tables of a chunked model (renderer/chunked_format.h): one record per chunk, saying
// where the chunk is in space (its region) and in the file, how many voxels it refines and holds,
// and its CRC-32. A table is checked against the head and the coarser level's table, so that every
// chunk can afterwards be checked on its own.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "renderer/chunked_errors.h"
#include "renderer/chunked_head.h"

namespace octopoint {

struct ChunkRecord {
  std::uint32_t region = 0;         // Morton code at the level's region level
  std::uint32_t bytes = 0;          // chunk size
  std::uint32_t points = 0;         // its voxels (leaves) at the level's depth
  std::uint32_t coarse_points = 0;  // the coarser level's voxels in the region, which it refines
  std::uint32_t crc = 0;            // CRC-32 of the chunk's bytes
  std::uint64_t offset = 0;         // file offset of the chunk (from the table's order)
  std::uint32_t parent =
      0;  // index of the coarser level's chunk it lies in (0 at level 1: the base)
};

// The tree levels a voxel of depth `fine_depth` lies below a voxel of depth `coarse_depth`.
inline int refinementLevels(const ChunkedHead& head, int level) {
  return head.levels[static_cast<std::size_t>(level)].depth -
         head.levels[static_cast<std::size_t>(level - 1)].depth;
}

// Parses and checks the record table of chunked level `level` (1..level_count-1). `coarser` is the
// checked table of the level above (empty for level 1, whose chunks all refine the base).
std::optional<std::vector<ChunkRecord>> parseRecordTable(std::span<const std::uint8_t> bytes,
                                                         const ChunkedHead& head, int level,
                                                         std::span<const ChunkRecord> coarser,
                                                         ChunkedIssue* issue);

}  // namespace octopoint
