// fixed_delta (renderer/render_fixed_delta.h): fixed_fast's walk for a small register file.
//
// What differs from fixed_fast, each measured on the Cortex-M0+ (docs/device.md):
// - On-screen leaf parents plot through renderer/delta_leaves.h: no x, y, z per leaf, no multiply,
//   no shift by a variable.
// - The walk's cursors are members, passed by reference: fixed_fast returns them by value, which
//   the ARM calling convention does through memory for a struct of two pointers.
// - The grandparents of on-screen leaves plot their grandchildren themselves (as fixed_fast), so
//   there is no call per leaf parent.
#include "renderer/render_fixed_delta.h"

#include "octopoint/render.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {
namespace {

struct DeltaWalk {
  const FrameSetup& setup;
  const SubtreeClip& clip;
  const DeltaLeaves& leaves;
  std::int32_t height;
  bool packed;
  const std::atomic<bool>* abort;
  const std::uint8_t* node;
  const std::uint8_t* leaf;
  bool aborted = false;

  // The children of an on-screen leaf parent at `c` with child mask `mask`.
  [[gnu::always_inline]] void plotInside(unsigned mask, const Vec3& c) {
    if (packed) {
      leaf = plotDeltaLeaves(leaves, mask, leaf, packCentre(leaves, c));
      return;
    }
    const auto& offsets = setup.child_offset[static_cast<std::size_t>(setup.depth - 1)];
    const int f = leaves.fraction_bits;
    for (; mask != 0; mask &= mask - 1) {
      const Vec3 p = c + offsets[lowestChild(mask)];
      const std::size_t index =
          static_cast<std::size_t>(p.y >> f) * static_cast<std::size_t>(leaves.width) +
          static_cast<std::size_t>(p.x >> f);
      const std::uint32_t word = FrameView::pack(setup.depthKey(p.z), *leaf++);
      if (word < leaves.pixel[index]) leaves.pixel[index] = word;
    }
  }

  // The children of a leaf parent at `c` that straddles the frame's edge: each tested.
  void plotChecked(unsigned mask, const Vec3& c) {
    const auto& offsets = setup.child_offset[static_cast<std::size_t>(setup.depth - 1)];
    const int f = leaves.fraction_bits;
    for (; mask != 0; mask &= mask - 1) {
      const Vec3 p = c + offsets[lowestChild(mask)];
      const std::uint8_t colour = *leaf++;
      const std::int32_t x = p.x >> f, y = p.y >> f;
      if (static_cast<std::uint32_t>(x) >= static_cast<std::uint32_t>(leaves.width) ||
          static_cast<std::uint32_t>(y) >= static_cast<std::uint32_t>(height)) {
        continue;
      }
      std::uint32_t& at =
          leaves.pixel[static_cast<std::size_t>(y) * static_cast<std::size_t>(leaves.width) +
                       static_cast<std::size_t>(x)];
      const std::uint32_t word = FrameView::pack(setup.depthKey(p.z), colour);
      if (word < at) at = word;
    }
  }

  // An on-screen subtree at `level` centred at `c`: a leaf parent or grandparent plotted here (no
  // call), a higher node walked by visit<false>. The caller polled the abort flag at this level.
  [[gnu::always_inline]] void drawInside(int level, const Vec3& c) {
    if (level + 2 < setup.depth) {
      visit<false>(level, c);
      return;
    }
    const unsigned mask = *node++;
    if (level + 1 == setup.depth) {
      plotInside(mask, c);
    } else {
      plotGrandchildren(mask, c);
    }
  }

  // The children of an on-screen grandparent at `c` (leaf parents) and theirs (leaves).
  [[gnu::always_inline]] void plotGrandchildren(unsigned mask, const Vec3& c) {
    if (packed) {
      plotDeltaGrandchildren(leaves, mask, node, leaf, packCentre(leaves, c));
      return;
    }
    const auto& offsets = setup.child_offset[static_cast<std::size_t>(setup.depth - 2)];
    for (; mask != 0; mask &= mask - 1) {
      const unsigned below = *node++;
      plotInside(below, c + offsets[lowestChild(mask)]);
    }
  }

  template <bool kChecked>
  void visit(int level, const Vec3& c) {
    if (level <= kAbortCheckLevel && abort != nullptr) {
      if (!aborted && level == kAbortCheckLevel) aborted = abort->load(std::memory_order_relaxed);
      if (aborted) return;
    }
    if constexpr (kChecked) {
      switch (clip.classify(level, c)) {
        case Clip::kOutside:
          skipSubtree(node, leaf, level, setup.depth);
          return;
        case Clip::kInside:
          drawInside(level, c);
          return;
        case Clip::kStraddling:
          break;
      }
    }
    const auto& offsets = setup.child_offset[static_cast<std::size_t>(level)];
    unsigned mask = *node++;
    if (level + 1 == setup.depth) {
      if (kChecked) {
        plotChecked(mask, c);
      } else {
        plotInside(mask, c);
      }
      return;
    }
    if (!kChecked && level + 2 == setup.depth) {  // leaf parents below: plotted here, no call each
      plotGrandchildren(mask, c);
      return;
    }
    for (; mask != 0; mask &= mask - 1) visit<kChecked>(level + 1, c + offsets[lowestChild(mask)]);
  }
};

}  // namespace

// What a refused decoder prepares from: depth 0, so the clip and the leaf tables read no offset
// (constexpr: in flash on a microcontroller, not 1 KB of RAM).
constexpr FrameSetup kRefusedSetup{};

FixedDeltaDecoder::FixedDeltaDecoder(const FrameSetup& setup, FrameView& frame)
    : accepted_(checkFrameSetup(setup) == RenderError::kNone && frame.width() == setup.width &&
                frame.height() == setup.height && frame.payload() == PixelPayload::kColour),
      setup_(accepted_ ? setup : kRefusedSetup),
      clip_(setup_),
      leaves_(prepareDeltaLeaves(setup_, frame.pixelData(), frame.width())),
      height_(frame.height()),
      packed_(deltaLeavesApply(setup_)) {}

bool FixedDeltaDecoder::draw(const LevelView& level, const Vec3& root,
                             const std::atomic<bool>* abort) {
  if (!accepted_ || level.depth != setup_.depth ||
      !plausibleLevelSize(level.depth, level.nodes.size(), level.leaves.size())) {
    return false;  // refused, nothing drawn
  }
  DeltaWalk walk{
      setup_, clip_, leaves_, height_, packed_, abort, level.nodes.data(), level.leaves.data()};
  walk.visit<true>(0, root);
  return !walk.aborted;
}

bool renderFixedDelta(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                      const std::atomic<bool>* abort) {
  return FixedDeltaDecoder(setup, frame).draw(level, setup.root, abort);
}

}  // namespace octopoint
