#pragma once
// The chunked model format, version 3 (docs/format.md): one model cut into chunks that can be
// fetched, checked and drawn one by one, and a file that refines the whole model coarse to fine
// when read front to back. All integers are little-endian.
//
// Levels. A chunked model has L levels: level 0, the base, holds the whole model at a coarse depth
// d0 as one ordinary octree stream (renderer/model_format.h); levels 1..L-1 hold ever finer depths
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
//   4      2    format version, 3
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
//   then   20 L level table: u8 depth, u8 region level, u16 reserved 0, u32 chunk count,
//                u32 CRC-32 of the level's record table, u64 file offset of the level's first
//                chunk. Row 0 is the base: region level, chunk count, CRC and offset 0.
//   then        base node bytes, base leaf palette indices
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

#include <cstddef>
#include <cstdint>

#include "renderer/model_format.h"

namespace octopoint::chunked {

inline constexpr std::uint16_t kFormatVersion = 3;
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
