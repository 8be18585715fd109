#pragma once
// Where the subtrees of one tree level end in a level's depth-first stream: what lets fixed_fast
// and fixed_simd step over an off-screen subtree without reading its bytes (renderer/skip_runs.h,
// skipSubtreeIndexed).
//
// A depth-first stream has no index: zoomed in, most of a frame's subtrees are off screen, and
// passing one meant reading all its mask bytes to find where the next begins (lms400 at depth 9,
// 176x208 zoom 4: 27% of the frame's instructions). The index records, for every node of one tree
// level in stream order, the offsets just past its subtree in the node stream and in the leaves. A
// walk that counts the nodes of that level it passes knows which entry is next; an off-screen
// subtree at that level is then one look-up, one above it costs only its nodes above that level.
//
// It depends on the model only, not on the camera: ModelView builds it once when it validates a
// model, on the heap (hosted builds; a bare-metal build has none and keeps the byte walk), 8 bytes
// per node of the indexed level, the leaves' great-grandparents. Each of those has at least 3 mask
// bytes below and at it, so the index is at most 8/3 of a level's node bytes; measured, 6% of the
// nodes: 55 KB for lms400 at depths 6..9 (a 404 KB file), 16 KB for the default model (125 KB).
// It is built from a validated stream only, so a corrupt one fails validation before. Frames are
// the same bit for bit with the index or without it.

#include <cstddef>
#include <cstdint>
#include <span>

namespace octopoint {

struct LevelView;

struct SubtreeEnd {
  std::uint32_t node;  // node stream offset just past the subtree
  std::uint32_t leaf;  // leaf offset just past it (its last leaf's index + 1)
};

#if !defined(OCTOPOINT_BARE_METAL)
struct SkipIndex {
  int level = 0;                      // the indexed tree level, >= 1; 0: no index
  std::span<const SubtreeEnd> ends;   // one per node at `level`, in stream order
};
#else
// A bare-metal build has no index: an empty type, which costs a LevelView no RAM
// ([[no_unique_address]]); the decoders' indexed branch is never taken.
struct SkipIndex {
  static constexpr int level = 0;
  static constexpr std::span<const SubtreeEnd> ends{};
};
#endif

// The tree level ModelView indexes in a level of `depth`: the leaves' great-grandparents
// (depth - 3), or 0 (none) for depths below 4, whose subtrees are a few bytes.
int skipIndexLevel(int depth);

// The number of entries the index of `level` needs (its nodes at skipIndexLevel), 0 when none;
// also 0 when an offset would not fit 32 bits.
std::size_t skipIndexEntries(const LevelView& level);

// Fills `storage` (at least skipIndexEntries(level) entries) and returns the index, or no index
// (level 0) when `level` has none or the storage is too small. `level` must be validated
// (ModelView): the walk trusts its stream.
SkipIndex buildSkipIndex(const LevelView& level, std::span<SubtreeEnd> storage);

}  // namespace octopoint
