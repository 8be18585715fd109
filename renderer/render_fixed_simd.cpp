// fixed_simd: the fastest integer decoder on x86-64 CPUs with AVX2 (listed only where the CPU has
// it). Same frame as fixed_baseline, bit for bit: still integer only, eight lanes at a time.
//
// At depth 8 a frame is bound by two unpredictable decisions per leaf parent, not by arithmetic:
// how many children it has (the exit of a set-bit loop) and, per child, whether it is nearer than
// the pixel's point (about half are). This decoder removes both from the inner loop:
// - Emit: a leaf parent computes all eight children's pixel indices and depth keys at once in
//   32-bit lanes (add the level's offsets, shift by F, row * width + column), packs its colours in,
//   and keeps the lanes of its set children by a per-mask permutation, appended to a batch with a
//   store of fixed width: no loop over the children, no branch on the mask.
// - Plot: the batch is written with an unsigned min per point (Framebuffer's packed word makes the
//   z-test a min, and makes the result independent of the order points are drawn in).
// Subtrees straddling the frame's edge, and a model's last leaves (the eight-byte colour load
// would read past them), use the scalar checked plot; off-screen subtrees are skipped, as in
// fixed_fast. The abort flag is polled at kAbortCheckLevel.
#include <algorithm>
#include <array>
#include <bit>
#include <cassert>

#include "renderer/decode_algorithms.h"
#include "renderer/framebuffer_plot.h"
#include "renderer/render.h"
#include "renderer/subtree_clip.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

namespace octopoint {
namespace {

// kKeep[mask]: the lanes of the set bits of `mask`, in order, then zeros: the vpermd control that
// moves a leaf parent's set children to the front.
struct LaneOrder {
  std::uint8_t lane[8];
};
constexpr std::array<LaneOrder, 256> makeKeepTable() {
  std::array<LaneOrder, 256> table{};
  for (unsigned mask = 0; mask < 256; ++mask) {
    unsigned kept = 0;
    for (std::uint8_t child = 0; child < 8; ++child) {
      if (mask >> child & 1u) table[mask].lane[kept++] = child;
    }
  }
  return table;
}
constexpr std::array<LaneOrder, 256> kKeep = makeKeepTable();

constexpr int kBatch = 1024;  // points per batch: 8 KiB of indices and words, in L1

struct SimdFrame {
  SimdFrame(const LevelView& level, const FrameSetup& setup, Framebuffer& frame,
            const std::atomic<bool>* abort_flag)
      : target(frame, setup),
        levels(setup.depth),
        offsets(&setup.child_offset),
        clip(setup),
        abort(abort_flag),
        leaf_end(level.leaves.data() + level.leaves.size()) {}

  FixedPlot<true> target;  // also the checked plot of leaf parents on the frame's edge
  int levels;  // the model depth
  const OffsetTable<std::int32_t>* offsets;
  SubtreeClip clip;
  const std::atomic<bool>* abort;
  bool aborted = false;
  const std::uint8_t* leaf_end;
  // The offsets of each level's eight children, one axis per vector (Q(32-F).F); set by renderAvx2.
  __m256i dx[format::kMaxDepth], dy[format::kMaxDepth], dz[format::kMaxDepth];
  int batched = 0;
  alignas(32) std::uint32_t batch_index[kBatch + 8];
  alignas(32) std::uint32_t batch_word[kBatch + 8];
};

__attribute__((target("avx2"))) void plotBatch(SimdFrame& f) {
  std::uint32_t* const pixel = f.target.pixel;
  const std::uint32_t* const index = f.batch_index;
  const std::uint32_t* const word = f.batch_word;
  const int count = f.batched;
  for (int i = 0; i < count; ++i) {
    // Unconditional store of the min: the branch "is it nearer" would be a coin toss.
    pixel[index[i]] = std::min(pixel[index[i]], word[i]);
  }
  f.batched = 0;
}

// The scalar plot with bounds checks: for leaf parents on the frame's edge.
void plotChildrenChecked(const SimdFrame& f, int level, Vec3 c, unsigned mask, const std::uint8_t*& leaf) {
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  for (; mask != 0; mask &= mask - 1) {
    f.target(c + offsets[static_cast<std::size_t>(std::countr_zero(mask))], *leaf++);
  }
}

// The leaf parents' level as vectors, loaded into registers once per grandparent.
struct LeafLanes {
  __m256i dx, dy, dz;  // the eight children's offsets per axis (Q(32-F).F)
  __m256i width, depth_bias;
  __m128i fraction_bits, depth_shift;
};

__attribute__((target("avx2"))) inline LeafLanes leafLanes(const SimdFrame& f, int level) {
  const auto l = static_cast<std::size_t>(level);
  return {f.dx[l],
          f.dy[l],
          f.dz[l],
          _mm256_set1_epi32(f.target.width),
          _mm256_set1_epi32(static_cast<int>(f.target.depth_bias)),
          _mm_cvtsi32_si128(f.target.fraction_bits),
          _mm_cvtsi32_si128(f.target.depth_shift)};
}

// A leaf parent centred at `c` whose children all land on screen writes their pixel indices and
// packed words to `index_out` and `word_out` (8 slots each) and returns how many it wrote. Its
// set children's colours are the next popcount(mask) bytes at `colours`, already in kept order.
__attribute__((target("avx2"))) inline int emitChildren(const LeafLanes& lanes, Vec3 c, unsigned mask,
                                                         const std::uint8_t* colours,
                                                         std::uint32_t* index_out, std::uint32_t* word_out) {
  // Pixel column and row: floor((c + d) / 2^F); index = row * width + column (< 2^26).
  const __m256i x = _mm256_sra_epi32(_mm256_add_epi32(_mm256_set1_epi32(c.x), lanes.dx), lanes.fraction_bits);
  const __m256i y = _mm256_sra_epi32(_mm256_add_epi32(_mm256_set1_epi32(c.y), lanes.dy), lanes.fraction_bits);
  const __m256i index = _mm256_add_epi32(_mm256_mullo_epi32(y, lanes.width), x);
  // Depth key (FrameSetup::depthKey): (z + bias) >> shift, unsigned, mod 2^32.
  const __m256i z = _mm256_add_epi32(_mm256_set1_epi32(c.z), lanes.dz);
  const __m256i key = _mm256_srl_epi32(_mm256_add_epi32(z, lanes.depth_bias), lanes.depth_shift);
  const __m256i keep = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&kKeep[mask])));
  const __m256i colour = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(colours)));
  const __m256i word = _mm256_or_si256(_mm256_slli_epi32(_mm256_permutevar8x32_epi32(key, keep), 8), colour);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(index_out), _mm256_permutevar8x32_epi32(index, keep));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(word_out), word);
  return std::popcount(mask);
}

template <bool kChecked>
__attribute__((target("avx2"))) const std::uint8_t* visit(SimdFrame& f, int level, Vec3 c,
                                                           const std::uint8_t* node,
                                                           const std::uint8_t*& leaf) {
  if (level <= kAbortCheckLevel && f.abort != nullptr) {
    if (!f.aborted && level == kAbortCheckLevel) f.aborted = f.abort->load(std::memory_order_relaxed);
    if (f.aborted) return node;
  }
  if constexpr (kChecked) {
    switch (f.clip.classify(level, c)) {
      case Clip::kOutside: skipSubtree(node, leaf, level, f.levels); return node;
      case Clip::kInside: return visit<false>(f, level, c, node, leaf);
      case Clip::kStraddling: break;
    }
  }
  unsigned mask = *node++;
  if (level + 1 == f.levels) {
    // The eight-byte colour load must stay inside the stream.
    if (kChecked || f.leaf_end - leaf < 8) {
      plotChildrenChecked(f, level, c, mask, leaf);
    } else {
      if (f.batched > kBatch - 8) plotBatch(f);
      const int children = emitChildren(leafLanes(f, level), c, mask, leaf, f.batch_index + f.batched,
                                        f.batch_word + f.batched);
      f.batched += children;
      leaf += children;
    }
    return node;
  }
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  if (!kChecked && level + 2 == f.levels && f.leaf_end - leaf >= 64) {
    // Leaf parents below, all on screen, with their at most 64 colours inside the stream: emit
    // them here, no call each (calls were half the time).
    if (f.batched > kBatch - 64) plotBatch(f);
    const LeafLanes lanes = leafLanes(f, level + 1);
    // Cursors in locals: a store to the batch may alias any 32-bit field of `f`.
    std::uint32_t* index_out = f.batch_index + f.batched;
    std::uint32_t* word_out = f.batch_word + f.batched;
    const std::uint8_t* colours = leaf;
    for (; mask != 0; mask &= mask - 1) {
      const Vec3 centre = c + offsets[static_cast<std::size_t>(std::countr_zero(mask))];
      const int children = emitChildren(lanes, centre, *node++, colours, index_out, word_out);
      index_out += children;
      word_out += children;
      colours += children;
    }
    f.batched = static_cast<int>(index_out - f.batch_index);
    leaf = colours;
    return node;
  }
  for (; mask != 0; mask &= mask - 1) {
    node = visit<kChecked>(f, level + 1, c + offsets[static_cast<std::size_t>(std::countr_zero(mask))], node, leaf);
  }
  return node;
}

__attribute__((target("avx2"))) bool renderAvx2(const LevelView& level, const FrameSetup& setup,
                                                Framebuffer& frame, const std::atomic<bool>* abort) {
  SimdFrame state(level, setup, frame, abort);  // about 10 KiB with the batch; drawing never allocates
  SimdFrame* const f = &state;
  for (std::size_t l = 0; l < static_cast<std::size_t>(setup.depth); ++l) {
    alignas(32) std::int32_t axis[3][8];
    for (std::size_t k = 0; k < 8; ++k) {
      axis[0][k] = setup.child_offset[l][k].x;
      axis[1][k] = setup.child_offset[l][k].y;
      axis[2][k] = setup.child_offset[l][k].z;
    }
    f->dx[l] = _mm256_load_si256(reinterpret_cast<const __m256i*>(axis[0]));
    f->dy[l] = _mm256_load_si256(reinterpret_cast<const __m256i*>(axis[1]));
    f->dz[l] = _mm256_load_si256(reinterpret_cast<const __m256i*>(axis[2]));
  }
  const std::uint8_t* leaf = level.leaves.data();
  visit<true>(*f, 0, setup.root, level.nodes.data(), leaf);
  plotBatch(*f);
  return !f->aborted;
}

}  // namespace

bool simdDecoderAvailable() { return __builtin_cpu_supports("avx2") != 0; }

bool renderFixedSimd(const LevelView& level, const FrameSetup& setup, Framebuffer& frame,
                     const std::atomic<bool>* abort) {
  assert(level.depth == setup.depth);
  assert(frame.width() == setup.width && frame.height() == setup.height);
  if (!simdDecoderAvailable()) return renderFixedFast(level, setup, frame, abort);  // same frame
  return renderAvx2(level, setup, frame, abort);
}

}  // namespace octopoint

#else  // not x86-64: the variant is not listed, and draws with fixed_fast if called anyway

namespace octopoint {

bool simdDecoderAvailable() { return false; }

bool renderFixedSimd(const LevelView& level, const FrameSetup& setup, Framebuffer& frame,
                     const std::atomic<bool>* abort) {
  return renderFixedFast(level, setup, frame, abort);
}

}  // namespace octopoint

#endif
