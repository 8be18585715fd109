#pragma once
// Random access to the upper tree levels of one level's stream (docs/perspective.md, "Detail by
// distance" and "Occlusion culling"): for every node from the root down to the leaves'
// great-grandparents, where its mask byte and its first leaf are, and where its children's entries
// begin. A depth-first stream is read in order only; with this index the perspective walk visits a
// node's children nearest first (occlusion culling wants front to back), and passes over a subtree
// that another depth draws, or that is hidden, without reading its bytes. Built once per model, in
// one pass over the stream, in storage the caller provides (no heap: a device build can keep it in
// a static array); 12 bytes a node, about 1/8 of the leaves' great-grandparents' subtrees' bytes.

#include <cstddef>
#include <cstdint>
#include <span>

#include "octopoint/model.h"

namespace octopoint {

struct UpperTreeNode {
  std::uint32_t node = 0;         // the offset of its mask byte in the level's node stream
  std::uint32_t leaf = 0;         // the index of its first leaf
  std::uint32_t first_child = 0;  // the entry of its first child (its children's are consecutive)
};

struct UpperTreeIndex {
  int bottom = -1;                         // the deepest tree level indexed; -1: no index
  std::span<const UpperTreeNode> entries;  // level by level, each in stream order: the root first
};

// The deepest tree level indexed for a level of `depth`: the leaves' great-grandparents (depth -
// 3), as the skip index (octopoint/model.h); the root alone below depth 4.
int upperTreeBottom(int depth);

// The entries `level`'s index needs; 0 when an offset would not fit 32 bits.
std::size_t upperTreeEntries(const LevelView& level);

// Fills `storage` (at least upperTreeEntries(level) entries) and returns the index; no index
// (bottom -1) when the storage is too small or the level needs none. `level` must be validated
// (ModelView): the walk trusts its stream.
UpperTreeIndex buildUpperTreeIndex(const LevelView& level, std::span<UpperTreeNode> storage);

}  // namespace octopoint
