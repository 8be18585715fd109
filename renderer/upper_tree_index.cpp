#include "renderer/upper_tree_index.h"

#include <array>
#include <limits>

#include "octopoint/bands.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {
namespace {

struct UpperTreeWalk {
  const std::uint8_t* node_begin;
  const std::uint8_t* leaf_begin;
  int bottom;
  int depth;
  UpperTreeNode* entries;
  // The next entry of each level: level l's entries begin after the counts of the levels above.
  std::array<std::uint32_t, format::kMaxDepth + 1> next{};

  void visit(const std::uint8_t*& node, const std::uint8_t*& leaf, int level) {
    const auto l = static_cast<std::size_t>(level);
    entries[next[l]++] = {static_cast<std::uint32_t>(node - node_begin),
                          static_cast<std::uint32_t>(leaf - leaf_begin), next[l + 1]};
    if (level == bottom) {
      skipSubtree(node, leaf, level, depth);
      return;
    }
    for (int child = childCount(*node++); child > 0; --child) visit(node, leaf, level + 1);
  }
};

}  // namespace

int upperTreeBottom(int depth) { return depth >= 4 ? depth - 3 : 0; }

std::size_t upperTreeEntries(const LevelView& level) {
  if (level.depth < 1 || level.nodes.empty() ||
      level.nodes.size() > std::numeric_limits<std::uint32_t>::max() ||
      level.leaves.size() > std::numeric_limits<std::uint32_t>::max()) {
    return 0;
  }
  std::array<std::uint32_t, format::kMaxDepth> counts{};
  countNodesPerLevel(level, counts);
  std::size_t entries = 0;
  for (int l = 0; l <= upperTreeBottom(level.depth); ++l)
    entries += counts[static_cast<std::size_t>(l)];
  return entries;
}

UpperTreeIndex buildUpperTreeIndex(const LevelView& level, std::span<UpperTreeNode> storage) {
  const std::size_t entries = upperTreeEntries(level);
  if (entries == 0 || storage.size() < entries) return {};
  std::array<std::uint32_t, format::kMaxDepth> counts{};
  countNodesPerLevel(level, counts);
  UpperTreeWalk walk{level.nodes.data(), level.leaves.data(), upperTreeBottom(level.depth),
                     level.depth, storage.data()};
  for (int l = 0; l < walk.bottom; ++l) {
    walk.next[static_cast<std::size_t>(l + 1)] =
        walk.next[static_cast<std::size_t>(l)] + counts[static_cast<std::size_t>(l)];
  }
  // Entries of the bottom level have no children: their first_child is past the end.
  walk.next[static_cast<std::size_t>(walk.bottom + 1)] = static_cast<std::uint32_t>(entries);
  const std::uint8_t* node = walk.node_begin;
  const std::uint8_t* leaf = walk.leaf_begin;
  walk.visit(node, leaf, 0);
  return {walk.bottom, storage.first(entries)};
}

}  // namespace octopoint
