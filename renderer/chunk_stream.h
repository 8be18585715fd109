#pragma once
// One chunk of a chunked model (renderer/chunked_format.h): checking its bytes on their own, and
// turning it, with the coarser stream it refines, into the ordinary octree stream of its region
// that the decoders draw (renderer/model_format.h's layout, rooted at the region instead of the
// cube).

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "renderer/chunk_records.h"
#include "renderer/chunked_errors.h"

namespace octopoint {

// Checks a chunk against its record without anything else: its length and CRC-32, then a walk of
// its `record.coarse_points` refinements of `gap` tree levels each (a first mask may be 0, masks
// below it never are), which must use exactly its mask bytes and have exactly `record.points`
// leaves, each inside the palette. Cost: one pass over the bytes; no allocation.
ChunkedIssue validateChunk(std::span<const std::uint8_t> bytes, const ChunkRecord& record, int gap,
                           int palette_count);

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
