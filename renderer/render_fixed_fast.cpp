// fixed_fast: the fastest integer decoder here. Same frame as fixed_baseline, bit for bit.
//
// What makes it fast, each measured in bench/render_bench.cpp against the plainer variants:
// - Algorithm 2 with set-bit iteration: a leaf parent plots its children in a loop over the set
//   bits of its mask (count trailing zeros), no call per leaf.
// - Stream cursors and frame pointers live in locals and travel by value (in and out of each call),
//   not in a struct in memory: a colour store is a byte store, which may alias any object in memory,
//   so state kept in memory would be reloaded after every plotted leaf.
// - The level above the leaf parents plots its grandchildren itself (in the on-screen case), so
//   there is no call per leaf parent: calls were a third of the instructions per point.
// - Hierarchical clipping as in fixed_clipped: subtrees proven on screen plot without bounds
//   checks, subtrees proven off screen are stepped over without computing positions.
#include <algorithm>
#include <bit>
#include <cassert>
#include <cstdlib>

#include "renderer/decode_algorithms.h"
#include "renderer/render.h"

namespace octopoint {
namespace {

struct Cursor {
  const std::uint8_t* node;
  const std::uint8_t* leaf;
};

struct FastFrame {
  std::uint8_t* colour;
  std::int32_t* depth;
  std::int32_t width;
  int fraction_bits;
  int levels;  // the model depth
  const OffsetTable<std::int32_t>* offsets;
  std::int64_t x_end, y_end;  // screen edges in Q(32-F).F (64 bits: width << 24 overflows 32)
  std::array<std::int64_t, format::kMaxDepth> reach_x, reach_y;  // see ClippedWalk
  const std::atomic<bool>* abort;
  mutable bool aborted;
};

enum class Clip { kOutside, kInside, kStraddling };

Clip classify(const FastFrame& f, int level, const Vec3& c) {
  const std::int64_t rx = f.reach_x[static_cast<std::size_t>(level)];
  const std::int64_t ry = f.reach_y[static_cast<std::size_t>(level)];
  if (c.x + rx < 0 || c.x - rx >= f.x_end || c.y + ry < 0 || c.y - ry >= f.y_end) return Clip::kOutside;
  if (c.x - rx >= 0 && c.x + rx < f.x_end && c.y - ry >= 0 && c.y + ry < f.y_end) return Clip::kInside;
  return Clip::kStraddling;
}

// A leaf parent at tree level `level` centred at `c` plots its children.
template <bool kChecked>
Cursor plotChildren(const FastFrame& f, int level, Vec3 c, Cursor at) {
  std::uint8_t* const colour = f.colour;
  std::int32_t* const depth = f.depth;
  const std::int32_t width = f.width;
  const std::int32_t height = static_cast<std::int32_t>(f.y_end >> f.fraction_bits);
  const int shift = f.fraction_bits;
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  const std::uint8_t* leaf = at.leaf;
  for (unsigned mask = *at.node; mask != 0; mask &= mask - 1, ++leaf) {
    const Vec3& d = offsets[static_cast<std::size_t>(std::countr_zero(mask))];
    const std::int32_t x = (c.x + d.x) >> shift;  // Q(32-F).F -> pixel (floor)
    const std::int32_t y = (c.y + d.y) >> shift;
    if constexpr (kChecked) {
      if (static_cast<std::uint32_t>(x) >= static_cast<std::uint32_t>(width) ||
          static_cast<std::uint32_t>(y) >= static_cast<std::uint32_t>(height)) {
        continue;
      }
    }
    const std::size_t pixel = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x);
    const std::int32_t z = c.z + d.z;
    if (z < depth[pixel]) {
      depth[pixel] = z;
      colour[pixel] = *leaf;
    }
  }
  return {at.node + 1, leaf};
}

template <bool kChecked>
Cursor visit(const FastFrame& f, int level, Vec3 c, Cursor at) {
  if (level <= kAbortCheckLevel && f.abort != nullptr) {
    if (!f.aborted && level == kAbortCheckLevel) f.aborted = f.abort->load(std::memory_order_relaxed);
    if (f.aborted) return at;
  }
  if constexpr (kChecked) {
    switch (classify(f, level, c)) {
      case Clip::kOutside:
        skipSubtree(at.node, at.leaf, level, f.levels);
        return at;
      case Clip::kInside: return visit<false>(f, level, c, at);
      case Clip::kStraddling: break;
    }
  }
  if (level + 1 == f.levels) return plotChildren<kChecked>(f, level, c, at);
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  unsigned mask = *at.node++;
  if (!kChecked && level + 2 == f.levels) {  // leaf parents below: plot them here, no call each
    for (; mask != 0; mask &= mask - 1) {
      at = plotChildren<false>(f, level + 1, c + offsets[static_cast<std::size_t>(std::countr_zero(mask))], at);
    }
    return at;
  }
  for (; mask != 0; mask &= mask - 1) {
    at = visit<kChecked>(f, level + 1, c + offsets[static_cast<std::size_t>(std::countr_zero(mask))], at);
  }
  return at;
}

}  // namespace

bool renderFixedFast(const LevelView& level, const FrameSetup& setup, Framebuffer& frame,
                     const std::atomic<bool>* abort) {
  assert(level.depth == setup.depth);
  assert(frame.width() == setup.width && frame.height() == setup.height);
  FastFrame f{frame.colourIndexData(), frame.depthData(), frame.width(), setup.fraction_bits,
              setup.depth, &setup.child_offset, std::int64_t{setup.width} << setup.fraction_bits,
              std::int64_t{setup.height} << setup.fraction_bits, {}, {}, abort, false};
  std::int64_t x = 0, y = 0;
  for (int l = setup.depth - 1; l >= 0; --l) {
    for (const Vec3& d : setup.child_offset[static_cast<std::size_t>(l)]) {
      f.reach_x[static_cast<std::size_t>(l)] = std::max<std::int64_t>(f.reach_x[static_cast<std::size_t>(l)], std::llabs(d.x));
      f.reach_y[static_cast<std::size_t>(l)] = std::max<std::int64_t>(f.reach_y[static_cast<std::size_t>(l)], std::llabs(d.y));
    }
    x += f.reach_x[static_cast<std::size_t>(l)];
    y += f.reach_y[static_cast<std::size_t>(l)];
    f.reach_x[static_cast<std::size_t>(l)] = x;
    f.reach_y[static_cast<std::size_t>(l)] = y;
  }
  visit<true>(f, 0, setup.root, {level.nodes.data(), level.leaves.data()});
  return !f.aborted;
}

}  // namespace octopoint
