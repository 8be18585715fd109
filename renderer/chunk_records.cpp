#include <algorithm>

#include "octopoint/progressive.h"
#include "renderer/crc32.h"
#include "renderer/little_endian.h"

namespace octopoint {
namespace {

using le::readU32;

bool fail(ChunkedIssue* issue, ChunkedError error, std::uint64_t offset, int level) {
  if (issue != nullptr) *issue = ChunkedIssue{error, offset, level};
  return false;
}

// Whether a chunk of these sizes can be the refinement of `coarse` voxels by `gap` tree levels:
// each coarse voxel takes at least its first mask byte and at most a full subtree, (8^gap - 1) / 7
// bytes; each leaf-parent mask byte has at most 8 leaves. Checked in constant time, before any
// walk.
bool plausibleChunk(const ChunkRecord& record, int gap) {
  if (record.coarse_points == 0 || record.bytes < record.points) return false;
  const std::uint64_t masks = record.bytes - record.points;
  if (masks < record.coarse_points || record.points > 8 * masks) return false;
  if (gap <= 10) {
    const std::uint64_t full_leaves = std::uint64_t{1} << (3 * gap);
    if (masks > record.coarse_points * ((full_leaves - 1) / 7)) return false;
    if (record.points > record.coarse_points * full_leaves) return false;
  }
  return true;
}

}  // namespace

std::optional<std::vector<ChunkRecord>> parseRecordTable(std::span<const std::uint8_t> bytes,
                                                         const ChunkedHead& head, int level,
                                                         std::span<const ChunkRecord> coarser,
                                                         ChunkedIssue* issue) {
  const ChunkedLevel& info = head.levels[static_cast<std::size_t>(level)];
  if (bytes.size() != chunked::kRecordBytes * std::uint64_t{info.chunk_count}) {
    fail(issue, ChunkedError::kBadTableSize, info.table_offset, level);
    return std::nullopt;
  }
  if (crc32(bytes) != info.table_crc) {
    fail(issue, ChunkedError::kBadTableCrc, info.table_offset, level);
    return std::nullopt;
  }
  const int gap = refinementLevels(head, level);
  // Regions of the coarser level are this many tree levels above ours (level 1: the root, level 0).
  const int region_shift =
      3 * (info.region_level -
           (level > 1 ? head.levels[static_cast<std::size_t>(level - 1)].region_level : 0));
  const std::uint64_t region_end = std::uint64_t{1} << (3 * info.region_level);

  std::vector<ChunkRecord> records(info.chunk_count);
  std::uint64_t offset = info.chunks_offset;
  std::size_t parent = 0;               // walks the coarser level alongside, both being ascending
  std::uint64_t refined_in_parent = 0;  // coarse points of the chunks seen so far in `parent`
  const auto parent_points = [&](std::size_t index) -> std::uint64_t {
    return level == 1 ? head.base_leaves.size() : coarser[index].points;
  };
  const std::size_t parent_count = level == 1 ? 1 : coarser.size();
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::uint8_t* p = bytes.data() + chunked::kRecordBytes * i;
    const std::uint64_t at = info.table_offset + chunked::kRecordBytes * i;
    ChunkRecord& record = records[i];
    record = {readU32(p), readU32(p + 4), readU32(p + 8), readU32(p + 12), readU32(p + 16), offset,
              0};
    if (record.region >= region_end) {
      fail(issue, ChunkedError::kRegionOutsideLevel, at, level);
      return std::nullopt;
    }
    if (i > 0 && record.region <= records[i - 1].region) {
      fail(issue, ChunkedError::kRegionsNotAscending, at, level);
      return std::nullopt;
    }
    if (!plausibleChunk(record, gap)) {
      fail(issue, ChunkedError::kImplausibleChunk, at + 4, level);
      return std::nullopt;
    }
    offset += record.bytes;
    // Move the parent cursor to the coarser chunk whose region holds this one; every parent passed
    // over must have had exactly its points refined.
    const std::uint32_t parent_region = level == 1 ? 0 : record.region >> region_shift;
    while (parent < parent_count && (level == 1 ? 0 : coarser[parent].region) < parent_region) {
      if (refined_in_parent != parent_points(parent)) {
        fail(issue, ChunkedError::kCoarseCountMismatch, at, level);
        return std::nullopt;
      }
      ++parent;
      refined_in_parent = 0;
    }
    if (parent == parent_count || (level > 1 && coarser[parent].region != parent_region)) {
      fail(issue, ChunkedError::kNoCoarserChunk, at, level);
      return std::nullopt;
    }
    record.parent = static_cast<std::uint32_t>(parent);
    refined_in_parent += record.coarse_points;
  }
  for (; parent < parent_count; ++parent, refined_in_parent = 0) {
    if (refined_in_parent != parent_points(parent)) {
      fail(issue, ChunkedError::kCoarseCountMismatch, info.table_offset + bytes.size(), level);
      return std::nullopt;
    }
  }
  if (offset != info.chunks_end) {
    fail(issue, ChunkedError::kChunkBytesMismatch, info.table_offset, level);
    return std::nullopt;
  }
  if (issue != nullptr) *issue = {};
  return records;
}

}  // namespace octopoint
