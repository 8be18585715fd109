#pragma once
// Algorithm 1 of the paper: recurse from the root down to every leaf, adding one precomputed
// displacement vector per level; the leaf itself hands its position to the sink. Templated on the
// sink so that the same walk draws into a z-buffer (fixed_baseline) or lists leaf positions (tests,
// tools) with no indirect call per leaf.

#include <atomic>
#include <cstdint>

#include "renderer/abort_flag.h"
#include "renderer/camera.h"
#include "renderer/model.h"

namespace octopoint {

template <typename LeafSink>
class BaselineWalk {
 public:
  BaselineWalk(const LevelView& level, const FrameSetup& setup, LeafSink& sink,
               const std::atomic<bool>* abort = nullptr)
      : node_(level.nodes.data()), leaf_(level.leaves.data()), setup_(setup), sink_(sink), abort_(abort) {}

  // Returns false when the walk was aborted (the sink then saw only part of the leaves).
  bool run() {
    visit(0, setup_.root.x, setup_.root.y, setup_.root.z);
    return !aborted_;
  }

 private:
  // A node at tree level `level` centred at (x, y, z), in Q(32-F).F screen pixels.
  void visit(int level, std::int32_t x, std::int32_t y, std::int32_t z) {
    if (level <= kAbortCheckLevel && abort_ != nullptr && shouldStop(level)) return;
    if (level == setup_.depth) {
      sink_(x, y, z, *leaf_++);
      return;
    }
    const std::uint8_t mask = *node_++;
    const auto& offsets = setup_.child_offset[static_cast<std::size_t>(level)];
    for (int k = 0; k < 8; ++k) {
      if (mask & (1u << k)) {
        const Vec3& d = offsets[static_cast<std::size_t>(k)];
        visit(level + 1, x + d.x, y + d.y, z + d.z);
      }
    }
  }

  // Polls the flag at tree level kAbortCheckLevel only (at most 8^3 = 512 polls a frame); once it
  // was seen, every node down to that level returns at once, unwinding the recursion.
  bool shouldStop(int level) {
    if (!aborted_ && level == kAbortCheckLevel) aborted_ = abort_->load(std::memory_order_relaxed);
    return aborted_;
  }

  const std::uint8_t* node_;
  const std::uint8_t* leaf_;
  const FrameSetup& setup_;
  LeafSink& sink_;
  const std::atomic<bool>* abort_;
  bool aborted_ = false;
};

}  // namespace octopoint
