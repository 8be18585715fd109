#pragma once
// fixed_simd's leaf parents and grandparents on the frame's edge (renderer/render_fixed_simd.cpp,
// x86-64 with AVX2 only): the walk's checked path near the leaves. Inside the frame a leaf
// parent's children are emitted without a test (avx2_emit.h); one whose subtree straddles the
// frame's edge must keep only its children's pixels on screen. Zoomed in on a small screen the
// edge cuts many leaf parents (678 in lms400's 176x208 zoom 4 frame), so this path is in lanes
// too, and it has a file of its own because it is the walk's other half: the clip of each child
// and each pixel of its box, where the inside path has none.
#include <immintrin.h>

#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "renderer/avx2_emit.h"
#include "renderer/avx2_frame.h"

namespace octopoint::simd {

// The scalar plot with bounds checks: for leaf parents on the frame's edge whose eight-byte colour
// load would read past the model's last leaf.
template <bool kSplat, typename Leaves>
void plotChildrenChecked(const SimdFrame& f, int level, Vec3 c, unsigned mask, Leaves& leaves) {
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  const FixedPlot<true, Leaves::kPayload> plot(f.target);
  for (; mask != 0; mask &= mask - 1) {
    const Vec3 p = c + offsets[static_cast<std::size_t>(std::countr_zero(mask))];
    if constexpr (kSplat) {
      f.splat.plot<true, Leaves::kPayload>(p, leaves.next());
    } else {
      plot(p, leaves.next());
    }
  }
}

// One bit per lane: whether a < b (signed).
__attribute__((target("avx2"), always_inline)) inline unsigned below(__m256i a, __m256i b) {
  return lowBits(_mm256_cmpgt_epi32(b, a));
}

// A leaf parent on the frame's edge (its subtree straddles it) centred at `c`, with child mask
// `mask` (already read), whose eight colour bytes are in the stream, in lanes as in the unchecked
// walk: one pixel per leaf, the children on screen go to the batch; footprints of up to
// kMostBoxPixels pixels, each pixel of the box for the children that have it on screen; larger
// ones, the children whose rectangle lies wholly on screen, and only those partly on it take the
// scalar checked plot (those wholly off it are passed). Zoomed in on a small
// screen, the frame's edge cuts many leaf parents, and the scalar plot of each child's clipped
// rectangle was up to 14% of the frame (lms400 176x208 zoom 4, 2x2 splats).
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"))) void emitEdgeLeafParent(SimdFrame& f, int level, Vec3 c,
                                                        unsigned mask, Leaves& leaves) {
  makeRoom<kEmit>(f, 1);
  constexpr bool kSplat = kEmit.emit != Emit::kPixel;
  const LeafLanes lanes = leafLanes(f);
  const auto l = static_cast<std::size_t>(level);
  Vec3 first = c;  // the splat's first pixel (mod 2^32, as lanes add), as emitSubtree
  if constexpr (kSplat) {
    first.x += f.splat.footprint.offset_x;
    first.y += f.splat.footprint.offset_y;
  }
  // Q(32-F).F per child lane.
  const __m256i x = _mm256_add_epi32(_mm256_set1_epi32(first.x), f.child_lanes[0][l]);
  const __m256i y = _mm256_add_epi32(_mm256_set1_epi32(first.y), f.child_lanes[1][l]);
  // Each child's first and last column and row on screen (SplatFootprint; one pixel: first = last).
  const __m256i column = _mm256_sra_epi32(x, lanes.fraction_bits);
  const __m256i row = _mm256_sra_epi32(y, lanes.fraction_bits);
  __m256i last_column = column;
  __m256i last_row = row;
  if constexpr (kSplat) {
    last_column = _mm256_sra_epi32(_mm256_add_epi32(x, lanes.span_x), lanes.fraction_bits);
    last_row = _mm256_sra_epi32(_mm256_add_epi32(y, lanes.span_y), lanes.fraction_bits);
  }
  const __m256i zero = _mm256_setzero_si256();
  const __m256i height = _mm256_set1_epi32(f.target.height);
  const unsigned all = 0xffu;
  const unsigned inside = mask & ~below(column, zero) & ~below(row, zero) &
                          below(last_column, lanes.width) & below(last_row, height);
  const unsigned outside = below(last_column, zero) | (all & ~below(column, lanes.width)) |
                           below(last_row, zero) | (all & ~below(row, height));
  // Small footprints: per column and row of the box, the children that have it on screen.
  BoxOnScreen box_on_screen;
  if constexpr (kEmit.emit == Emit::kSplatPixels) {
    const int columns = kEmit.box_columns != 0 ? kEmit.box_columns : f.splat.footprint.columns;
    const int rows = kEmit.box_rows != 0 ? kEmit.box_rows : f.splat.footprint.rows;
    for (int k = 0; k < columns; ++k) {
      const __m256i at = _mm256_add_epi32(column, _mm256_set1_epi32(k));
      box_on_screen.column_drawn[k] = ~below(at, zero) & below(at, lanes.width);
    }
    for (int k = 0; k < rows; ++k) {
      const __m256i at = _mm256_add_epi32(row, _mm256_set1_epi32(k));
      box_on_screen.row_drawn[k] = ~below(at, zero) & below(at, height);
    }
  }
  const Leaves at = leaves;  // the children's payloads, for the scalar plot
  Emitter<Leaves> out{f.batch_index, f.batch_word, leaves, f.batch_extent,
                      static_cast<std::size_t>(f.batched)};
  emitChildrenOf<kEmit, true>(
      lanes, x, y, _mm256_add_epi32(biasedDepthLanes(f, c), f.child_lanes[2][l]), mask,
      kEmit.emit == Emit::kSplatPixels ? mask : inside, out, &box_on_screen);
  f.batched = static_cast<int>(out.count);
  leaves = out.leaves;
  if constexpr (kEmit.emit == Emit::kSplatRects) {
    const auto& offsets = (*f.offsets)[l];
    for (unsigned partly = mask & ~inside & ~outside; partly != 0; partly &= partly - 1) {
      const auto k = static_cast<unsigned>(std::countr_zero(partly));
      Leaves leaf = at;
      leaf.skip(static_cast<std::size_t>(std::popcount(mask & ((1u << k) - 1))));
      f.splat.plot<true, Leaves::kPayload>(c + offsets[k], leaf.next());
    }
  }
}

// A leaf parent wholly on screen centred at `c`, with child mask `mask` (already read), whose
// eight colour bytes are in the stream: emitSubtree's leaf parent (render_fixed_simd.cpp), for
// emitEdgeGrandparent.
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline void emitLeafParent(
    SimdFrame& f, const LeafLanes& lanes, int level, Vec3 c, unsigned mask, Leaves& leaves) {
  makeRoom<kEmit>(f, 1);
  Vec3 first = c;  // the splat's first pixel (mod 2^32, as lanes add), as emitSubtree
  if constexpr (kEmit.emit != Emit::kPixel) {
    first.x += f.splat.footprint.offset_x;
    first.y += f.splat.footprint.offset_y;
  }
  const auto l = static_cast<std::size_t>(level);
  Emitter<Leaves> out{f.batch_index, f.batch_word, leaves, f.batch_extent,
                      static_cast<std::size_t>(f.batched)};
  emitChildren<kEmit>(lanes, _mm256_add_epi32(_mm256_set1_epi32(first.x), f.child_lanes[0][l]),
                      _mm256_add_epi32(_mm256_set1_epi32(first.y), f.child_lanes[1][l]),
                      _mm256_add_epi32(biasedDepthLanes(f, c), f.child_lanes[2][l]), mask, out);
  f.batched = static_cast<int>(out.count);
  leaves = out.leaves;
}

// A grandparent on the frame's edge (its subtree straddles it) at `level` (at or below
// kAbortCheckLevel's) centred at `c`, with child mask `mask` (already read): its leaf parents in
// this call, each clipped, polled and drawn as the walk would in a call of its own (off screen:
// stepped over; on screen: emitted unchecked; straddling: emitEdgeLeafParent). Reads their masks
// from `node` on, returns the node after. The walk's call per leaf parent (and a second for one on
// screen) was most of its checked nodes' own instructions, 17.6% of lms400's 176x208 zoom 4 frame.
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"))) const std::uint8_t* emitEdgeGrandparent(SimdFrame& f, int level,
                                                                        Vec3 c, unsigned mask,
                                                                        const std::uint8_t* node,
                                                                        Leaves& leaves) {
  constexpr bool kSplat = kEmit.emit != Emit::kPixel;
  const int child_level = level + 1;
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  const LeafLanes lanes = leafLanes(f);
  for (; mask != 0; mask &= mask - 1) {
    // A splat frame polls at every node below kAbortCheckLevel (render_fixed_simd.cpp, visit).
    if (kSplat && f.abort != nullptr && (f.aborted = f.abort->load(std::memory_order_relaxed)))
      return node;
    const Vec3 p = c + offsets[static_cast<std::size_t>(std::countr_zero(mask))];
    const Clip clip = f.clip.classify(child_level, p);
    if (clip == Clip::kOutside) {
      f.off_screen.skip(node, leaves, child_level);
      continue;
    }
    f.off_screen.enter(child_level);
    const unsigned child_mask = *node++;
    if (clip == Clip::kInside) f.off_screen.enterChildren(child_level, child_mask);
    if (f.leaf_end - leaves.colour < 8) {  // the model's last leaves: the scalar plot
      plotChildrenChecked<kSplat, Leaves>(f, child_level, p, child_mask, leaves);
    } else if (clip == Clip::kInside) {
      emitLeafParent<kEmit, Leaves>(f, lanes, child_level, p, child_mask, leaves);
    } else {
      emitEdgeLeafParent<kEmit, Leaves>(f, child_level, p, child_mask, leaves);
    }
  }
  return node;
}

}  // namespace octopoint::simd
