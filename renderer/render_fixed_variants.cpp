// The integer decoders: each draws bit-identical frames (tests/core/render_variants_test.cpp).

#include "octopoint/render.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"
#include "renderer/framebuffer_plot.h"
#include "renderer/subtree_clip.h"

namespace octopoint {
namespace {

template <typename Leaves>
using CheckedPlot = FixedPlot<true, Leaves::kPayload>;
template <typename Leaves>
using InsidePlot = FixedPlot<false, Leaves::kPayload>;

template <typename Visit>
bool renderWith(Visit visit, const LevelView& level, const FrameSetup& setup, FrameView& frame,
                const std::atomic<bool>* abort) {
  if (checkRender(level, setup, frame) != RenderError::kNone)
    return false;  // refused, nothing drawn
  return withLeafCursor(level, frame, [&]<typename Leaves>(Leaves leaves) {
    DecodeState<std::int32_t, CheckedPlot<Leaves>, Leaves> state{level.nodes.data(),
                                                                 leaves,
                                                                 setup.child_offset,
                                                                 setup.depth,
                                                                 CheckedPlot<Leaves>(frame, setup),
                                                                 abort};
    visit(state, 0, setup.root);
    return !state.aborted;
  });
}

// Hierarchical clipping (renderer/subtree_clip.h): a subtree whose leaves all lie on screen is
// drawn without per-pixel bounds checks; one whose leaves all lie off screen is skipped (its bytes
// still have to be stepped over); only subtrees straddling an edge test each leaf.
template <typename Leaves>
class ClippedWalk {
 public:
  ClippedWalk(const LevelView& level, Leaves leaves, const FrameSetup& setup, FrameView& frame,
              const std::atomic<bool>* abort)
      : checked_{level.nodes.data(),
                 leaves,
                 setup.child_offset,
                 setup.depth,
                 CheckedPlot<Leaves>(frame, setup),
                 abort},
        inside_{level.nodes.data(),
                leaves,
                setup.child_offset,
                setup.depth,
                InsidePlot<Leaves>(frame, setup),
                abort},
        clip_(setup) {}

  bool run(const Vec3& root) {
    visit(0, root);
    return !checked_.aborted;
  }

 private:
  void visit(int level, const Vec3& centre) {
    if (checked_.stopsAt(level)) return;
    const Clip clip = clip_.classify(level, centre);
    if (clip == Clip::kOutside) {
      skipSubtree(checked_.node, checked_.leaves, level, checked_.depth);
      return;
    }
    if (clip == Clip::kInside) {
      // The unchecked walk's state lives beside the checked one: handing the cursors over costs
      // three stores, where building a state per subtree copied its plotter (a memcpy call on
      // Thumb-1, docs/device.md).
      inside_.node = checked_.node;
      inside_.leaves = checked_.leaves;
      inside_.aborted = checked_.aborted;
      visitSetBits(inside_, level, centre);
      checked_.node = inside_.node;
      checked_.leaves = inside_.leaves;
      checked_.aborted = inside_.aborted;
      return;
    }
    unsigned mask = *checked_.node++;
    const auto& offsets = checked_.offsets[static_cast<std::size_t>(level)];
    if (level + 1 == checked_.depth) {
      for (; mask != 0; mask &= mask - 1) {
        checked_.plot(centre + offsets[lowestChild(mask)], checked_.leaves.next());
      }
      return;
    }
    for (; mask != 0; mask &= mask - 1) visit(level + 1, centre + offsets[lowestChild(mask)]);
  }

  DecodeState<std::int32_t, CheckedPlot<Leaves>, Leaves> checked_;
  DecodeState<std::int32_t, InsidePlot<Leaves>, Leaves> inside_;
  SubtreeClip clip_;
};

}  // namespace

bool renderFixedBaseline(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                         const std::atomic<bool>* abort) {
  return renderWith([](auto& s, int l, Vec3 p) { visitBaseline(s, l, p); }, level, setup, frame,
                    abort);
}

bool renderFixedLeafCall(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                         const std::atomic<bool>* abort) {
  return renderWith([](auto& s, int l, Vec3 p) { visitLeafCall(s, l, p); }, level, setup, frame,
                    abort);
}

bool renderFixedUnrolled(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                         const std::atomic<bool>* abort) {
  return renderWith([](auto& s, int l, Vec3 p) { visitUnrolled(s, l, p); }, level, setup, frame,
                    abort);
}

bool renderFixedSetBits(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                        const std::atomic<bool>* abort) {
  return renderWith([](auto& s, int l, Vec3 p) { visitSetBits(s, l, p); }, level, setup, frame,
                    abort);
}

bool renderFixedClipped(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                        const std::atomic<bool>* abort) {
  if (checkRender(level, setup, frame) != RenderError::kNone)
    return false;  // refused, nothing drawn
  return withLeafCursor(level, frame, [&]<typename Leaves>(Leaves leaves) {
    return ClippedWalk<Leaves>(level, leaves, setup, frame, abort).run(setup.root);
  });
}

}  // namespace octopoint
