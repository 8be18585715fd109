#include <array>
#include <limits>

#include "octopoint/bands.h"
#include "octopoint/model.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {
namespace {

struct EndWalk {
  const std::uint8_t* node_begin;
  const std::uint8_t* leaf_begin;
  int index_level;
  int depth;
  SubtreeEnd* out;

  // Walks the levels above the index level; records where each index-level subtree ends.
  void visit(const std::uint8_t*& node, const std::uint8_t*& leaf, int level) {
    if (level == index_level) {
      skipSubtree(node, leaf, level, depth);
      *out++ = {static_cast<std::uint32_t>(node - node_begin),
                static_cast<std::uint32_t>(leaf - leaf_begin)};
      return;
    }
    for (int child = childCount(*node++); child > 0; --child) visit(node, leaf, level + 1);
  }
};

}  // namespace

int skipIndexLevel(int depth) { return depth >= 4 ? depth - 3 : 0; }

std::size_t skipIndexEntries(const LevelView& level) {
  const int index_level = skipIndexLevel(level.depth);
  if (index_level == 0 || level.nodes.empty() ||
      level.nodes.size() > std::numeric_limits<std::uint32_t>::max() ||
      level.leaves.size() > std::numeric_limits<std::uint32_t>::max()) {
    return 0;
  }
  std::array<std::uint32_t, format::kMaxDepth> counts{};
  countNodesPerLevel(level, counts);
  return counts[static_cast<std::size_t>(index_level)];
}

SkipIndex buildSkipIndex(const LevelView& level, std::span<SubtreeEnd> storage) {
  const std::size_t entries = skipIndexEntries(level);
  if (entries == 0 || storage.size() < entries) return {};
  EndWalk walk{level.nodes.data(), level.leaves.data(), skipIndexLevel(level.depth), level.depth,
               storage.data()};
  const std::uint8_t* node = walk.node_begin;
  const std::uint8_t* leaf = walk.leaf_begin;
  walk.visit(node, leaf, 0);
  return {walk.index_level, storage.first(entries)};
}

}  // namespace octopoint
