#pragma once
// Stepping over a clipped-away subtree a grandparent at a time (fixed_fast, fixed_simd): the same
// result as skipSubtree (renderer/decode_algorithms.h), the stream and leaf cursors past the
// subtree, with far fewer unpredictable branches.
//
// Zoomed in, most of a frame's subtrees are off screen, and stepping over their bytes is most of
// the frame (lms400 at depth 9, 176x208 zoom 8: 70% of the instructions). skipSubtree reads one
// mask byte per step; the exits of its loops (how many siblings a node has, how many levels to
// climb) are a coin toss per grandparent. Here the leaf parents of a grandparent, which follow it
// as one run of popcount(grandparent) bytes in a depth-first stream, are counted at once: their
// leaves are the set bits of those bytes, one 8-byte load masked to the run and counted without a
// branch. The walk then branches per great-grandparent, not per leaf parent.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "renderer/bit_scan.h"
#include "renderer/camera.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {

// The set bits of the `bytes` (1..8) bytes at `run`, of which 8 may be read. A byte-wise sum of
// bit counts (SWAR) where the CPU has no popcount instruction in the default build (x86-64,
// ARMv5), not libgcc's call.
inline unsigned runBitCount(const std::uint8_t* run, unsigned bytes) {
  std::uint64_t v;
  std::memcpy(&v, run, sizeof v);
  v &= ~std::uint64_t{0} >> (64 - 8 * bytes);  // the run's bytes: the low ones (little-endian)
#if defined(__POPCNT__)
  return static_cast<unsigned>(std::popcount(v));
#else
  v -= (v >> 1) & 0x5555555555555555u;
  v = (v & 0x3333333333333333u) + ((v >> 2) & 0x3333333333333333u);
  v = (v + (v >> 4)) & 0x0f0f0f0f0f0f0f0fu;
  return static_cast<unsigned>((v * 0x0101010101010101u) >> 56);
#endif
}

// skipSubtree's result for the subtree whose root (at tree `level` of a `depth`-level tree) is at
// `node_cursor`; `node_end` is the end of the level's node stream (no load reaches past it).
template <typename Leaves>
void skipSubtreeByRuns(const std::uint8_t*& node_cursor, Leaves& leaves, int level, int depth,
                       const std::uint8_t* node_end) {
  const int great_grandparents = depth - level - 3;  // their relative level in the subtree
  // The masked 8-byte load needs a little-endian CPU with 64-bit registers; elsewhere (armel, the
  // Cortex-M builds) the byte walk.
  if constexpr (std::endian::native != std::endian::little || sizeof(std::size_t) < 8) {
    skipSubtree(node_cursor, leaves, level, depth);
    return;
  }
  if (great_grandparents < 0) {  // a leaf parent or a grandparent: nothing to gain
    skipSubtree(node_cursor, leaves, level, depth);
    return;
  }
  const std::uint8_t* node = node_cursor;
  std::size_t skipped = 0;  // leaves
  // pending[l]: the nodes of relative level l still to read under the current parent (as
  // skipSubtree; locals, so that no store through a byte pointer may alias the cursors).
  std::array<std::uint8_t, kMaxRenderDepth> pending;
  int l = 0;
  pending[0] = 1;
  for (;;) {
    const unsigned mask = *node++;
    --pending[static_cast<std::size_t>(l)];
    if (l < great_grandparents) {  // above the great-grandparents: its first child is next
      pending[static_cast<std::size_t>(++l)] = static_cast<std::uint8_t>(childCount(mask));
      continue;
    }
    // A great-grandparent: each of its grandparents is a mask followed by its leaf parents' masks.
    for (int grandparents = childCount(mask); grandparents != 0; --grandparents) {
      const auto parents = static_cast<unsigned>(childCount(*node++));
      if (node_end - node >= 8) {
        skipped += runBitCount(node, parents);
        node += parents;
      } else {  // the stream's last bytes: one at a time
        for (unsigned k = 0; k < parents; ++k) skipped += static_cast<std::size_t>(childCount(*node++));
      }
    }
    while (pending[static_cast<std::size_t>(l)] == 0) {
      if (l == 0) {
        node_cursor = node;
        skipLeaves(leaves, skipped);
        return;
      }
      --l;
    }
  }
}

}  // namespace octopoint
