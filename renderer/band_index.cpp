#include "renderer/band_index.h"

#include <array>

#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {
namespace {

// Counts the nodes of the subtree at `node` per level and returns the stream just past it.
const std::uint8_t* countSubtree(const std::uint8_t* node, int level, int depth, std::uint32_t* counts) {
  ++counts[level];
  const unsigned mask = *node++;
  if (level + 1 == depth) return node;
  for (int child = childCount(mask); child > 0; --child) node = countSubtree(node, level + 1, depth, counts);
  return node;
}

struct IndexWalk {
  const std::uint8_t* nodes;
  const std::uint8_t* leaves;
  int index_level;
  int depth;
  std::span<SubtreeEnd> storage;
  std::size_t count = 0;

  // Walks the levels above the index level; records where each index-level subtree ends.
  void visit(const std::uint8_t*& node, const std::uint8_t*& leaf, int level) {
    if (level == index_level) {
      skipSubtree(node, leaf, level, depth);
      storage[count++] = {static_cast<std::uint32_t>(node - nodes), static_cast<std::uint32_t>(leaf - leaves)};
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

int deepestIndexLevel(const LevelView& level, std::size_t capacity) {
  std::array<std::uint32_t, format::kMaxDepth> counts{};
  countNodesPerLevel(level, counts);
  int best = 0;
  for (int l = 1; l + 1 < level.depth; ++l) {
    if (counts[static_cast<std::size_t>(l)] <= capacity) best = l;
  }
  return best;
}

BandIndex buildBandIndex(const LevelView& level, int index_level, std::span<SubtreeEnd> storage) {
  if (index_level < 1 || index_level >= level.depth) return {};
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
