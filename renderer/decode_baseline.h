#pragma once
// Algorithm 1 (renderer/decode_algorithms.h) over a level, handing every leaf's Q(32-F).F screen
// position and palette index to a sink: the slow, readable walk that tests and tools use to see
// each leaf (fixed_baseline draws with the same walk into a z-buffer).

#include <atomic>
#include <cstdint>

#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {

// With kWithNormals, the sink gets each leaf's payload (palette index | normal index << 8, as
// renderer/leaf_cursor.h reads it) instead of its palette index alone; the level must have normals.
template <typename LeafSink, bool kWithNormals = false>
class BaselineWalk {
 public:
  // `sink(x, y, z, palette_index)` (or `payload`) is called once per leaf, in stream order.
  BaselineWalk(const LevelView& level, const FrameSetup& setup, LeafSink& sink,
               const std::atomic<bool>* abort = nullptr)
      : level_(level), setup_(setup), sink_(sink), abort_(abort) {}

  // Returns false when the walk was aborted (the sink then saw only part of the leaves).
  bool run() {
    if constexpr (kWithNormals) {
      DecodeState<std::int32_t, ForwardToSink, ColourNormalLeaves> state{
          level_.nodes.data(),  ColourNormalLeaves{level_.leaves.data(), level_.normals.data()},
          setup_.child_offset,  setup_.depth,
          ForwardToSink{sink_}, abort_};
      visitBaseline(state, 0, setup_.root);
      return !state.aborted;
    } else {
      DecodeState<std::int32_t, ForwardToSink> state{
          level_.nodes.data(),  ColourLeaves{level_.leaves.data()},
          setup_.child_offset,  setup_.depth,
          ForwardToSink{sink_}, abort_};
      visitBaseline(state, 0, setup_.root);
      return !state.aborted;
    }
  }

 private:
  struct ForwardToSink {
    LeafSink& sink;
    void operator()(const Vec3& p, std::uint32_t payload) {
      if constexpr (kWithNormals) {
        sink(p.x, p.y, p.z, payload);
      } else {
        sink(p.x, p.y, p.z, static_cast<std::uint8_t>(payload));
      }
    }
  };

  const LevelView& level_;
  const FrameSetup& setup_;
  LeafSink& sink_;
  const std::atomic<bool>* abort_;
};

}  // namespace octopoint
