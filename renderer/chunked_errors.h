#pragma once
// What can be wrong with a chunked model (renderer/chunked_format.h): its head, a record table, or
// one chunk. Each failure has its own error and a one-line description; the offset says where in
// the file it was found.

#include <cstddef>
#include <cstdint>

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
  kChunkDisagrees,  // the chunk's voxels do not match the regions the next level's table lists
};

// A short, stable English description, for one-line messages.
const char* describe(ChunkedError error);

struct ChunkedIssue {
  ChunkedError error = ChunkedError::kNone;
  std::uint64_t offset = 0;  // file offset (head, tables) or offset inside the chunk
  int level = 0;             // the level concerned; 0 for the head and the base
};

}  // namespace octopoint
