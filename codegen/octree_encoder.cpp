#include "codegen/octree_encoder.h"

#include <cassert>

namespace octopoint::prepare {
namespace {

// Writes the subtree of the keys in [begin, end), which share their first `level` octal digits:
// this node's mask, then each occupied child's subtree in order k = 0..7.
void encodeNode(std::span<const std::uint64_t> keys, std::size_t begin, std::size_t end,
                int level, int depth, std::vector<std::uint8_t>& out) {
  const int shift = 3 * (depth - 1 - level);  // the child digit of this node's level
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
    encodeNode(keys, child_begin[c], child_begin[c + 1], level + 1, depth, out);
  }
}

}  // namespace

std::vector<std::uint8_t> encodeOctree(std::span<const std::uint64_t> sorted_keys, int depth) {
  assert(depth >= 1);
  std::vector<std::uint8_t> nodes;
  if (!sorted_keys.empty()) encodeNode(sorted_keys, 0, sorted_keys.size(), 0, depth, nodes);
  return nodes;
}

}  // namespace octopoint::prepare
