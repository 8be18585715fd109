#include <array>

#include "octopoint/bands.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {
namespace {

// Counts the nodes of the subtree at `node` per level and returns the stream just past it.
const std::uint8_t* countSubtree(const std::uint8_t* node, int level, int depth,
                                 std::uint32_t* counts) {
  ++counts[level];
  const unsigned mask = *node++;
  if (level + 1 == depth) return node;
  for (int child = childCount(mask); child > 0; --child)
    node = countSubtree(node, level + 1, depth, counts);
  return node;
}

struct IndexWalk {
  const std::uint8_t* nodes;
  const std::uint8_t* leaves;
  int index_level;
  int depth;
  std::span<SubtreeSize> storage;
  std::size_t count = 0;

  // Walks the levels above the index level; records each index-level subtree's size.
  void visit(const std::uint8_t*& node, const std::uint8_t*& leaf, int level) {
    if (level == index_level) {
      const std::uint8_t* const node_begin = node;
      const std::uint8_t* const leaf_begin = leaf;
      skipSubtree(node, leaf, level, depth);
      storage[count++] = {static_cast<std::uint16_t>(node - node_begin),
                          static_cast<std::uint16_t>(leaf - leaf_begin)};
      return;
    }
    const unsigned mask = *node++;
    for (int child = childCount(mask); child > 0; --child) visit(node, leaf, level + 1);
  }
};

}  // namespace

void countNodesPerLevel(const LevelView& level, std::span<std::uint32_t> counts) {
  for (int l = 0; l < level.depth; ++l) counts[static_cast<std::size_t>(l)] = 0;
  countSubtree(level.nodes.data(), 0, level.depth, counts.data());
}

bool indexLevelAllowed(int depth, int index_level) {
  return index_level >= 1 && index_level + 2 <= depth &&
         depth - index_level <= kMaxIndexedSubtreeLevels;
}

int deepestIndexLevel(const LevelView& level, std::size_t capacity) {
  std::array<std::uint32_t, format::kMaxDepth> counts{};
  countNodesPerLevel(level, counts);
  int best = 0;
  for (int l = 1; l < level.depth; ++l) {
    if (indexLevelAllowed(level.depth, l) && counts[static_cast<std::size_t>(l)] <= capacity)
      best = l;
  }
  return best;
}

BandIndex buildBandIndex(const LevelView& level, int index_level, std::span<SubtreeSize> storage) {
  if (!indexLevelAllowed(level.depth, index_level)) return {};
  std::array<std::uint32_t, format::kMaxDepth> counts{};
  countNodesPerLevel(level, counts);
  const std::uint32_t needed = counts[static_cast<std::size_t>(index_level)];
  if (needed > storage.size()) return {};
  IndexWalk walk{level.nodes.data(), level.leaves.data(), index_level, level.depth, storage};
  const std::uint8_t* node = walk.nodes;
  const std::uint8_t* leaf = walk.leaves;
  walk.visit(node, leaf, 0);
  return {index_level, storage.first(walk.count)};
}

}  // namespace octopoint
