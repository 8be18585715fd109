#pragma once
// The recursive octree decoders of docs/design.md section 4, written once for any position type:
// instantiated with int32_t positions (Q(32-F).F screen pixels) they are the fixed variants, with a
// floating point type (only in render_float_*.cpp) the reference variants the paper compares
// against. Every algorithm walks the same depth-first stream: a node's child-mask byte, then its
// occupied children's subtrees in order k = 0..7; a leaf takes the next payload from its cursor
// (the palette index, and the normal index where the frame carries normals:
// renderer/leaf_cursor.h).
//
// Each algorithm polls the abort flag at tree level kAbortCheckLevel (and, once it was seen,
// returns at every level above it), so a frame can be stopped within one level-3 subtree.

#include <array>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "octopoint/camera.h"
#include "octopoint/render.h"
#include "renderer/bit_scan.h"
#include "renderer/leaf_cursor.h"

namespace octopoint {

template <typename T>
using OffsetTable = std::array<std::array<Point3<T>, 8>, kMaxRenderDepth>;

template <typename T>
constexpr Point3<T> operator+(const Point3<T>& a, const Point3<T>& b) {
  return {static_cast<T>(a.x + b.x), static_cast<T>(a.y + b.y), static_cast<T>(a.z + b.z)};
}

// What one walk reads and writes. `Plot` is called as plot(position, payload), the payload being
// what `Leaves::next()` returns.
template <typename T, typename Plot, typename Leaves = ColourLeaves>
struct DecodeState {
  const std::uint8_t* node;
  Leaves leaves;
  const OffsetTable<T>& offsets;  // offsets[l][k]: from a level-l node's centre to child k's
  int depth;
  Plot plot;
  const std::atomic<bool>* abort;
  bool aborted = false;

  // True when the walk must stop at this node (see the header comment).
  bool stopsAt(int level) {
    if (level > kAbortCheckLevel || abort == nullptr) return false;
    if (!aborted && level == kAbortCheckLevel) aborted = abort->load(std::memory_order_relaxed);
    return aborted;
  }
};

// Algorithm 1: recursion down to the leaf; the leaf itself plots.
template <typename T, typename Plot, typename Leaves>
void visitBaseline(DecodeState<T, Plot, Leaves>& s, int level, Point3<T> centre) {
  if (s.stopsAt(level)) return;
  if (level == s.depth) {
    s.plot(centre, s.leaves.next());
    return;
  }
  const std::uint8_t mask = *s.node++;
  const auto& offsets = s.offsets[static_cast<std::size_t>(level)];
  for (unsigned k = 0; k < 8; ++k) {
    if (mask & (1u << k)) visitBaseline(s, level + 1, centre + offsets[k]);
  }
}

// Algorithm 2: the last recursion level is eliminated; a leaf parent plots its children.
template <typename T, typename Plot, typename Leaves>
void visitLeafCall(DecodeState<T, Plot, Leaves>& s, int level, Point3<T> centre) {
  if (s.stopsAt(level)) return;
  const std::uint8_t mask = *s.node++;
  const auto& offsets = s.offsets[static_cast<std::size_t>(level)];
  if (level + 1 == s.depth) {
    for (unsigned k = 0; k < 8; ++k) {
      if (mask & (1u << k)) s.plot(centre + offsets[k], s.leaves.next());
    }
    return;
  }
  for (unsigned k = 0; k < 8; ++k) {
    if (mask & (1u << k)) visitLeafCall(s, level + 1, centre + offsets[k]);
  }
}

// Algorithm 2 with the 8-way child loop unrolled: eight straight tests, constant bit masks.
template <typename T, typename Plot, typename Leaves>
void visitUnrolled(DecodeState<T, Plot, Leaves>& s, int level, Point3<T> centre) {
  if (s.stopsAt(level)) return;
  const std::uint8_t mask = *s.node++;
  const auto& offsets = s.offsets[static_cast<std::size_t>(level)];
  if (level + 1 == s.depth) {
    [&]<std::size_t... k>(std::index_sequence<k...>) {
      ((mask & (1u << k) ? s.plot(centre + offsets[k], s.leaves.next()) : void()), ...);
    }
    (std::make_index_sequence<8>{});
    return;
  }
  [&]<std::size_t... k>(std::index_sequence<k...>) {
    ((mask & (1u << k) ? visitUnrolled(s, level + 1, centre + offsets[k]) : void()), ...);
  }
  (std::make_index_sequence<8>{});
}

// Algorithm 2 visiting only the set bits (count-trailing-zeros), so a sparse node costs its
// children, not eight tests.
template <typename T, typename Plot, typename Leaves>
void visitSetBits(DecodeState<T, Plot, Leaves>& s, int level, Point3<T> centre) {
  if (s.stopsAt(level)) return;
  unsigned mask = *s.node++;
  const auto& offsets = s.offsets[static_cast<std::size_t>(level)];
  if (level + 1 == s.depth) {
    for (; mask != 0; mask &= mask - 1)
      s.plot(centre + offsets[lowestChild(mask)], s.leaves.next());
    return;
  }
  for (; mask != 0; mask &= mask - 1) {
    visitSetBits(s, level + 1, centre + offsets[lowestChild(mask)]);
  }
}

// Moves a leaf cursor (renderer/leaf_cursor.h) or a plain pointer to palette indices `count`
// leaves on: what stepping over a subtree does with the leaves it counted.
template <typename Leaves>
void skipLeaves(Leaves& leaves, std::size_t count) {
  if constexpr (std::is_pointer_v<Leaves>) {
    leaves += count;
  } else {
    leaves.skip(count);
  }
}

// Advances the stream past a subtree without computing a single position: what a clipped-away
// subtree still costs in a depth-first stream without an index. A loop, not a recursion: its cost
// is a few instructions per node, and its stack one byte per level (on a microcontroller, stack is
// RAM). pending[l] counts the nodes of relative level l still to read under the current parent.
// The node cursor is copied into a local and the leaves are counted in one: a byte store into
// `pending` may alias anything, so cursors kept behind the references would be written back to
// memory at every step. `leaves` is a leaf cursor (renderer/leaf_cursor.h) or a plain pointer to
// palette indices; it moves once, by the count, at the end.
template <typename Leaves>
void skipSubtree(const std::uint8_t*& node_cursor, Leaves& leaves, int level, int depth) {
  const int node_levels = depth - level;  // the subtree's levels of mask bytes
  const std::uint8_t* node = node_cursor;
  std::size_t skipped = 0;  // leaves
  std::array<std::uint8_t, kMaxRenderDepth> pending;
  int l = 0;
  pending[0] = 1;
  for (;;) {
    const unsigned mask = *node++;
    --pending[static_cast<std::size_t>(l)];
    if (l + 1 < node_levels) {  // an inner node: its first child is next
      pending[static_cast<std::size_t>(++l)] = static_cast<std::uint8_t>(childCount(mask));
      continue;
    }
    // A leaf parent, then its remaining siblings: a count in a register, not in `pending`.
    skipped += static_cast<std::size_t>(childCount(mask));
    for (unsigned siblings = pending[static_cast<std::size_t>(l)]; siblings != 0; --siblings) {
      skipped += static_cast<std::size_t>(childCount(*node++));
    }
    pending[static_cast<std::size_t>(l)] = 0;
    do {
      if (l == 0) {
        node_cursor = node;
        skipLeaves(leaves, skipped);
        return;
      }
      --l;
    } while (pending[static_cast<std::size_t>(l)] == 0);
  }
}

}  // namespace octopoint
