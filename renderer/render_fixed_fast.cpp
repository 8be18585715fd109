// fixed_fast: the fastest portable integer decoder (fixed_simd, AVX2 only, is faster). Same frame
// as fixed_baseline, bit for bit.
//
// What makes it fast, each measured in bench/render_bench.cpp against the plainer variants:
// - Algorithm 2 with set-bit iteration: a leaf parent plots its children in a loop over the set
//   bits of its mask (count trailing zeros), no call per leaf.
// - A branch-free z-test: the pixel gets the min of its word and the leaf's (Framebuffer).
// - Stream cursors and frame pointers live in locals and travel by value (in and out of each call),
//   not in a struct in memory: a pixel store may alias any 32-bit field of such a struct, so state
//   kept in memory would be reloaded after every plotted leaf.
// - The level above the leaf parents plots its grandchildren itself (in the on-screen case), so
//   there is no call per leaf parent: calls were a third of the instructions per point. The level
//   above that loops over its children in the same call where they do not poll (plotSubtree), and
//   a splat frame's box kernel is chosen per such call, not per leaf (docs/splats.md, "Cost").
// - Hierarchical clipping as in fixed_clipped: subtrees proven on screen plot without bounds
//   checks, subtrees proven off screen are stepped over without computing positions, a
//   grandparent's leaf parents at a time (renderer/skip_runs.h).
// When a voxel of the drawn depth projects to more than one pixel (FrameSetup::splat), each leaf
// covers its footprint splat instead (renderer/splat_plot.h), and the clip's reach includes the
// splat; the walk is the same, instantiated a second time so the one-pixel path stays as it was.
#include <algorithm>
#include <bit>
#include <type_traits>
#include <utility>

#include "octopoint/render.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"
#include "renderer/framebuffer_plot.h"
#include "renderer/skip_runs.h"
#include "renderer/splat_plot.h"
#include "renderer/subtree_clip.h"

namespace octopoint {
namespace {

template <typename Leaves>
struct Cursor {
  const std::uint8_t* node;
  Leaves leaves;  // renderer/leaf_cursor.h: the palette (and normal) indices
};

// A frame's normal indices, read beside the palette indices: the cursor carries the palette
// index pointer alone and the frame the two arrays' starts, so a cursor is two pointers (the node
// and the palette index) and travels in registers; with a third pointer (ColourNormalLeaves) it was
// returned through memory from every call, and normal frames took 30% longer to decode instead of
// the 13% more instructions they need (docs/styles.md, "Cost").
struct NormalBesideColourLeaves {
  static constexpr PixelPayload kPayload = PixelPayload::kColourNormal;
  const std::uint8_t* colour;

  void skip(std::size_t count) { colour += count; }
};

struct FastFrame {
  PlotTarget target;
  int levels;  // the model depth
  const OffsetTable<std::int32_t>* offsets;
  SubtreeClip clip;
  const std::atomic<bool>* abort;
  mutable bool aborted;
  SplatPlot splat;                        // used by the splat path only
  const std::uint8_t* colours = nullptr;  // NormalBesideColourLeaves: the level's palette indices
  const std::uint8_t* normals = nullptr;  // and its normal indices, one each per leaf
  mutable OffScreenSkip off_screen;       // steps over off-screen subtrees (skip_runs.h)
};

// The next leaf's payload (Framebuffer::packLeaf), and the cursor one leaf on.
template <typename Leaves>
std::uint32_t nextLeaf(const FastFrame&, Leaves& leaves) {
  return leaves.next();
}
inline std::uint32_t nextLeaf(const FastFrame& f, NormalBesideColourLeaves& leaves) {
  const std::uint8_t* const colour = leaves.colour++;
  return std::uint32_t{*colour} | std::uint32_t{f.normals[colour - f.colours]} << 8;
}

// A leaf parent at tree level `level` centred at `c` plots its children: one pixel each, or
// (kSplat) each its footprint splat.
template <bool kChecked, bool kSplat, typename Leaves>
Cursor<Leaves> plotChildren(const FastFrame& f, int level, Vec3 c, Cursor<Leaves> at) {
  if constexpr (kSplat) {
    const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
    Leaves leaves = at.leaves;
    for (unsigned mask = *at.node; mask != 0; mask &= mask - 1) {
      f.splat.plot<kChecked, Leaves::kPayload>(c + offsets[lowestChild(mask)], nextLeaf(f, leaves));
    }
    return {at.node + 1, leaves};
  }
  std::uint32_t* const pixel = f.target.pixel;
  const std::int32_t width = f.target.width;
  const std::int32_t height = f.target.height;
  const int shift = f.target.fraction_bits;
  const std::uint32_t depth_bias = f.target.depth_bias;
  const int depth_shift = f.target.depth_shift;
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  Leaves leaves = at.leaves;
  for (unsigned mask = *at.node; mask != 0; mask &= mask - 1) {
    const Vec3& d = offsets[lowestChild(mask)];
    const std::uint32_t payload = nextLeaf(f, leaves);
    const std::int32_t x = (c.x + d.x) >> shift;  // Q(32-F).F -> pixel (floor)
    const std::int32_t y = (c.y + d.y) >> shift;
    if constexpr (kChecked) {
      if (static_cast<std::uint32_t>(x) >= static_cast<std::uint32_t>(width) ||
          static_cast<std::uint32_t>(y) >= static_cast<std::uint32_t>(height)) {
        continue;
      }
    }
    const std::size_t index =
        static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
    // FrameSetup::depthKey, inline: (z + bias) >> shift, mod 2^32.
    const std::uint32_t key = (static_cast<std::uint32_t>(c.z + d.z) + depth_bias) >> depth_shift;
    // Branch-free z-test: whether a point is nearer is a coin toss at depth 8 (about half are),
    // and a mispredicted branch cost more than the unconditional store (bench/render_bench.cpp).
    pixel[index] = std::min(pixel[index], Framebuffer::packLeaf<Leaves::kPayload>(key, payload));
  }
  return {at.node + 1, leaves};
}

// The kernel of plotGrandchildren for one pixel per leaf; a splat frame's is its box kernel
// (SplatPlot::withBoxKernel).
constexpr int kOnePixel = SplatPlot::kNoBox - 1;

// A grandparent at tree level `level` centred at `c`, whose subtree is on screen, plots its
// grandchildren in one call: no call per leaf parent, and the frame's values the loops read held
// in locals (a pixel store may alias any 32-bit field of the frame, which would then be reloaded
// after every leaf). Per leaf parent, its centre (a splat's: plus the footprint's offset) and its
// biased depth (PlotTarget::biasedDepth) are made once, so a leaf is one add per axis from them;
// all wrap mod 2^32 as the scalar sums would, and the leaf's own sums fit 32 bits
// (buildFrameSetup). A splat frame polls the abort flag after every leaf parent, as plotting them
// one call each did.
template <int kKernel, typename Leaves>
__attribute__((always_inline)) inline Cursor<Leaves> plotGrandchildren(const FastFrame& f,
                                                                       int level, Vec3 c,
                                                                       Cursor<Leaves> at) {
  constexpr bool kSplat = kKernel != kOnePixel;
  const SplatPlot splat = f.splat;  // the splat's kernel reads its copy
  std::uint32_t* const pixel = f.target.pixel;
  const auto width = static_cast<std::uint32_t>(f.target.width);
  const int shift = f.target.fraction_bits;
  const int depth_shift = f.target.depth_shift;
  const auto& parent_offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  const auto& leaf_offsets = (*f.offsets)[static_cast<std::size_t>(level) + 1];
  auto cx = static_cast<std::uint32_t>(c.x);
  auto cy = static_cast<std::uint32_t>(c.y);
  const std::uint32_t biased_cz = f.target.biasedDepth(c.z);
  if constexpr (kSplat) {
    cx += static_cast<std::uint32_t>(splat.footprint.offset_x);
    cy += static_cast<std::uint32_t>(splat.footprint.offset_y);
  }
  const std::uint8_t* node = at.node;
  Leaves leaves = at.leaves;
  for (unsigned mask = *node++; mask != 0; mask &= mask - 1) {
    const Vec3& d = parent_offsets[lowestChild(mask)];
    const std::uint32_t px = cx + static_cast<std::uint32_t>(d.x);
    const std::uint32_t py = cy + static_cast<std::uint32_t>(d.y);
    const std::uint32_t pz = biased_cz + static_cast<std::uint32_t>(d.z);
    for (unsigned leaf_mask = *node++; leaf_mask != 0; leaf_mask &= leaf_mask - 1) {
      const Vec3& e = leaf_offsets[lowestChild(leaf_mask)];
      const std::int32_t x = static_cast<std::int32_t>(px + static_cast<std::uint32_t>(e.x));
      const std::int32_t y = static_cast<std::int32_t>(py + static_cast<std::uint32_t>(e.y));
      // FrameSetup::depthKey: (z + bias) >> shift, mod 2^32.
      const std::uint32_t word = Framebuffer::packLeaf<Leaves::kPayload>(
          (pz + static_cast<std::uint32_t>(e.z)) >> depth_shift, nextLeaf(f, leaves));
      if constexpr (kSplat) {
        splat.plotUnchecked<kKernel>(x, y, word);
      } else {
        // The pixel (Q(32-F).F -> pixel, floor); on screen, so its index fits 32 bits (8192^2).
        std::uint32_t& kept = pixel[static_cast<std::uint32_t>(y >> shift) * width +
                                    static_cast<std::uint32_t>(x >> shift)];
        kept = std::min(kept, word);  // branch-free z-test, as plotChildren
      }
    }
    if (kSplat && f.abort != nullptr && (f.aborted = f.abort->load(std::memory_order_relaxed)))
      break;
  }
  return {node, leaves};
}

// A node three levels above the leaves (a great-grandparent) at `level`, on screen, plots its
// subtree in one call: its grandparents as visit would (a splat frame polls at each, and stops when
// the flag is seen), without a call each. Only where the grandparents do not poll otherwise
// (below kAbortCheckLevel, or nobody can abort; visit checks).
template <int kKernel, typename Leaves>
__attribute__((always_inline)) inline Cursor<Leaves> plotGreatGrandchildren(const FastFrame& f,
                                                                            int level, Vec3 c,
                                                                            Cursor<Leaves> at) {
  constexpr bool kSplat = kKernel != kOnePixel;
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  unsigned mask = *at.node++;
  f.off_screen.enterChildren(level, mask);
  for (; mask != 0; mask &= mask - 1) {
    if (kSplat && f.abort != nullptr && (f.aborted = f.abort->load(std::memory_order_relaxed)))
      break;
    at = plotGrandchildren<kKernel, Leaves>(f, level + 1, c + offsets[lowestChild(mask)], at);
    if (kSplat && f.aborted) break;
  }
  return at;
}

// The subtree of an on-screen node `levels_below` (2 or 3) levels above the leaves, in one call,
// with the frame's leaf kernel: one pixel, or the splat's box kernel (SplatPlot::withBoxKernel,
// chosen per call: a jump, not a test per leaf).
template <int kKernel, typename Leaves>
Cursor<Leaves> plotSubtreeWith(const FastFrame& f, int level, int levels_below, Vec3 c,
                               Cursor<Leaves> at) {
  if (levels_below == 2) return plotGrandchildren<kKernel, Leaves>(f, level, c, at);
  return plotGreatGrandchildren<kKernel, Leaves>(f, level, c, at);
}
template <bool kSplat, typename Leaves, int... kBox>
__attribute__((noinline)) Cursor<Leaves> plotSubtree(const FastFrame& f, int level,
                                                     int levels_below, Vec3 c, Cursor<Leaves> at,
                                                     std::integer_sequence<int, kBox...>) {
  if constexpr (!kSplat) {
    return plotSubtreeWith<kOnePixel, Leaves>(f, level, levels_below, c, at);
  } else {
    f.splat.withBoxKernel(
        std::integer_sequence<int, kBox...>{}, [&](auto kernel) __attribute__((always_inline)) {
          at = plotSubtreeWith<decltype(kernel)::value, Leaves>(f, level, levels_below, c, at);
        });
    return at;
  }
}

// The box kernels plotSubtree is compiled for (SplatPlot kernel indices); another footprint
// takes the kNoBox kernel. Each is a whole loop nest per leaf type, about 1.3 KB of Thumb code on
// a Cortex-M0+: a bare-metal build, short of flash, keeps the footprints up to 2 x 2 only.
#if defined(OCTOPOINT_BARE_METAL)
using SubtreeBoxKernels = std::integer_sequence<int, 0, 1, kMostBoxSide, kMostBoxSide + 1>;
#else
using SubtreeBoxKernels = std::make_integer_sequence<int, kMostBoxSide * kMostBoxSide>;
#endif

template <bool kChecked, bool kSplat, typename Leaves>
Cursor<Leaves> visit(const FastFrame& f, int level, Vec3 c, Cursor<Leaves> at) {
  if (level <= kAbortCheckLevel && f.abort != nullptr) {
    if (!f.aborted && level == kAbortCheckLevel)
      f.aborted = f.abort->load(std::memory_order_relaxed);
    if (f.aborted) return at;
  }
  // A splat frame's level-3 subtree may cover the whole screen: it polls at every node below too,
  // and every loop stops at once when the flag is seen (octopoint/render.h's latency).
  if (kSplat && level > kAbortCheckLevel && f.abort != nullptr &&
      (f.aborted = f.abort->load(std::memory_order_relaxed))) {
    return at;
  }
  if constexpr (kChecked) {
    switch (f.clip.classify(level, c)) {
      case Clip::kOutside:
        f.off_screen.skip(at.node, at.leaves, level);
        return at;
      case Clip::kInside:
        f.off_screen.enter(level);
        return visit<false, kSplat, Leaves>(f, level, c, at);
      case Clip::kStraddling:
        f.off_screen.enter(level);
        break;
    }
  }
  if (level + 1 == f.levels) return plotChildren<kChecked, kSplat, Leaves>(f, level, c, at);
  // Two or three levels above the leaves: the subtree in one call (plotSubtree), three only where
  // the level below would not poll.
  const int levels_below = f.levels - level;
  if (!kChecked && (levels_below == 2 ||
                    (levels_below == 3 && (level + 1 > kAbortCheckLevel || f.abort == nullptr)))) {
    return plotSubtree<kSplat, Leaves>(f, level, levels_below, c, at, SubtreeBoxKernels{});
  }
  const auto& offsets = (*f.offsets)[static_cast<std::size_t>(level)];
  unsigned mask = *at.node++;
  if (!kChecked) f.off_screen.enterChildren(level, mask);  // a checked child counts itself
  for (; mask != 0; mask &= mask - 1) {
    at = visit<kChecked, kSplat, Leaves>(f, level + 1, c + offsets[lowestChild(mask)], at);
    if (kSplat && f.aborted) return at;
  }
  return at;
}

}  // namespace

bool renderFixedFast(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                     const std::atomic<bool>* abort) {
  if (checkRender(level, setup, frame) != RenderError::kNone)
    return false;  // refused, nothing drawn
  const bool splat = setup.splat.active();
  FastFrame f{PlotTarget(frame, setup),
              setup.depth,
              &setup.child_offset,
              splat ? SubtreeClip(setup, setup.splat) : SubtreeClip(setup),
              abort,
              false,
              SplatPlot(frame, setup),
              level.leaves.data(),
              level.normals.data(),
              OffScreenSkip(level)};
  return withLeafCursor(level, frame, [&]<typename Given>(Given given) {
    // A normal frame's cursor: the palette index pointer alone (NormalBesideColourLeaves).
    using Leaves = std::conditional_t<std::is_same_v<Given, ColourNormalLeaves>,
                                      NormalBesideColourLeaves, Given>;
    const Cursor<Leaves> root{level.nodes.data(), Leaves{given.colour}};
    if (splat) {
      visit<true, true, Leaves>(f, 0, setup.root, root);
    } else {
      visit<true, false, Leaves>(f, 0, setup.root, root);
    }
    return !f.aborted;
  });
}

}  // namespace octopoint
