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
// Where the level has a skip index (octopoint/model.h, ModelView builds it), a subtree at or
// above the indexed level is not read at all below that level: skipSubtreeIndexed.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/bit_scan.h"
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

// Reads the masks of the subtree whose root is at `node` down to its nodes `bottom` levels below
// the root (0: the root itself) and hands each of those to `past(mask, node)`, which steps over
// the rest of that node's subtree (its mask is read) and returns the stream after it. Returns the
// stream after the whole subtree. pending[l] counts the nodes of relative level l still to read
// under the current parent (as skipSubtree; locals, so that no store through a byte pointer may
// alias the cursors).
template <typename Past>
const std::uint8_t* walkDownTo(const std::uint8_t* node, int bottom, Past past) {
  std::array<std::uint8_t, kMaxRenderDepth> pending;
  int l = 0;
  pending[0] = 1;
  for (;;) {
    const unsigned mask = *node++;
    --pending[static_cast<std::size_t>(l)];
    if (l < bottom) {  // above the bottom: its first child is next
      pending[static_cast<std::size_t>(++l)] = static_cast<std::uint8_t>(childCount(mask));
      continue;
    }
    node = past(mask, node);
    while (pending[static_cast<std::size_t>(l)] == 0) {
      if (l == 0) return node;
      --l;
    }
  }
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
  std::size_t skipped = 0;  // leaves
  // A great-grandparent: each of its grandparents is a mask followed by its leaf parents' masks.
  node_cursor =
      walkDownTo(node_cursor, great_grandparents, [&](unsigned mask, const std::uint8_t* node) {
        for (int grandparents = childCount(mask); grandparents != 0; --grandparents) {
          const auto parents = static_cast<unsigned>(childCount(*node++));
          if (node_end - node >= 8) {
            skipped += runBitCount(node, parents);
            node += parents;
          } else {  // the stream's last bytes: one at a time
            for (unsigned k = 0; k < parents; ++k)
              skipped += static_cast<std::size_t>(childCount(*node++));
          }
        }
        return node;
      });
  skipLeaves(leaves, skipped);
}

// The first leaf a leaf cursor (renderer/leaf_cursor.h) or a plain pointer to palette indices
// points at.
template <typename Leaves>
const std::uint8_t* leafPosition(const Leaves& leaves) {
  if constexpr (std::is_pointer_v<Leaves>) {
    return leaves;
  } else {
    return leaves.colour;
  }
}

// skipSubtree's result, through `index`, for the subtree whose root (at tree `level`, at most
// index.level) is at `node_cursor`; `node_begin` and `leaf_begin` are the level's streams, whose
// offsets the index holds. `next` is the ordinal of the first index-level node at or after the
// root, and is left at the first one after the subtree: the walk counts the index-level nodes it
// passes. Only the subtree's masks above the index level are read: the children of a node just
// above it are consecutive entries, stepped over at once to the last one's end.
template <typename Leaves>
void skipSubtreeIndexed(const std::uint8_t*& node_cursor, Leaves& leaves, std::size_t& next,
                        int level, const SkipIndex& index, const std::uint8_t* node_begin,
                        const std::uint8_t* leaf_begin) {
  std::size_t ordinal = next;  // the index-level nodes passed, at the end the next one's ordinal
  if (level == index.level) {
    ++ordinal;
  } else {  // down to the index level's parents; their children are indexed: past them at once
    walkDownTo(node_cursor, index.level - level - 1, [&](unsigned mask, const std::uint8_t*) {
      ordinal += static_cast<std::size_t>(childCount(mask));
      return node_begin + index.ends[ordinal - 1].node;
    });
  }
  const SubtreeEnd& end = index.ends[ordinal - 1];
  node_cursor = node_begin + end.node;
  skipLeaves(leaves, static_cast<std::size_t>(leaf_begin + end.leaf - leafPosition(leaves)));
  next = ordinal;
}

// How fixed_fast and fixed_simd step over the off-screen subtrees of one level's stream: through
// its skip index at and above the indexed level, by runs below it or without an index. The walk
// tells it which index-level nodes it draws (enter, enterChildren), so that it knows the entry
// of the next one it skips.
class OffScreenSkip {
 public:
  explicit OffScreenSkip(const LevelView& level)
      : index_(level.skip),
        node_begin_(level.nodes.data()),
        node_end_(level.nodes.data() + level.nodes.size()),
        leaf_begin_(level.leaves.data()),
        depth_(level.depth) {}

  // The walk draws the node at `level` (it reads its mask itself).
  void enter(int level) {
    if (level == index_.level) ++next_;
  }
  // The walk draws every child of the node at `level` whose child mask is `mask`.
  void enterChildren(int level, unsigned mask) {
    if (level + 1 == index_.level) next_ += static_cast<std::size_t>(childCount(mask));
  }
  // Moves both cursors past the subtree at `level` whose root is at `node`.
  template <typename Leaves>
  void skip(const std::uint8_t*& node, Leaves& leaves, int level) {
    if (index_.level == 0 || level > index_.level) {
      skipSubtreeByRuns(node, leaves, level, depth_, node_end_);
    } else {
      skipSubtreeIndexed(node, leaves, next_, level, index_, node_begin_, leaf_begin_);
    }
  }

 private:
  [[no_unique_address]] SkipIndex index_;
  const std::uint8_t* node_begin_;
  const std::uint8_t* node_end_;
  const std::uint8_t* leaf_begin_;
  int depth_;
  std::size_t next_ = 0;  // the ordinal of the next index-level node the walk reaches
};

}  // namespace octopoint
