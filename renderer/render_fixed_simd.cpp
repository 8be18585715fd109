// fixed_simd: the fastest integer decoder on x86-64 CPUs with AVX2 (listed only where the CPU has
// it). Same frame as fixed_baseline, bit for bit: still integer only, eight lanes at a time.
//
// At depth 8 a frame is bound by unpredictable decisions, not by arithmetic: how many children a
// node has (the exit of each set-bit loop) and, per leaf, whether it is nearer than the pixel's
// point (about half are). This decoder removes them from the inner loops, or makes them rarer:
// - Emit: a leaf parent computes all eight children's pixel indices and depth keys at once in
//   32-bit lanes (add the offsets, shift by F, row * width + column), packs its colours in, and
//   keeps the lanes of its set children by a per-mask permutation, appended to a batch with a
//   store of fixed width: no loop over the children, no branch on the mask.
// - Walk: the lowest three levels of a subtree on screen are two nested set-bit loops in one call
//   (emitSubtree), not a call per node, and the level above them loops over its children in the
//   same call. A grandparent's eight possible children's offsets are precomputed per axis as
//   vectors (its own offset plus its child's eight), so a leaf parent's lanes are one add per axis
//   from the grandparent's centre, itself one add from its parent's, all in lanes.
// - Plot: the batch is written with an unsigned min per point (Framebuffer's packed word makes the
//   z-test a min, and makes the result independent of the order points are drawn in), four
//   instructions per point.
// Leaf parents straddling the frame's edge keep, in lanes, only their children's pixels on screen
// (emitEdgeLeafParent); a model's last leaves (the eight-byte colour load would read past them)
// use the scalar checked plot; off-screen subtrees are skipped, as in
// fixed_fast. The abort flag is polled at kAbortCheckLevel.
// Splats (FrameSetup::splat active): the same walk, instantiated again, emits each leaf's splat
// from its first pixel (its position plus the footprint's offset, then shifted): up to 2 x 2
// pixels as single-pixel entries, exactly the splat's pixels (renderer/simd_emit.h), larger ones
// as rectangles written by a kernel chosen per footprint (renderer/splat_batch.h); the clip's
// reach includes the splat. Frames equal fixed_fast's, bit for bit.
#include <algorithm>
#include <array>
#include <bit>
#include <cassert>

#include "renderer/decode_algorithms.h"
#include "renderer/framebuffer_plot.h"
#include "renderer/render.h"
#include "renderer/render_check.h"
#include "renderer/skip_runs.h"
#include "renderer/splat_batch.h"
#include "renderer/splat_plot.h"
#include "renderer/subtree_clip.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include "renderer/simd_emit.h"

namespace octopoint {
namespace {

using simd::BoxChildren;
using simd::Emit;
using simd::EmitMode;
using simd::Emitter;
using simd::LeafLanes;
using simd::SplatBox;

constexpr int kBatch = 2048;  // entries per batch (index and word): 16 KiB

// The most leaves below one node whose subtree the unchecked walk emits in one call: a node three
// levels above the leaves (8^3). A batch with less room left is plotted first: one pixel per leaf
// plots at most 1024 entries at a time, 8 KiB of indices and words, in L1.
constexpr int kMostLeavesPerCall = 512;
constexpr int kPixelBatchLimit = 1024 - kMostLeavesPerCall;
constexpr std::int64_t kSplatPixelsPerFlush = 1 << 16;

struct SimdFrame {
  SimdFrame(const LevelView& level, const FrameSetup& setup, FrameView& frame,
            const std::atomic<bool>* abort_flag)
      : target(frame, setup),
        levels(setup.depth),
        offsets(&setup.child_offset),
        clip(setup.splat.active() ? SubtreeClip(setup, setup.splat) : SubtreeClip(setup)),
        splat(frame, setup),
        abort(abort_flag),
        leaf_end(level.leaves.data() + level.leaves.size()),
        off_screen(level) {}

  FixedPlot<true> target;  // also the checked plot of leaf parents on the frame's edge
  int levels;              // the model depth
  const OffsetTable<std::int32_t>* offsets;
  SubtreeClip clip;
  SplatPlot splat;  // the splat path's footprint, and its checked plot on the frame's edge
  // The splat path: at most about kSplatPixelsPerFlush pixels are batched between two flushes
  // (and so between two polls of the abort flag): up to 512 leaves per call while a splat has at
  // most 128 pixels, else one leaf parent's 8 per call.
  int splat_levels_inline = 3;
  int splat_batch_limit = kPixelBatchLimit;
  SplatBatchPlot plot_splats = nullptr;  // Emit::kSplatRects: the kernel for this footprint
  SplatBox box;                          // Emit::kSplatPixels: the footprint's box
  const std::atomic<bool>* abort;
  bool aborted = false;
  const std::uint8_t* leaf_end;
  OffScreenSkip off_screen;  // steps over off-screen subtrees (skip_runs.h)
  // Set by renderAvx2, per axis, in Q(32-F).F:
  // child_lanes[a][l]: the offsets of a level-l node's eight children, one per lane;
  // grandchild_lanes[l][k][a]: offset[l][k] plus child_lanes[a][l + 1], so that the eight children
  // of a level-l node's child k are one add from the level-l centre (a level-l node's 24 vectors
  // side by side: k's three are one address).
  __m256i child_lanes[3][kMaxRenderDepth];
  __m256i grandchild_lanes[kMaxRenderDepth][8][3];
  // grandchild_at[l][k]: grandchild_lanes[l][k], a load away from the child's number.
  const __m256i* grandchild_at[kMaxRenderDepth][8];
  int batched = 0;
  alignas(32) std::uint32_t batch_index[kBatch + 8];
  alignas(32) std::uint32_t batch_word[kBatch + 8];
  // Emit::kSplatRects only: each point's columns (low 16 bits) and rows (high 16 bits), both <=
  // 8192; such a batch holds at most kPixelBatchLimit + kMostLeavesPerCall points.
  alignas(32) std::uint32_t batch_extent[kPixelBatchLimit + kMostLeavesPerCall + 8];
};

// One entry: the pixel keeps the min of its word and the entry's. The word is read as the low lane
// of a four-word load (the batch has room past its last entry), so that the min takes it straight
// from memory: four instructions per entry (index, pixel, min, store).
__attribute__((target("avx2"), always_inline)) inline void plotEntry(std::uint32_t* pixel,
                                                                    std::uint32_t at,
                                                                    const std::uint32_t* word) {
  const __m128i kept = _mm_min_epu32(_mm_cvtsi32_si128(static_cast<std::int32_t>(pixel[at])),
                                     _mm_loadu_si128(reinterpret_cast<const __m128i*>(word)));
  pixel[at] = static_cast<std::uint32_t>(_mm_cvtsi128_si32(kept));
}

__attribute__((target("avx2"))) void plotBatch(SimdFrame& f) {
  std::uint32_t* const pixel = f.target.pixel;
  const std::uint32_t* const index = f.batch_index;
  const std::uint32_t* const word = f.batch_word;
  const int count = f.batched;
  // Unconditional store of the min: the branch "is it nearer" would be a coin toss. Neighbouring
  // points often share a pixel, and each min then waits for the store before it; the batch's four
  // quarters, interleaved, are four independent chains (two measured 4% of the frame at depth 8),
  // and the loop's own count and test are paid once per four entries.
  const int quarter = count / 4;
  for (int i = 0; i < quarter; ++i) {
    plotEntry(pixel, index[i], word + i);
    plotEntry(pixel, index[quarter + i], word + quarter + i);
    plotEntry(pixel, index[2 * quarter + i], word + 2 * quarter + i);
    plotEntry(pixel, index[3 * quarter + i], word + 3 * quarter + i);
  }
  for (int i = 4 * quarter; i < count; ++i) plotEntry(pixel, index[i], word + i);
  f.batched = 0;
}

// The splat path's batch: each point's index is its splat's first pixel, on screen with the whole
// rectangle (the clip proved it); the frame's kernel (renderer/splat_batch.h) writes the
// rectangles.
void plotSplatBatch(SimdFrame& f) {
  f.plot_splats(SplatBatch{
      f.target.pixel, static_cast<std::size_t>(f.target.width),
      static_cast<std::size_t>(f.target.width) * static_cast<std::size_t>(f.target.height),
      f.batch_index, f.batch_word, f.batch_extent, f.batched});
  f.batched = 0;
}

template <EmitMode kEmit>
void flushBatch(SimdFrame& f) {
  if constexpr (kEmit.emit == Emit::kSplatRects) {
    plotSplatBatch(f);
  } else {
    plotBatch(f);
  }
}

// The scalar plot with bounds checks: for leaf parents on the frame's edge.
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

__attribute__((target("avx2"))) inline LeafLanes leafLanes(const SimdFrame& f) {
  return {_mm256_set1_epi32(f.target.width),
          _mm_cvtsi32_si128(f.target.fraction_bits),
          _mm_cvtsi32_si128(f.target.depth_shift),
          _mm256_set1_epi32(f.splat.footprint.span_x),
          _mm256_set1_epi32(f.splat.footprint.span_y),
          _mm256_set1_epi32(f.splat.footprint.columns - 1),
          _mm256_set1_epi32(f.splat.footprint.rows - 1),
          static_cast<std::uint32_t>(f.target.width),
          &f.box};
}

// The centre's z plus the depth bias (PlotTarget::biasedDepth) in every lane: adding a child's
// offset wraps mod 2^32 as the scalar key does, and the key is one shift away.
__attribute__((target("avx2"))) inline __m256i biasedDepthLanes(const SimdFrame& f, Vec3 c) {
  return _mm256_set1_epi32(static_cast<std::int32_t>(f.target.biasedDepth(c.z)));
}

// One bit per lane: whether a < b (signed).
__attribute__((target("avx2"), always_inline)) inline unsigned below(__m256i a, __m256i b) {
  return simd::lowBits(_mm256_cmpgt_epi32(b, a));
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
  constexpr bool kSplat = kEmit.emit != Emit::kPixel;
  if (f.batched > (kSplat ? f.splat_batch_limit : kPixelBatchLimit)) flushBatch<kEmit>(f);
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
  simd::BoxOnScreen box_on_screen;
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
  simd::emitChildrenOf<kEmit, true>(
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

// The leaf parents below a grandparent at `level` whose centre is `cx`, `cy`, `biased_cz` in every
// lane, with child mask `mask` (already read), whose subtree is on screen: reads their masks from
// `node` on, returns the node after.
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline const std::uint8_t* emitGrandparent(
    const SimdFrame& f, const LeafLanes& lanes, int level, __m256i cx, __m256i cy,
    __m256i biased_cz, unsigned mask, const std::uint8_t* node, Emitter<Leaves>& out) {
  const __m256i* const* const below = f.grandchild_at[static_cast<std::size_t>(level)];
  for (; mask != 0; mask &= mask - 1) {
    const __m256i* const k = below[std::countr_zero(mask)];
    simd::emitChildren<kEmit>(lanes, _mm256_add_epi32(cx, k[0]), _mm256_add_epi32(cy, k[1]),
                              _mm256_add_epi32(biased_cz, k[2]), *node++, out);
  }
  return node;
}

// The subtree below a node at `level` centred at `c`, with child mask `mask` (already read), one to
// three levels above its leaves and on screen, into the batch in one go (flushed first when it may
// not have room): reads its masks from `node` on, returns the node after. The unchecked emit loads
// eight colour (and normal) bytes per leaf parent, from its first leaf on: the caller checked that
// 8^(levels below) bytes are left in the stream (a normal array is as long as the colours).
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline const std::uint8_t* emitSubtree(
    SimdFrame& f, const LeafLanes& lanes, int level, Vec3 c, unsigned mask,
    const std::uint8_t* node, Leaves& leaves) {
  constexpr bool kSplat = kEmit.emit != Emit::kPixel;
  if (f.batched > (kSplat ? f.splat_batch_limit : kPixelBatchLimit)) flushBatch<kEmit>(f);
  if constexpr (kSplat) {  // positions shifted to the splat's first pixel (mod 2^32, as lanes add)
    c.x += f.splat.footprint.offset_x;
    c.y += f.splat.footprint.offset_y;
  }
  Emitter<Leaves> out{f.batch_index, f.batch_word, leaves, f.batch_extent,
                      static_cast<std::size_t>(f.batched)};
  const int levels_below = f.levels - level;
  const auto l = static_cast<std::size_t>(level);
  if (levels_below == 1) {
    simd::emitChildren<kEmit>(lanes, _mm256_add_epi32(_mm256_set1_epi32(c.x), f.child_lanes[0][l]),
                              _mm256_add_epi32(_mm256_set1_epi32(c.y), f.child_lanes[1][l]),
                              _mm256_add_epi32(biasedDepthLanes(f, c), f.child_lanes[2][l]), mask,
                              out);
  } else if (levels_below == 2) {
    node = emitGrandparent<kEmit, Leaves>(f, lanes, level, _mm256_set1_epi32(c.x),
                                          _mm256_set1_epi32(c.y), biasedDepthLanes(f, c), mask,
                                          node, out);
  } else {
    // The grandparents' centres in every lane, one add from this node's: no scalar centre.
    const auto& offsets = (*f.offsets)[l];
    const __m256i cx = _mm256_set1_epi32(c.x);
    const __m256i cy = _mm256_set1_epi32(c.y);
    const __m256i biased_cz = biasedDepthLanes(f, c);
    for (; mask != 0; mask &= mask - 1) {
      const unsigned grandparent_mask = *node++;
      const Vec3& d = offsets[static_cast<unsigned>(std::countr_zero(mask))];
      node = emitGrandparent<kEmit, Leaves>(
          f, lanes, level + 1, _mm256_add_epi32(cx, _mm256_set1_epi32(d.x)),
          _mm256_add_epi32(cy, _mm256_set1_epi32(d.y)),
          _mm256_add_epi32(biased_cz, _mm256_set1_epi32(d.z)), grandparent_mask, node, out);
    }
  }
  f.batched = static_cast<int>(out.count);
  leaves = out.leaves;
  return node;
}

template <bool kChecked, EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"))) const std::uint8_t* visit(SimdFrame& f, int level, Vec3 c,
                                                          const std::uint8_t* node, Leaves& leaves) {
  constexpr bool kSplat = kEmit.emit != Emit::kPixel;
  if (level <= kAbortCheckLevel && f.abort != nullptr) {
    if (!f.aborted && level == kAbortCheckLevel)
      f.aborted = f.abort->load(std::memory_order_relaxed);
    if (f.aborted) return node;
  }
  // A splat frame's level-3 subtree may cover the whole screen: it polls at every node below too
  // (and flushes its batch before each poll), and every loop stops at once when the flag is seen.
  if (kSplat && level > kAbortCheckLevel && f.abort != nullptr &&
      (f.aborted = f.abort->load(std::memory_order_relaxed))) {
    return node;
  }
  if constexpr (kChecked) {
    switch (f.clip.classify(level, c)) {
      case Clip::kOutside:
        f.off_screen.skip(node, leaves, level);
        return node;
      case Clip::kInside:
        f.off_screen.enter(level);
        return visit<false, kEmit, Leaves>(f, level, c, node, leaves);
      case Clip::kStraddling:
        f.off_screen.enter(level);
        break;
    }
  }
  unsigned mask = *node++;
  // Every path below draws all the children: the skip index's count (a checked child counts itself).
  if (!kChecked) f.off_screen.enterChildren(level, mask);
  const int levels_below = f.levels - level;  // 1: a leaf parent, 2: a grandparent, 3: above that
  // Emitting several levels in one call skips the polls of the levels below: only from the poll's
  // level on, or when nobody can abort.
  const bool may_inline = level >= kAbortCheckLevel || f.abort == nullptr;
  // The subtree in one go (emitSubtree) where the stream has its 8^(levels below) bytes left.
  // Splats: large ones emit a leaf parent at a time and flush sooner (SimdFrame::splat_levels_inline,
  // splat_batch_limit), so the pixels written between two polls stay few.
  const int levels_inline = kSplat ? f.splat_levels_inline : 3;
  if (!kChecked && may_inline && levels_below <= levels_inline + 1) {
    const LeafLanes lanes = leafLanes(f);
    if (levels_below <= levels_inline) {
      if (f.leaf_end - leaves.colour >= (std::ptrdiff_t{1} << (3 * levels_below)))
        return emitSubtree<kEmit, Leaves>(f, lanes, level, c, mask, node, leaves);
    } else {
      // One level above: each child as visit would draw it (its poll, its subtree in one go), in
      // this call: a call per child and its set-up cost as much as a grandparent's leaf parents.
      const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
      const std::ptrdiff_t most_leaves = std::ptrdiff_t{1} << (3 * levels_inline);
      for (; mask != 0; mask &= mask - 1) {
        if (kSplat && f.abort != nullptr && (f.aborted = f.abort->load(std::memory_order_relaxed)))
          return node;
        const Vec3 child = c + offsets[static_cast<unsigned>(std::countr_zero(mask))];
        if (f.leaf_end - leaves.colour >= most_leaves) {
          const unsigned child_mask = *node++;
          node = emitSubtree<kEmit, Leaves>(f, lanes, level + 1, child, child_mask, node, leaves);
        } else {  // the model's last leaves: the scalar plot
          node = visit<false, kEmit, Leaves>(f, level + 1, child, node, leaves);
        }
      }
      return node;
    }
  }
  if (levels_below == 1) {
    if (kChecked && f.leaf_end - leaves.colour >= 8) {
      emitEdgeLeafParent<kEmit, Leaves>(f, level, c, mask, leaves);
    } else {
      plotChildrenChecked<kSplat, Leaves>(f, level, c, mask, leaves);
    }
    return node;
  }
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  for (; mask != 0; mask &= mask - 1) {
    node = visit<kChecked, kEmit, Leaves>(
        f, level + 1, c + offsets[static_cast<std::size_t>(std::countr_zero(mask))], node, leaves);
    if (kSplat && f.aborted) return node;
  }
  return node;
}

// A 2 x 2 footprint whose padded height is at most 1 + 1/8 pixel (span_y, Q(32-F).F) reaches its
// second row for at most one leaf in eight, so most leaf parents have no child there: the
// default model at 1920x1080 zoom 0.25 (depth 8 at 1.05-pixel voxels) and lms400 at 1920x1080
// zoom 0.5 (depth 9). Q8.24 here, shifted to the frame's F.
constexpr std::int32_t kRareLastRowSpan = std::int32_t{1} << (kMaxFractionBits - 3);

// The walk for Emit::kSplatPixels: unrolled for the common small boxes (the footprints of a turned
// model from 2x1 to 3x3 pixels), the frame's box from SimdFrame otherwise.
template <typename Leaves>
void drawBoxes(SimdFrame& f, const FrameSetup& setup, const LevelView& level, Leaves leaf,
               std::int32_t columns, std::int32_t rows) {
  const std::uint8_t* const nodes = level.nodes.data();
  const auto is = [&](std::int32_t c, std::int32_t r) { return columns == c && rows == r; };
  if (is(2, 1)) {
    visit<true, EmitMode{Emit::kSplatPixels, 2, 1}, Leaves>(f, 0, setup.root, nodes, leaf);
  } else if (is(1, 2)) {
    visit<true, EmitMode{Emit::kSplatPixels, 1, 2}, Leaves>(f, 0, setup.root, nodes, leaf);
  } else if (is(2, 2) && setup.splat.span_y <= kRareLastRowSpan >> (kMaxFractionBits - setup.fraction_bits)) {
    visit<true, EmitMode{Emit::kSplatPixels, 2, 2, true}, Leaves>(f, 0, setup.root, nodes, leaf);
  } else if (is(2, 2)) {
    visit<true, EmitMode{Emit::kSplatPixels, 2, 2}, Leaves>(f, 0, setup.root, nodes, leaf);
  } else {
    visit<true, EmitMode{Emit::kSplatPixels}, Leaves>(f, 0, setup.root, nodes, leaf);
  }
}

// How this frame's leaves are emitted, and for splats the batch's limits: at most about
// kSplatPixelsPerFlush pixels are batched between two flushes (and so between two polls of the
// abort flag), and a call of the unchecked walk never emits more than the batch has room for.
Emit chooseEmit(const SplatFootprint& splat, std::int32_t width, SimdFrame& f) {
  if (!splat.active()) return Emit::kPixel;
  const std::int64_t area = std::int64_t{splat.columns} * splat.rows;
  if (area <= simd::kMostBoxPixels) {
    f.box.pixels = static_cast<int>(area);
    for (std::int32_t r = 0; r < splat.rows; ++r) {
      for (std::int32_t c = 0; c < splat.columns; ++c) {
        const auto p = static_cast<std::size_t>(r * splat.columns + c);
        f.box.offset[p] = static_cast<std::uint32_t>(r * width + c);
        f.box.edge[p] = static_cast<std::uint8_t>((c + 1 == splat.columns ? 1 : 0) |
                                                  (r + 1 == splat.rows ? 2 : 0));
        f.box.column[p] = static_cast<std::uint8_t>(c);
        f.box.row[p] = static_cast<std::uint8_t>(r);
      }
    }
    // Up to 512 leaves per call while their boxes fit the batch, else 64.
    f.splat_levels_inline = kMostLeavesPerCall * area <= kBatch ? 3 : 2;
    f.splat_batch_limit = kBatch - static_cast<int>(area) * (1 << (3 * f.splat_levels_inline));
    return Emit::kSplatPixels;
  }
  f.splat_levels_inline = area <= 128 ? 3 : 1;
  f.splat_batch_limit =
      static_cast<int>(std::clamp<std::int64_t>(kSplatPixelsPerFlush / area, 8, kPixelBatchLimit));
  f.plot_splats = splatBatchPlot(splat.columns, splat.rows);
  return Emit::kSplatRects;
}

__attribute__((target("avx2"))) bool renderAvx2(const LevelView& level, const FrameSetup& setup,
                                                FrameView& frame,
                                                const std::atomic<bool>* abort) {
  // About 35 KiB with the offset vectors and the batch, on the stack: drawing never allocates.
  SimdFrame state(level, setup, frame, abort);
  SimdFrame* const f = &state;
  const Emit emit = chooseEmit(setup.splat, frame.width(), *f);
  const auto depth = static_cast<std::size_t>(setup.depth);
  for (std::size_t l = 0; l < depth; ++l) {
    alignas(32) std::int32_t axis[3][8];
    for (std::size_t k = 0; k < 8; ++k) {
      axis[0][k] = setup.child_offset[l][k].x;
      axis[1][k] = setup.child_offset[l][k].y;
      axis[2][k] = setup.child_offset[l][k].z;
    }
    for (std::size_t a = 0; a < 3; ++a)
      f->child_lanes[a][l] = _mm256_load_si256(reinterpret_cast<const __m256i*>(axis[a]));
  }
  for (std::size_t l = 0; l + 1 < depth; ++l) {
    for (std::size_t k = 0; k < 8; ++k) {
      const Vec3& d = setup.child_offset[l][k];
      // Lanes add mod 2^32, so c + (d + e) is the scalar walk's (c + d) + e, bit for bit.
      f->grandchild_lanes[l][k][0] =
          _mm256_add_epi32(_mm256_set1_epi32(d.x), f->child_lanes[0][l + 1]);
      f->grandchild_lanes[l][k][1] =
          _mm256_add_epi32(_mm256_set1_epi32(d.y), f->child_lanes[1][l + 1]);
      f->grandchild_lanes[l][k][2] =
          _mm256_add_epi32(_mm256_set1_epi32(d.z), f->child_lanes[2][l + 1]);
      f->grandchild_at[l][k] = f->grandchild_lanes[l][k];
    }
  }
  return withLeafCursor(level, frame, [&]<typename Leaves>(Leaves leaf) {
    switch (emit) {
      case Emit::kPixel:
        visit<true, EmitMode{Emit::kPixel}, Leaves>(*f, 0, setup.root, level.nodes.data(), leaf);
        plotBatch(*f);
        break;
      case Emit::kSplatPixels:
        drawBoxes(*f, setup, level, leaf, setup.splat.columns, setup.splat.rows);
        if (!f->aborted) plotBatch(*f);
        break;
      case Emit::kSplatRects:
        visit<true, EmitMode{Emit::kSplatRects}, Leaves>(*f, 0, setup.root, level.nodes.data(), leaf);
        if (!f->aborted) plotSplatBatch(*f);
        break;
    }
    return !f->aborted;
  });
}

}  // namespace

bool simdDecoderAvailable() { return __builtin_cpu_supports("avx2") != 0; }

bool renderFixedSimd(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                     const std::atomic<bool>* abort) {
  if (checkRender(level, setup, frame) != RenderError::kNone) return false;  // refused, nothing drawn
  if (!simdDecoderAvailable()) return renderFixedFast(level, setup, frame, abort);  // same frame
  return renderAvx2(level, setup, frame, abort);
}

}  // namespace octopoint

#else  // not x86-64: the variant is not listed, and draws with fixed_fast if called anyway

namespace octopoint {

bool simdDecoderAvailable() { return false; }

bool renderFixedSimd(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                     const std::atomic<bool>* abort) {
  return renderFixedFast(level, setup, frame, abort);
}

}  // namespace octopoint

#endif
