#include "codegen/octree_encoder.h"

#include <array>
#include <bit>
#include <cassert>

namespace octopoint::prepare {
namespace {

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

// One pass over the keys. The stream is the nodes in depth-first (pre-)order, which is the order in
// which ascending keys first reach them: a node's byte is placed when its first key arrives, and
// the later keys under it only set bits in it. Each key opens the nodes below the highest octal
// digit in which it differs from the key before, so the work is one step per node and per key.
void encodeSubtree(std::span<const std::uint64_t> sorted_keys, int level, int depth, int key_depth,
                   std::vector<std::uint8_t>& out) {
  assert(level >= 0 && level < depth && depth <= key_depth && !sorted_keys.empty());
  const auto digit = [&](std::uint64_t key, int l) {
    return static_cast<unsigned>(key >> (3 * (key_depth - 1 - l))) & 7u;
  };
  std::array<std::size_t, 64> open{};  // where the open node of each level has its byte
  const auto openFrom = [&](std::uint64_t key, int first) {
    for (int l = first; l < depth; ++l) {
      open[static_cast<std::size_t>(l)] = out.size();
      out.push_back(static_cast<std::uint8_t>(1u << digit(key, l)));
    }
  };
  openFrom(sorted_keys[0], level);
  const int below_depth = 3 * (key_depth - depth);  // the bits of digits finer than `depth`
  std::uint64_t previous = sorted_keys[0];
  for (std::size_t i = 1; i < sorted_keys.size(); ++i) {
    const std::uint64_t key = sorted_keys[i];
    const std::uint64_t differ = (key ^ previous) >> below_depth;
    if (differ == 0) continue;  // the same voxel at this depth
    previous = key;
    // The level whose child digit is the highest that differs: that node stays open and gains a
    // child; every node below it is new.
    const int split = depth - 1 - (63 - std::countl_zero(differ)) / 3;
    assert(split >= level);  // all keys share the first `level` digits
    out[open[static_cast<std::size_t>(split)]] |=
        static_cast<std::uint8_t>(1u << digit(key, split));
    openFrom(key, split + 1);
  }
}

std::vector<std::uint64_t> decodeLeafKeys(std::span<const std::uint8_t> nodes, int depth) {
  std::vector<std::uint64_t> keys;
  if (!nodes.empty()) decodeNode(nodes, 0, 0, depth, 0, keys);
  return keys;
}

}  // namespace octopoint::prepare
