#include <cassert>

#include "renderer/decode_baseline.h"
#include "renderer/render.h"

namespace octopoint {
namespace {

// Turns a leaf's Q(32-F).F position into its pixel and z-tests it.
struct ZBufferSink {
  Framebuffer& frame;
  int fraction_bits;
  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t colour) {
    frame.plot(x >> fraction_bits, y >> fraction_bits, z, colour);
  }
};

}  // namespace

bool renderFixedBaseline(const LevelView& level, const FrameSetup& setup, Framebuffer& frame,
                         const std::atomic<bool>* abort) {
  assert(level.depth == setup.depth);
  assert(frame.width() == setup.width && frame.height() == setup.height);
  ZBufferSink sink{frame, setup.fraction_bits};
  return BaselineWalk<ZBufferSink>(level, setup, sink, abort).run();
}

}  // namespace octopoint
