#pragma once
// octopoint/chunked.h: the chunked model format (docs/format.md): what can be wrong with one,
// its layout, reading its head, its record tables and checking a chunk on its own. The model that
// fills in as the parts arrive is octopoint/progressive.h; the manual of the whole library is
// octopoint/octopoint.h.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/model.h"

// What can be wrong with a chunked model (octopoint/chunked.h): its head, a record table, or
// one chunk. Each failure has its own error and a one-line description; the offset says where in
// the file it was found.

namespace octopoint {

enum class ChunkedError : std::uint8_t {
  kNone,
  // The head.
  kTruncatedHead,       // fewer bytes than the fixed header or the head size says
  kBadMagic,            // not an octopoint model
  kUnsupportedVersion,  // not version 3
  kBadLevelCount,       // fewer than 2 or more than kMaxChunkedLevels levels
  kBadFlags,            // a flag this reader does not know
  kBadReservedField,    // a reserved field is not zero
  kBadPaletteCount,     // 0 or more than 256 colours
  kBadHeadSize,         // the head size does not match the palette, level table and base
  kBadFileSize,         // the file size does not fit the head, the tables and the level offsets
  kBadHeadCrc,          // the head's CRC-32 does not match
  kBadDepth,            // a depth outside 1..16
  kDepthsNotAscending,  // the same depth twice, or out of order
  kBadRegionLevel,      // region levels decreasing, too deep, or not coarser than the level refined
  kTooManyChunks,       // a chunk count of 0, more than the regions there are, or past kMaxChunks
  kBadBase,             // the base stream is not a valid octree stream (see its ModelError)
  // A record table.
  kTableOutOfOrder,      // a level's table offered before the table of the level above it
  kBadTableSize,         // not exactly 20 bytes per chunk
  kBadTableCrc,          // the table's CRC-32 does not match the level table
  kRegionsNotAscending,  // the same region twice, or out of order
  kRegionOutsideLevel,   // a region code with more bits than the region level has
  kNoCoarserChunk,       // a region inside no chunk of the level above
  kCoarseCountMismatch,  // the chunks inside a coarser chunk refine a different number of voxels
  kImplausibleChunk,     // chunk bytes, point and coarse counts no refinement can have
  kChunkBytesMismatch,   // a level's chunk bytes do not fill its part of the file
  // One chunk.
  kUnknownChunk,             // no such chunk, or its level's table is not known yet
  kWrongChunkLength,         // not the chunk's declared number of bytes
  kBadChunkCrc,              // the chunk's CRC-32 does not match its record
  kChunkTruncated,           // the refinement needs more mask bytes than the chunk has
  kChunkEmptyNode,           // a zero mask below the first level of a refinement
  kChunkTrailingBytes,       // mask bytes left after the last refinement
  kChunkLeafCountMismatch,   // the refinements have a different number of leaves than declared
  kChunkLeafOutsidePalette,  // a leaf names a colour past the palette count
  kChunkDisagrees,    // the chunk's voxels do not match the regions the next level's table lists
  kBadCubePlacement,  // version 5: the cube's placement is not one a file may hold
  kBadSampleReach,    // version 7: a level's sample reach outside 16..128 (Q4 footprints)
};

// A short, stable English description, for one-line messages.
const char* describe(ChunkedError error);

struct ChunkedIssue {
  ChunkedError error = ChunkedError::kNone;
  std::uint64_t offset = 0;  // file offset (head, tables) or offset inside the chunk
  int level = 0;             // the level concerned; 0 for the head and the base
};

}  // namespace octopoint

// The chunked model format, version 3 (docs/format.md): one model cut into chunks that can be
// fetched, checked and drawn one by one, and a file that refines the whole model coarse to fine
// when read front to back. All integers are little-endian.
//
// Levels. A chunked model has L levels: level 0, the base, holds the whole model at a coarse depth
// d0 as one ordinary octree stream (octopoint/model.h); levels 1..L-1 hold ever finer depths
// d1 < d2 < ... Level j cuts the cube into regions at tree level r_j (its region level) and holds
// one chunk per region that contains some voxel of level j-1. A chunk is a refinement: for every
// voxel of level j-1 inside its region, in depth-first order, the subtree that voxel becomes at
// depth d_j (d_j - d_{j-1} tree levels of child masks); then the palette index of every new leaf.
// So a chunk repeats nothing its coarser level already said, and it can be drawn only once the
// chunk it refines is held.
//
// Layout:
//   head     fixed header (kFixedHeaderBytes), palette, level table, base stream, head CRC
//   tables   one record table per level 1..L-1, kRecordBytes per chunk, regions ascending
//   chunks   level 1's chunks in record order, then level 2's, ...; the file ends after the last
//
// Fixed header:
//   offset size field
//   0      4    magic "OCTP"
//   4      2    format version, 3, 5 or 7 (5: version 3 with the cube's placement, below; 7:
//                version 5 with each level's sample reach in the level table)
//   6      1    level count L, 2..kMaxChunkedLevels
//   7      1    flags, as in version 2: bit 1 synthetic colour (the scan had none: the palette is a
//                depth shade); bit 0 (per-leaf normals: a normal palette after the colour palette
//                and each chunk's normal indices after its colour indices) is kept for a later
//                reader and refused by this one; other bits 0
//   8      8    cube edge in picometres (the metric size of the model cube; 0: not recorded)
//   16     2    palette colour count P, 1..256
//   18     2    normal count, 0 (until normals are read)
//   20     4    head bytes H: from offset 0 to the end of the head CRC
//   24     8    file bytes: the whole file
//   32     4    base node bytes
//   36     4    base leaf count
//   40     3 P  palette, RGB888
//   then   20 L level table: u8 depth, u8 region level, u8 sample reach (version 7: the level's
//                splat reach in sixteenths of a footprint, format::kOneSampleReachQ4..
//                kMaxSampleReachQ4, as in `.oct` version 6; earlier versions: reserved 0, one
//                footprint), u8 reserved 0, u32 chunk count,
//                u32 CRC-32 of the level's record table, u64 file offset of the level's first
//                chunk. Row 0 is the base: region level, chunk count, CRC and offset 0.
//   then        base node bytes, base leaf palette indices
//   then   40   version 5 only: the cube's placement in the scan (format::kCubePlacementBytes,
//                octopoint/model.h's CubePlacement); version 3 has none
//   H - 4  4    CRC-32 of bytes [0, H - 4)
//
// Record (kRecordBytes), one per chunk:
//   0  4  region: Morton code of the region at the level's region level r (3 r bits, the child
//         index k = (x << 2) | (y << 1) | z of each tree level from the root, the root's highest)
//   4  4  chunk bytes
//   8  4  point count: the chunk's leaves (voxels of depth d_j)
//   12 4  coarse count: the voxels of level j-1 in the region, which the chunk refines
//   16 4  CRC-32 of the chunk's bytes
//
// Chunk bytes: the refinement masks (a voxel whose refinement's first mask is 0 has nothing at the
// finer depth; masks below the first are never 0), then `point count` palette indices.
//
// Rules a valid file obeys (the reader checks every one): depths strictly ascending in 1..16;
// region levels non-decreasing, r_j < d_{j-1} (a region is larger than a voxel of the level it
// refines), r_j <= kMaxRegionLevel; regions of a level strictly ascending, each inside a region of
// the level before (level 1: inside the root); the coarse counts of the chunks inside one coarser
// chunk add up to its point count (level 1: to the base's leaf count); the record tables follow the
// head back to back, level 1's chunks follow the last table, each level's chunks fill exactly the
// bytes from its offset to the next level's (the last: to the end of the file).

namespace octopoint::chunked {

inline constexpr std::uint16_t kVersion3 = 3;
inline constexpr std::uint16_t kVersion5 = 5;  // version 3 and the cube's placement
inline constexpr std::uint16_t kVersion7 = 7;  // version 5 and each level's sample reach
inline constexpr std::uint16_t kFormatVersion = kVersion7;        // what the preparer writes
inline constexpr int kMaxChunkedLevels = format::kMaxLevels + 1;  // the base and up to 8 depths
inline constexpr int kMaxRegionLevel = 10;                        // 30-bit Morton codes
inline constexpr std::size_t kFixedHeaderBytes = 40;
inline constexpr std::size_t kLevelRowBytes = 20;
inline constexpr std::size_t kRecordBytes = 20;
inline constexpr std::size_t kHeadCrcBytes = 4;
// Bounds that keep what a reader allocates proportional to what it was sent: no more chunks in a
// model than this, and no file larger than this.
inline constexpr std::uint64_t kMaxChunks = std::uint64_t{1} << 22;
inline constexpr std::uint64_t kMaxFileBytes = std::uint64_t{1} << 40;

// Header flags (the same bits as format version 2).
inline constexpr std::uint8_t kFlagNormals = 1u << 0;          // not read yet: refused
inline constexpr std::uint8_t kFlagSyntheticColour = 1u << 1;  // the palette is a depth shade

// Where each part of the fixed header is.
namespace offset {
inline constexpr std::size_t kVersion = 4;
inline constexpr std::size_t kLevelCount = 6;
inline constexpr std::size_t kFlags = 7;
inline constexpr std::size_t kCubeEdge = 8;
inline constexpr std::size_t kPaletteCount = 16;
inline constexpr std::size_t kNormalCount = 18;
inline constexpr std::size_t kHeadBytes = 20;
inline constexpr std::size_t kFileBytes = 24;
inline constexpr std::size_t kBaseNodeBytes = 32;
inline constexpr std::size_t kBaseLeafCount = 36;
inline constexpr std::size_t kPalette = 40;
}  // namespace offset

}  // namespace octopoint::chunked

// Reading the head of a chunked model (octopoint/chunked.h): the fixed header, palette, level
// table and base stream, checked against the head's CRC-32 and the format's rules before anything
// is kept. The head is everything a reader needs before its first picture: the base draws the whole
// model at a coarse depth.

namespace octopoint {

struct ChunkedLevel {
  int depth = 0;
  int region_level = 0;  // the tree level of this level's regions (0 for the base)
  std::uint32_t chunk_count = 0;
  std::uint32_t table_crc = 0;
  std::uint64_t table_offset = 0;   // file offset of the level's record table
  std::uint64_t chunks_offset = 0;  // file offset of its first chunk
  std::uint64_t chunks_end = 0;  // where its chunks end: the next level's offset, or the file's end
  // How wide its splats are drawn, in sixteenths of a footprint: stored by version 7, one
  // footprint in versions 3 and 5.
  std::int32_t sample_reach = format::kOneSampleReachQ4;
};

struct ChunkedHead {
  int format_version = 0;          // chunked::kVersion3, kVersion5 or kVersion7
  std::uint64_t cube_edge_pm = 0;  // picometres; 0: not recorded
  CubePlacement cube{};            // versions 5 and 7; not recorded in version 3
  std::uint8_t flags = 0;          // chunked::kFlagSyntheticColour or 0
  int palette_count = 0;
  std::array<std::uint8_t, 3 * format::kPaletteEntries> palette_rgb{};  // zero past the count
  std::uint64_t head_bytes = 0;
  std::uint64_t file_bytes = 0;
  int level_count = 0;  // the base and the chunked levels
  std::array<ChunkedLevel, chunked::kMaxChunkedLevels> levels{};
  std::vector<std::uint8_t> base_nodes;  // the base: an octree stream of depth levels[0].depth
  std::vector<std::uint8_t> base_leaves;
};

// The largest head a reader accepts: a few kilobytes in files the preparer writes.
inline constexpr std::uint64_t kMaxHeadBytes = std::uint64_t{1} << 24;

// Whether `bytes` begin like a chunked model, version 3 or 5 (magic and version), so that a reader
// of both kinds can tell them apart from the first 6 bytes.
[[nodiscard]] bool looksChunked(std::span<const std::uint8_t> bytes);

// The head's size in bytes, read from the fixed header (the first chunked::kFixedHeaderBytes of
// the file); nullopt with the issue when those bytes already show a bad model.
[[nodiscard]] std::optional<std::uint64_t> chunkedHeadBytes(
    std::span<const std::uint8_t> fixed_header, ChunkedIssue* issue);

// Parses and checks the head; `bytes` must hold at least the head (any bytes after it are ignored).
// The result owns copies of everything it keeps.
[[nodiscard]] std::optional<ChunkedHead> parseChunkedHead(std::span<const std::uint8_t> bytes,
                                                          ChunkedIssue* issue);

}  // namespace octopoint

// The record tables of a chunked model (octopoint/chunked.h): one record per chunk, saying
// where the chunk is in space (its region) and in the file, how many voxels it refines and holds,
// and its CRC-32. A table is checked against the head and the coarser level's table, so that every
// chunk can afterwards be checked on its own.

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
[[nodiscard]] std::optional<std::vector<ChunkRecord>> parseRecordTable(
    std::span<const std::uint8_t> bytes, const ChunkedHead& head, int level,
    std::span<const ChunkRecord> coarser, ChunkedIssue* issue);

}  // namespace octopoint

// One chunk of a chunked model (octopoint/chunked.h): checking its bytes on their own, and
// turning it, with the coarser stream it refines, into the ordinary octree stream of its region
// that the decoders draw (octopoint/model.h's layout, rooted at the region instead of the
// cube).

namespace octopoint {

// Checks a chunk against its record without anything else: its length and CRC-32, then a walk of
// its `record.coarse_points` refinements of `gap` tree levels each (a first mask may be 0, masks
// below it never are), which must use exactly its mask bytes and have exactly `record.points`
// leaves, each inside the palette. Cost: one pass over the bytes; no allocation.
[[nodiscard]] ChunkedIssue validateChunk(std::span<const std::uint8_t> bytes,
                                         const ChunkRecord& record, int gap, int palette_count);

// Where a region's subtree lies inside a larger depth-first stream: its node bytes and its leaves.
struct StreamRange {
  std::uint32_t node_begin = 0, node_end = 0;
  std::uint32_t leaf_begin = 0, leaf_end = 0;
  std::uint32_t leafCount() const { return leaf_end - leaf_begin; }
};

// Builds a region's stream at the finer depth. `coarse_nodes` is the region's (validated) stream at
// the coarser depth, `coarse_levels` >= 1 tree levels deep; `chunk` is its validated refinement by
// `gap` levels, whose coarse count is the coarse stream's leaf count. Voxels whose refinement is
// empty disappear, and so do nodes left without children. Appends the result to `nodes` and
// `leaves` (the chunk's palette indices, which keep their order).
void refineRegion(std::span<const std::uint8_t> coarse_nodes, int coarse_levels,
                  std::span<const std::uint8_t> chunk, std::uint32_t points, int gap,
                  std::vector<std::uint8_t>& nodes, std::vector<std::uint8_t>& leaves);

// Calls `visit(code, range)`, in ascending order of code, for every node `level_below` tree levels
// under the root of a validated stream `levels` deep (level_below < levels): `code` is the node's
// Morton code relative to the stream's root (3 bits per level), `range` where its subtree lies.
// level_below = 0 visits the whole stream as code 0.
void forEachSubregion(
    std::span<const std::uint8_t> nodes, std::span<const std::uint8_t> leaves, int levels,
    int level_below,
    const std::function<void(std::uint32_t code, const StreamRange& range)>& visit);

}  // namespace octopoint
