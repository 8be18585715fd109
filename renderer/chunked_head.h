#pragma once
// Reading the head of a chunked model (renderer/chunked_format.h): the fixed header, palette, level
// table and base stream, checked against the head's CRC-32 and the format's rules before anything
// is kept. The head is everything a reader needs before its first picture: the base draws the whole
// model at a coarse depth.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "renderer/chunked_errors.h"
#include "renderer/chunked_format.h"

namespace octopoint {

struct ChunkedLevel {
  int depth = 0;
  int region_level = 0;  // the tree level of this level's regions (0 for the base)
  std::uint32_t chunk_count = 0;
  std::uint32_t table_crc = 0;
  std::uint64_t table_offset = 0;   // file offset of the level's record table
  std::uint64_t chunks_offset = 0;  // file offset of its first chunk
  std::uint64_t chunks_end = 0;  // where its chunks end: the next level's offset, or the file's end
};

struct ChunkedHead {
  std::uint64_t cube_edge_pm = 0;  // picometres; 0: not recorded
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

// Whether `bytes` begin like a version 3 model (magic and version), so that a reader of both kinds
// can tell them apart from the first 6 bytes.
bool looksChunked(std::span<const std::uint8_t> bytes);

// The head's size in bytes, read from the fixed header (the first chunked::kFixedHeaderBytes of
// the file); nullopt with the issue when those bytes already show a bad model.
std::optional<std::uint64_t> chunkedHeadBytes(std::span<const std::uint8_t> fixed_header,
                                              ChunkedIssue* issue);

// Parses and checks the head; `bytes` must hold at least the head (any bytes after it are ignored).
// The result owns copies of everything it keeps.
std::optional<ChunkedHead> parseChunkedHead(std::span<const std::uint8_t> bytes,
                                            ChunkedIssue* issue);

}  // namespace octopoint
