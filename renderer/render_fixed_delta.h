#pragma once
// fixed_delta: the integer decoder for CPUs with few registers (a Cortex-M0+), and the fastest band
// variant there (docs/device.md). fixed_fast's walk (hierarchical clipping, no call per leaf
// parent) with the leaves of on-screen leaf parents plotted from per-child pixel-index deltas and
// packed sub-pixel carries (renderer/delta_leaves.h). One pixel per leaf, as the paper's variants:
// bit-identical to fixed_baseline.
//
// Its preparation is an object, so that band rendering (octopoint/bands.h) prepares once per
// band and then draws each subtree of the band index with a call: the clip's reach and the leaf
// table are not computed again per subtree.
//
// It draws colour frames only (PixelPayload::kColour): its Thumb-1 leaf loop has no register left
// for a second leaf cursor. A frame cleared for normals (a lit or creased style) is refused.

#include <atomic>
#include <cstdint>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "renderer/delta_leaves.h"
#include "renderer/subtree_clip.h"

namespace octopoint {

class FixedDeltaDecoder {
 public:
  // Prepares to draw trees of `setup` (its child offsets, depth, screen and depth-key formats)
  // into `frame`, which has the set-up's width and height. A set-up checkFrameSetup refuses, a
  // frame of another size, or a frame that carries normals, is refused here
  // (octopoint/render.h): every draw then returns false and draws nothing.
  FixedDeltaDecoder(const FrameSetup& setup, FrameView& frame);

  // Draws `level` (of the set-up's depth) with its root at `root`: the whole tree when `root` is
  // the set-up's root, or a subtree whose stream and centre those are. Returns false when `abort`
  // stopped it (polled at tree level kAbortCheckLevel), or, without drawing, when the decoder was
  // refused or the level's depth or sizes do not fit (checkRender's checks, once per decoder for
  // the set-up: a band draws each of its subtrees with one decoder).
  bool draw(const LevelView& level, const Vec3& root, const std::atomic<bool>* abort = nullptr);

  // The clip the decoder classifies subtrees with (the set-up's, one pixel per leaf).
  const SubtreeClip& clip() const { return clip_; }

 private:
  bool accepted_;            // the set-up and frame passed the checks
  const FrameSetup& setup_;  // the caller's, or when refused an empty one (nothing to prepare)
  SubtreeClip clip_;
  DeltaLeaves leaves_;
  std::int32_t height_;
  bool packed_;  // deltaLeavesApply(setup)
};

}  // namespace octopoint
