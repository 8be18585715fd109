#include "codegen/octree_encoder.h"

#include <cassert>

namespace octopoint::prepare {
namespace {

// Writes the subtree of the keys in [begin, end), which share their first `level` octal digits:
// this node's mask, then each occupied child's subtree in order k = 0..7. Keys are at `key_depth`.
void encodeNode(std::span<const std::uint64_t> keys, std::size_t begin, std::size_t end, int level,
                int depth, int key_depth, std::vector<std::uint8_t>& out) {
  const int shift = 3 * (key_depth - 1 - level);  // the child digit of this node's level
  std::size_t child_begin[9];
  int child_count = 0;
  std::uint8_t mask = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const auto digit = static_cast<unsigned>(keys[i] >> shift) & 7u;
    if (i == begin || digit != (static_cast<unsigned>(keys[i - 1] >> shift) & 7u)) {
      child_begin[child_count++] = i;
      mask = static_cast<std::uint8_t>(mask | 1u << digit);
    }
  }
  child_begin[child_count] = end;
  out.push_back(mask);
  if (level + 1 == depth) return;  // a leaf parent: its children are leaves, with no byte
  for (int c = 0; c < child_count; ++c) {
    encodeNode(keys, child_begin[c], child_begin[c + 1], level + 1, depth, key_depth, out);
  }
}

// Reads the node at `at` (at `level`, key prefix `prefix`) and its subtree; returns the byte after.
std::size_t decodeNode(std::span<const std::uint8_t> nodes, std::size_t at, int level, int depth,
                       std::uint64_t prefix, std::vector<std::uint64_t>& keys) {
  const std::uint8_t mask = nodes[at++];
  for (unsigned child = 0; child < 8; ++child) {
    if (!(mask >> child & 1u)) continue;
    const std::uint64_t key = prefix << 3 | child;
    if (level + 1 == depth) {
      keys.push_back(key);
    } else {
      at = decodeNode(nodes, at, level + 1, depth, key, keys);
    }
  }
  return at;
}

}  // namespace

std::vector<std::uint8_t> encodeOctree(std::span<const std::uint64_t> sorted_keys, int depth) {
  std::vector<std::uint8_t> nodes;
  if (!sorted_keys.empty()) encodeSubtree(sorted_keys, 0, depth, depth, nodes);
  return nodes;
}

void encodeSubtree(std::span<const std::uint64_t> sorted_keys, int level, int depth, int key_depth,
                   std::vector<std::uint8_t>& out) {
  assert(level >= 0 && level < depth && depth <= key_depth && !sorted_keys.empty());
  encodeNode(sorted_keys, 0, sorted_keys.size(), level, depth, key_depth, out);
}

std::vector<std::uint64_t> decodeLeafKeys(std::span<const std::uint8_t> nodes, int depth) {
  std::vector<std::uint64_t> keys;
  if (!nodes.empty()) decodeNode(nodes, 0, 0, depth, 0, keys);
  return keys;
}

}  // namespace octopoint::prepare
