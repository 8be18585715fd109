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
// (renderer/avx2_edge.h); a model's last leaves (the eight-byte colour load would read past them)
// use the scalar checked plot; off-screen subtrees are skipped, as in fixed_fast. The abort flag is
// polled at kAbortCheckLevel. The frame's state and its batch: renderer/avx2_frame.h.
// Splats (FrameSetup::splat active): the same walk, instantiated again, emits each leaf's splat
// from its first pixel (its position plus the footprint's offset, then shifted): up to 2 x 2
// pixels as single-pixel entries, exactly the splat's pixels (renderer/avx2_emit.h), larger ones
// as rectangles written by a kernel chosen per footprint (renderer/splat_batch.h); the clip's
// reach includes the splat. Frames equal fixed_fast's, bit for bit.
#include <algorithm>
#include <array>
#include <bit>
#include <cassert>

#include "octopoint/render.h"
#include "renderer/decode_algorithms.h"
#include "renderer/framebuffer_plot.h"
#include "renderer/skip_runs.h"
#include "renderer/splat_batch.h"
#include "renderer/splat_plot.h"
#include "renderer/subtree_clip.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include "renderer/avx2_edge.h"
#include "renderer/avx2_emit.h"
#include "renderer/avx2_frame.h"

namespace octopoint {
namespace {

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

}  // namespace

namespace simd {

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

}  // namespace simd

namespace {

using simd::biasedDepthLanes;
using simd::Emit;
using simd::emitEdgeGrandparent;
using simd::emitEdgeLeafParent;
using simd::EmitMode;
using simd::Emitter;
using simd::flushBatch;
using simd::kBatch;
using simd::kMostLeavesPerCall;
using simd::kPixelBatchLimit;
using simd::kSplatPixelsPerFlush;
using simd::LeafLanes;
using simd::leafLanes;
using simd::makeRoom;
using simd::plotChildrenChecked;
using simd::SimdFrame;

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

// The subtree below a node at `level` centred at `c`, with child mask `mask` (already read),
// `levels_below` (1 to 3) levels above its leaves and on screen, into the batch in one go (flushed
// first when it may not have room): reads its masks from `node` on, returns the node after. The
// unchecked emit loads eight colour (and normal) bytes per leaf parent, from its first leaf on: the
// caller checked that 8^(levels below) bytes are left in the stream (a normal array is as long as
// the colours).
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline const std::uint8_t* emitSubtree(
    SimdFrame& f, const LeafLanes& lanes, int level, int levels_below, Vec3 c, unsigned mask,
    const std::uint8_t* node, Leaves& leaves) {
  constexpr bool kSplat = kEmit.emit != Emit::kPixel;
  // 2 x 2 boxes: a subtree of 512 leaves would need an empty batch (2048 entries), so the batch
  // was plotted before each such call, mostly small; such a call makes room per grandparent
  // instead (256 entries). It pays for 2 x 2 boxes only, not for 2 x 1 ones (docs/splats.md,
  // "The walk near the frame's edge, cheaper").
  constexpr bool kRoomPerGrandparent =
      kEmit.emit == Emit::kSplatPixels && kEmit.box_columns * kEmit.box_rows == 4;
  makeRoom<kEmit>(f, kRoomPerGrandparent && levels_below == 3 ? 2 : levels_below);
  if constexpr (kSplat) {  // positions shifted to the splat's first pixel (mod 2^32, as lanes add)
    c.x += f.splat.footprint.offset_x;
    c.y += f.splat.footprint.offset_y;
  }
  Emitter<Leaves> out{f.batch_index, f.batch_word, leaves, f.batch_extent,
                      static_cast<std::size_t>(f.batched)};
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
      if constexpr (kRoomPerGrandparent) {
        if (out.count > static_cast<std::size_t>(f.batch_limit[2])) {
          f.batched = static_cast<int>(out.count);
          flushBatch<kEmit>(f);
          out.count = 0;
        }
      }
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
                                                          const std::uint8_t* node, Leaves& leaves);

// visit one level above the subtrees it emits in one go (levels_inline deep): each child as visit
// would draw it (its poll, its subtree in one go), in this call: a call per child and its set-up
// cost as much as a grandparent's leaf parents.
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline const std::uint8_t* visitInlineChildren(
    SimdFrame& f, const LeafLanes& lanes, int level, int levels_inline, Vec3 c, unsigned mask,
    const std::uint8_t* node, Leaves& leaves) {
  constexpr bool kSplat = kEmit.emit != Emit::kPixel;
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  const std::ptrdiff_t most_leaves = std::ptrdiff_t{1} << (3 * levels_inline);
  for (; mask != 0; mask &= mask - 1) {
    if (kSplat && f.abort != nullptr && (f.aborted = f.abort->load(std::memory_order_relaxed)))
      return node;
    const Vec3 child = c + offsets[static_cast<unsigned>(std::countr_zero(mask))];
    if (f.leaf_end - leaves.colour >= most_leaves) {
      const unsigned child_mask = *node++;
      node = emitSubtree<kEmit, Leaves>(f, lanes, level + 1, levels_inline, child, child_mask, node,
                                        leaves);
    } else {  // the model's last leaves: the scalar plot
      node = visit<false, kEmit, Leaves>(f, level + 1, child, node, leaves);
    }
  }
  return node;
}

// visit's straddling node two levels above its leaf parents (checked, from the poll's level on).
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline const std::uint8_t* visitEdgeGrandparents(
    SimdFrame& f, int level, Vec3 c, unsigned mask, const std::uint8_t* node, Leaves& leaves) {
  constexpr bool kSplat = kEmit.emit != Emit::kPixel;
  // Its grandparents, each polled and clipped here as a call of its own would: a call of visit
  // less per grandparent (lms400 176x208 zoom 4: -1.3% of the frame's instructions).
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  for (; mask != 0; mask &= mask - 1) {
    if (kSplat && f.abort != nullptr && (f.aborted = f.abort->load(std::memory_order_relaxed)))
      return node;
    const Vec3 child = c + offsets[static_cast<std::size_t>(std::countr_zero(mask))];
    switch (f.clip.classify(level + 1, child)) {
      case Clip::kOutside:
        f.off_screen.skip(node, leaves, level + 1);
        break;
      case Clip::kInside:
        f.off_screen.enter(level + 1);
        node = visit<false, kEmit, Leaves>(f, level + 1, child, node, leaves);
        break;
      case Clip::kStraddling: {
        f.off_screen.enter(level + 1);
        const unsigned child_mask = *node++;
        node = emitEdgeGrandparent<kEmit, Leaves>(f, level + 1, child, child_mask, node, leaves);
        break;
      }
    }
    if (kSplat && f.aborted) return node;
  }
  return node;
}

template <bool kChecked, EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"))) const std::uint8_t* visit(SimdFrame& f, int level, Vec3 c,
                                                          const std::uint8_t* node,
                                                          Leaves& leaves) {
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
  // Every path below draws all the children: the skip index's count (a checked child counts
  // itself).
  if (!kChecked) f.off_screen.enterChildren(level, mask);
  const int levels_below = f.levels - level;  // 1: a leaf parent, 2: a grandparent, 3: above that
  // Emitting several levels in one call skips the polls of the levels below: only from the poll's
  // level on, or when nobody can abort.
  const bool may_inline = level >= kAbortCheckLevel || f.abort == nullptr;
  // The subtree in one go (emitSubtree) where the stream has its 8^(levels below) bytes left.
  // Splats: large ones emit a leaf parent at a time and flush sooner
  // (SimdFrame::splat_levels_inline, batch_limit), so the pixels written between two polls stay
  // few. (kSplatPixels: always 3, its boxes have at most 4 pixels; known here, so that the loop
  // below tells emitSubtree its depth.)
  const int levels_inline = kEmit.emit == Emit::kSplatRects ? f.splat_levels_inline : 3;
  if (!kChecked && may_inline && levels_below <= levels_inline + 1) {
    const LeafLanes lanes = leafLanes(f);
    if (levels_below <= levels_inline) {
      if (f.leaf_end - leaves.colour >= (std::ptrdiff_t{1} << (3 * levels_below)))
        return emitSubtree<kEmit, Leaves>(f, lanes, level, levels_below, c, mask, node, leaves);
    } else {
      return visitInlineChildren<kEmit, Leaves>(f, lanes, level, levels_inline, c, mask, node,
                                                leaves);
    }
  }
  if (kChecked && levels_below == 2 && level >= kAbortCheckLevel)
    return emitEdgeGrandparent<kEmit, Leaves>(f, level, c, mask, node, leaves);
  if (kChecked && levels_below == 3 && level >= kAbortCheckLevel)
    return visitEdgeGrandparents<kEmit, Leaves>(f, level, c, mask, node, leaves);
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
  } else if (is(2, 2) &&
             setup.splat.span_y <= kRareLastRowSpan >> (kMaxFractionBits - setup.fraction_bits)) {
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
    // Up to 512 leaves per call: their boxes fit the batch (visit counts on it).
    static_assert(kMostLeavesPerCall * simd::kMostBoxPixels <= kBatch);
    f.splat_levels_inline = 3;
    for (int n = 1; n <= 3; ++n)
      f.batch_limit[static_cast<std::size_t>(n)] = kBatch - static_cast<int>(area) * (1 << (3 * n));
    return Emit::kSplatPixels;
  }
  f.splat_levels_inline = area <= 128 ? 3 : 1;
  f.batch_limit.fill(
      static_cast<int>(std::clamp<std::int64_t>(kSplatPixelsPerFlush / area, 8, kPixelBatchLimit)));
  f.plot_splats = splatBatchPlot(splat.columns, splat.rows);
  return Emit::kSplatRects;
}

__attribute__((target("avx2"))) bool renderAvx2(const LevelView& level, const FrameSetup& setup,
                                                FrameView& frame, const std::atomic<bool>* abort) {
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
        visit<true, EmitMode{Emit::kSplatRects}, Leaves>(*f, 0, setup.root, level.nodes.data(),
                                                         leaf);
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
  if (checkRender(level, setup, frame) != RenderError::kNone)
    return false;  // refused, nothing drawn
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
