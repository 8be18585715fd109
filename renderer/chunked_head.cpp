#include <cstring>

#include "octopoint/model.h"
#include "octopoint/progressive.h"
#include "renderer/crc32.h"
#include "renderer/cube_placement.h"
#include "renderer/little_endian.h"

namespace octopoint {
namespace {

namespace off = chunked::offset;
using le::readU16;
using le::readU32;
using le::readU64;

bool fail(ChunkedIssue* issue, ChunkedError error, std::uint64_t offset, int level = 0) {
  if (issue != nullptr) *issue = ChunkedIssue{error, offset, level};
  return false;
}

bool hasPlacement(const std::uint8_t* p) {
  return readU16(p + off::kVersion) != chunked::kVersion3;
}

// The head size the fixed header implies: header, palette, level table, base, the cube's placement
// (versions 5 and 7), CRC.
std::uint64_t impliedHeadBytes(const std::uint8_t* p) {
  return chunked::kFixedHeaderBytes + 3 * std::uint64_t{readU16(p + off::kPaletteCount)} +
         chunked::kLevelRowBytes * std::uint64_t{p[off::kLevelCount]} +
         readU32(p + off::kBaseNodeBytes) + readU32(p + off::kBaseLeafCount) +
         (hasPlacement(p) ? format::kCubePlacementBytes : 0) + chunked::kHeadCrcBytes;
}

// Checks the level rows and fills head.levels; the base row first, then each chunked level against
// the one before it.
bool readLevelRows(const std::uint8_t* p, ChunkedHead& head, ChunkedIssue* issue) {
  const std::size_t table_at =
      chunked::kFixedHeaderBytes + 3 * static_cast<std::size_t>(head.palette_count);
  std::uint64_t chunks_total = 0;
  for (int j = 0; j < head.level_count; ++j) {
    const std::size_t row_at = table_at + chunked::kLevelRowBytes * static_cast<std::size_t>(j);
    const std::uint8_t* row = p + row_at;
    ChunkedLevel& level = head.levels[static_cast<std::size_t>(j)];
    level.depth = row[0];
    level.region_level = row[1];
    level.chunk_count = readU32(row + 4);
    level.table_crc = readU32(row + 8);
    level.chunks_offset = readU64(row + 12);
    if (level.depth < 1 || level.depth > format::kMaxDepth)
      return fail(issue, ChunkedError::kBadDepth, row_at, j);
    // Version 7 gives byte 2 a meaning, the level's sample reach; earlier versions reserve it.
    if (head.format_version == chunked::kVersion7) {
      if (row[2] < format::kOneSampleReachQ4 || row[2] > format::kMaxSampleReachQ4)
        return fail(issue, ChunkedError::kBadSampleReach, row_at + 2, j);
      level.sample_reach = row[2];
    } else if (row[2] != 0) {
      return fail(issue, ChunkedError::kBadReservedField, row_at + 2, j);
    }
    if (row[3] != 0) return fail(issue, ChunkedError::kBadReservedField, row_at + 3, j);
    if (j == 0) {
      if (level.region_level != 0 || level.chunk_count != 0 || level.table_crc != 0 ||
          level.chunks_offset != 0) {
        return fail(issue, ChunkedError::kBadReservedField, row_at + 1, 0);
      }
      continue;
    }
    const ChunkedLevel& coarser = head.levels[static_cast<std::size_t>(j - 1)];
    if (level.depth <= coarser.depth)
      return fail(issue, ChunkedError::kDepthsNotAscending, row_at, j);
    if (level.region_level >= coarser.depth || level.region_level > chunked::kMaxRegionLevel ||
        (j > 1 && level.region_level < coarser.region_level)) {
      return fail(issue, ChunkedError::kBadRegionLevel, row_at + 1, j);
    }
    chunks_total += level.chunk_count;
    if (level.chunk_count == 0 ||
        level.chunk_count > std::uint64_t{1} << (3 * level.region_level) ||
        chunks_total > chunked::kMaxChunks) {
      return fail(issue, ChunkedError::kTooManyChunks, row_at + 4, j);
    }
  }
  // Tables back to back after the head, then the chunks level by level, each level at least one
  // byte per chunk, the last ending with the file.
  std::uint64_t table_offset = head.head_bytes;
  for (int j = 1; j < head.level_count; ++j) {
    ChunkedLevel& level = head.levels[static_cast<std::size_t>(j)];
    level.table_offset = table_offset;
    table_offset += chunked::kRecordBytes * std::uint64_t{level.chunk_count};
  }
  for (int j = 1; j < head.level_count; ++j) {
    ChunkedLevel& level = head.levels[static_cast<std::size_t>(j)];
    const bool last = j + 1 == head.level_count;
    level.chunks_end =
        last ? head.file_bytes : head.levels[static_cast<std::size_t>(j + 1)].chunks_offset;
    const bool first_right = j > 1 || level.chunks_offset == table_offset;
    if (!first_right || level.chunks_end < level.chunks_offset ||
        level.chunks_end - level.chunks_offset < level.chunk_count) {
      return fail(issue, ChunkedError::kBadFileSize, off::kFileBytes, j);
    }
  }
  return true;
}

}  // namespace

bool looksChunked(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < off::kVersion + 2 || std::memcmp(bytes.data(), format::kMagic, 4) != 0)
    return false;
  const std::uint16_t version = readU16(bytes.data() + off::kVersion);
  return version == chunked::kVersion3 || version == chunked::kVersion5 ||
         version == chunked::kVersion7;
}

std::optional<std::uint64_t> chunkedHeadBytes(std::span<const std::uint8_t> bytes,
                                              ChunkedIssue* issue) {
  if (bytes.size() < chunked::kFixedHeaderBytes) {
    fail(issue, ChunkedError::kTruncatedHead, bytes.size());
    return std::nullopt;
  }
  const std::uint8_t* p = bytes.data();
  bool ok = true;
  if (std::memcmp(p, format::kMagic, sizeof format::kMagic) != 0) {
    ok = fail(issue, ChunkedError::kBadMagic, 0);
  } else if (!looksChunked(bytes)) {
    ok = fail(issue, ChunkedError::kUnsupportedVersion, off::kVersion);
  } else if (p[off::kLevelCount] < 2 || p[off::kLevelCount] > chunked::kMaxChunkedLevels) {
    ok = fail(issue, ChunkedError::kBadLevelCount, off::kLevelCount);
  } else if ((p[off::kFlags] & ~chunked::kFlagSyntheticColour) != 0) {
    ok = fail(issue, ChunkedError::kBadFlags, off::kFlags);  // normals, or a bit nobody knows
  } else if (readU16(p + off::kNormalCount) != 0) {
    ok = fail(issue, ChunkedError::kBadReservedField, off::kNormalCount);
  } else if (readU16(p + off::kPaletteCount) < 1 ||
             readU16(p + off::kPaletteCount) > format::kPaletteEntries) {
    ok = fail(issue, ChunkedError::kBadPaletteCount, off::kPaletteCount);
  } else if (readU32(p + off::kHeadBytes) != impliedHeadBytes(p) ||
             impliedHeadBytes(p) > kMaxHeadBytes) {
    ok = fail(issue, ChunkedError::kBadHeadSize, off::kHeadBytes);
  } else if (readU64(p + off::kFileBytes) > chunked::kMaxFileBytes) {
    ok = fail(issue, ChunkedError::kBadFileSize, off::kFileBytes);
  }
  if (!ok) return std::nullopt;
  return readU32(p + off::kHeadBytes);
}

std::optional<ChunkedHead> parseChunkedHead(std::span<const std::uint8_t> bytes,
                                            ChunkedIssue* issue) {
  const std::optional<std::uint64_t> head_bytes = chunkedHeadBytes(bytes, issue);
  if (!head_bytes) return std::nullopt;
  if (bytes.size() < *head_bytes) {
    fail(issue, ChunkedError::kTruncatedHead, bytes.size());
    return std::nullopt;
  }
  const std::uint8_t* p = bytes.data();
  const auto crc_at = static_cast<std::size_t>(*head_bytes - chunked::kHeadCrcBytes);
  if (crc32(bytes.first(crc_at)) != readU32(p + crc_at)) {
    fail(issue, ChunkedError::kBadHeadCrc, crc_at);
    return std::nullopt;
  }
  ChunkedHead head;
  head.format_version = readU16(p + off::kVersion);
  head.cube_edge_pm = readU64(p + off::kCubeEdge);
  if (hasPlacement(p)) {
    const std::size_t placement_at = crc_at - format::kCubePlacementBytes;
    if (!readCubePlacement(p + placement_at, &head.cube)) {
      fail(issue, ChunkedError::kBadCubePlacement, placement_at);
      return std::nullopt;
    }
  }
  head.flags = p[off::kFlags];
  head.palette_count = readU16(p + off::kPaletteCount);
  std::memcpy(head.palette_rgb.data(), p + off::kPalette,
              3 * static_cast<std::size_t>(head.palette_count));
  head.head_bytes = *head_bytes;
  head.file_bytes = readU64(p + off::kFileBytes);
  head.level_count = p[off::kLevelCount];
  if (!readLevelRows(p, head, issue)) return std::nullopt;

  const std::size_t base_at = chunked::kFixedHeaderBytes +
                              3 * static_cast<std::size_t>(head.palette_count) +
                              chunked::kLevelRowBytes * static_cast<std::size_t>(head.level_count);
  const std::size_t node_bytes = readU32(p + off::kBaseNodeBytes);
  const std::size_t leaf_count = readU32(p + off::kBaseLeafCount);
  const LevelView base{head.levels[0].depth, bytes.subspan(base_at, node_bytes),
                       bytes.subspan(base_at + node_bytes, leaf_count)};
  const ModelIssue base_issue = validateLevelStream(base, head.palette_count);
  if (base_issue.error != ModelError::kNone) {
    const std::uint64_t where =
        base_issue.offset + (base_issue.error == ModelError::kLeafOutsidePalette ||
                                     base_issue.error == ModelError::kLeafCountMismatch
                                 ? base_at + node_bytes
                                 : base_at);
    fail(issue, ChunkedError::kBadBase, where, 0);
    return std::nullopt;
  }
  head.base_nodes.assign(base.nodes.begin(), base.nodes.end());
  head.base_leaves.assign(base.leaves.begin(), base.leaves.end());
  if (issue != nullptr) *issue = {};
  return head;
}

const char* describe(ChunkedError error) {
  switch (error) {
    case ChunkedError::kNone:
      return "no error";
    case ChunkedError::kTruncatedHead:
      return "truncated head";
    case ChunkedError::kBadMagic:
      return "not an octopoint model (bad magic)";
    case ChunkedError::kUnsupportedVersion:
      return "not a chunked model (format version is not 3 or 5)";
    case ChunkedError::kBadLevelCount:
      return "bad level count";
    case ChunkedError::kBadFlags:
      return "unknown flags";
    case ChunkedError::kBadReservedField:
      return "reserved field is not zero";
    case ChunkedError::kBadPaletteCount:
      return "bad palette colour count";
    case ChunkedError::kBadHeadSize:
      return "head size does not match its contents";
    case ChunkedError::kBadFileSize:
      return "file size does not fit the tables and chunk offsets";
    case ChunkedError::kBadHeadCrc:
      return "head CRC-32 mismatch";
    case ChunkedError::kBadDepth:
      return "depth outside the supported range";
    case ChunkedError::kDepthsNotAscending:
      return "level depths are not strictly ascending";
    case ChunkedError::kBadRegionLevel:
      return "bad region level";
    case ChunkedError::kTooManyChunks:
      return "chunk count impossible for the region level";
    case ChunkedError::kBadBase:
      return "base stream is not a valid octree";
    case ChunkedError::kTableOutOfOrder:
      return "record table offered before the coarser level's";
    case ChunkedError::kBadTableSize:
      return "record table has the wrong size";
    case ChunkedError::kBadTableCrc:
      return "record table CRC-32 mismatch";
    case ChunkedError::kRegionsNotAscending:
      return "regions are not strictly ascending";
    case ChunkedError::kRegionOutsideLevel:
      return "region code outside its region level";
    case ChunkedError::kNoCoarserChunk:
      return "region lies in no chunk of the coarser level";
    case ChunkedError::kCoarseCountMismatch:
      return "coarse counts do not add up to the coarser chunk's points";
    case ChunkedError::kImplausibleChunk:
      return "chunk sizes impossible for a refinement";
    case ChunkedError::kChunkBytesMismatch:
      return "chunk sizes do not fill the level's bytes";
    case ChunkedError::kUnknownChunk:
      return "no such chunk (or its level's table is not known yet)";
    case ChunkedError::kWrongChunkLength:
      return "chunk has the wrong length";
    case ChunkedError::kBadChunkCrc:
      return "chunk CRC-32 mismatch";
    case ChunkedError::kChunkTruncated:
      return "chunk refinement truncated";
    case ChunkedError::kChunkEmptyNode:
      return "inner node without children in a chunk";
    case ChunkedError::kChunkTrailingBytes:
      return "trailing mask bytes in a chunk";
    case ChunkedError::kChunkLeafCountMismatch:
      return "chunk leaf count does not match its record";
    case ChunkedError::kChunkLeafOutsidePalette:
      return "chunk leaf colour index outside the palette";
    case ChunkedError::kChunkDisagrees:
      return "chunk voxels disagree with the finer level's regions";
    case ChunkedError::kBadCubePlacement:
      return "cube placement not finite, edge not above 0, or unknown scan axes";
    case ChunkedError::kBadSampleReach:
      return "level sample reach outside 16..128 sixteenths of a footprint";
  }
  return "unknown error";
}

}  // namespace octopoint
