#pragma once
// fixed_simd's state for one frame (renderer/render_fixed_simd.cpp, x86-64 with AVX2 only): the
// frame's targets, its offsets as lanes, and the batch the walk appends to. In a header of its own
// because two files use it: the walk (render_fixed_simd.cpp) and the path for leaf parents on the
// frame's edge (renderer/avx2_edge.h).
#include <immintrin.h>

#include <array>
#include <atomic>
#include <cstdint>

#include "octopoint/model.h"
#include "renderer/avx2_emit.h"
#include "renderer/decode_algorithms.h"
#include "renderer/framebuffer_plot.h"
#include "renderer/skip_runs.h"
#include "renderer/splat_batch.h"
#include "renderer/splat_plot.h"
#include "renderer/subtree_clip.h"

namespace octopoint::simd {

inline constexpr int kBatch = 2048;  // entries per batch (index and word): 16 KiB

// The most leaves below one node whose subtree the unchecked walk emits in one call: a node three
// levels above the leaves (8^3). A batch with less room left is plotted first: one pixel per leaf
// plots at most 1024 entries at a time, 8 KiB of indices and words, in L1.
inline constexpr int kMostLeavesPerCall = 512;
inline constexpr int kPixelBatchLimit = 1024 - kMostLeavesPerCall;
inline constexpr std::int64_t kSplatPixelsPerFlush = 1 << 16;

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
  // The splat path: up to 512 leaves per call while a splat has at most 128 pixels, else one leaf
  // parent's 8 per call (Emit::kSplatRects: at most about kSplatPixelsPerFlush pixels are batched
  // between two flushes, and so between two polls of the abort flag).
  int splat_levels_inline = 3;
  // batch_limit[n]: a splat frame's call that emits the subtree of a node n = 1..3 levels above
  // its leaves flushes the batch first when it holds more entries than this (one pixel per leaf:
  // kPixelBatchLimit). kSplatPixels: the call's boxes fit, so a leaf parent's 2 x 2 boxes wait
  // until 2048 - 32 entries are batched, not until any are, as a 512-leaf call's must (lms400's
  // 176x208 zoom 4 frame was flushed 1,779 times, a few entries at a time). kSplatRects: the
  // same limit for every n.
  std::array<int, 4> batch_limit{};
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

// Writes the batch (one pixel per entry) and empties it (render_fixed_simd.cpp).
__attribute__((target("avx2"))) void plotBatch(SimdFrame& f);
// The same for the splat path's rectangles (Emit::kSplatRects).
void plotSplatBatch(SimdFrame& f);

template <EmitMode kEmit>
void flushBatch(SimdFrame& f) {
  if constexpr (kEmit.emit == Emit::kSplatRects) {
    plotSplatBatch(f);
  } else {
    plotBatch(f);
  }
}

// Flushes the batch first when a call that emits the subtree of a node `levels_below` (1..3)
// levels above its leaves may not have room (SimdFrame::batch_limit).
template <EmitMode kEmit>
__attribute__((always_inline)) inline void makeRoom(SimdFrame& f, int levels_below) {
  const int limit = kEmit.emit == Emit::kPixel
                        ? kPixelBatchLimit
                        : f.batch_limit[static_cast<std::size_t>(levels_below)];
  if (f.batched > limit) flushBatch<kEmit>(f);
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

}  // namespace octopoint::simd
