#pragma once
// Where the subtrees of one tree level end in a level's depth-first stream: what lets band
// rendering (renderer/band_renderer.h) jump straight to the subtrees that meet a band instead of
// stepping over the bytes of every other one, once per band.
//
// A depth-first stream has no index: a subtree's bytes can only be passed by reading them all
// (skipSubtree). The index remembers, for every node at `level` in stream order, the node and leaf
// offsets just past its subtree. It depends on the model only, not on the camera: build it once at
// set-up, into memory the caller provides (8 bytes per node of that level), and keep it for every
// frame. Level 0 needs no memory and means "no index": each band then walks the whole tree.

#include <cstddef>
#include <cstdint>
#include <span>

#include "renderer/model.h"

namespace octopoint {

struct SubtreeEnd {
  std::uint32_t node_end;  // node byte offset just past the subtree
  std::uint32_t leaf_end;  // leaf offset just past the subtree
};

struct BandIndex {
  int level = 0;                     // 0: no index; else 1..depth-1
  std::span<const SubtreeEnd> ends;  // one per node at `level`, in stream order
};

// The number of nodes at each tree level 0..depth-1 (`counts` has at least level.depth entries).
void countNodesPerLevel(const LevelView& level, std::span<std::uint32_t> counts);

// The deepest tree level below the leaf parents' whose nodes fit `capacity` index entries, 0 when
// none below the root does.
int deepestIndexLevel(const LevelView& level, std::size_t capacity);

// Fills `storage` with the ends of the subtrees at `index_level` (1..depth-1) and returns the index,
// or an index of level 0 when they do not fit.
BandIndex buildBandIndex(const LevelView& level, int index_level, std::span<SubtreeEnd> storage);

}  // namespace octopoint
