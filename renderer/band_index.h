#pragma once
// Where the subtrees of one tree level end in a level's depth-first stream: what lets band
// rendering (renderer/band_renderer.h) jump straight to the subtrees that meet a band instead of
// stepping over the bytes of every other one, once per band.
//
// A depth-first stream has no index: a subtree's bytes can only be passed by reading them all
// (skipSubtree). The index remembers, for every node at `level` in stream order, how many node
// bytes and leaves its subtree has; the band walk reaches the subtrees in stream order, so it knows
// where each begins and, with its size, where it ends. Sizes fit 16 bits when the subtree has at
// most 5 levels (at most 4,681 nodes and 32,768 leaves), so the index costs 4 bytes per node of
// its level. It depends on the model only, not on the camera: build it once at set-up, into memory
// the caller provides, and keep it for every frame. Level 0 needs no memory and means "no index":
// each band then walks the whole tree.

#include <cstddef>
#include <cstdint>
#include <span>

#include "renderer/model.h"

namespace octopoint {

struct SubtreeSize {
  std::uint16_t nodes;   // mask bytes of the subtree
  std::uint16_t leaves;  // its leaves
};

// The most levels an indexed subtree may have: its sizes must fit SubtreeSize.
inline constexpr int kMaxIndexedSubtreeLevels = 5;

struct BandIndex {
  int level = 0;                       // 0: no index; else depth - 5 .. depth - 2, at least 1
  std::span<const SubtreeSize> sizes;  // one per node at `level`, in stream order
};

// The number of nodes at each tree level 0..depth-1 (`counts` has at least level.depth entries).
void countNodesPerLevel(const LevelView& level, std::span<std::uint32_t> counts);

// Whether an index can be built at `index_level` for a level of `depth`: below the root, above the
// leaf parents' parents, and its subtrees at most kMaxIndexedSubtreeLevels deep.
bool indexLevelAllowed(int depth, int index_level);

// The deepest allowed index level whose nodes fit `capacity` entries, 0 when none does.
int deepestIndexLevel(const LevelView& level, std::size_t capacity);

// Fills `storage` with the sizes of the subtrees at `index_level` and returns the index, or an
// index of level 0 when the level is not allowed or its nodes do not fit.
BandIndex buildBandIndex(const LevelView& level, int index_level, std::span<SubtreeSize> storage);

}  // namespace octopoint
