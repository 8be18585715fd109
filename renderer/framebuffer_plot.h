#pragma once
// How a decoder writes a leaf into a Framebuffer: the z-test on raw pointers held by value, so the
// decoder's inner loop needs no call into Framebuffer. Two flavours: with the per-pixel bounds
// check, and without it for subtrees proven to lie on screen (hierarchical clipping).

#include <cassert>
#include <cstdint>

#include "renderer/camera.h"
#include "renderer/framebuffer.h"

namespace octopoint {

template <bool kChecked>
struct FixedPlot {
  std::uint8_t* colour;
  std::int32_t* depth;
  std::int32_t width;
  std::int32_t height;
  int fraction_bits;

  FixedPlot(Framebuffer& frame, const FrameSetup& setup)
      : colour(frame.colourIndexData()),
        depth(frame.depthData()),
        width(frame.width()),
        height(frame.height()),
        fraction_bits(setup.fraction_bits) {}

  // `p` in Q(32-F).F screen pixels; the pixel is p >> F (floor).
  void operator()(const Vec3& p, std::uint8_t palette_index) const {
    const std::int32_t x = p.x >> fraction_bits;
    const std::int32_t y = p.y >> fraction_bits;
    if constexpr (kChecked) {
      if (static_cast<std::uint32_t>(x) >= static_cast<std::uint32_t>(width) ||
          static_cast<std::uint32_t>(y) >= static_cast<std::uint32_t>(height)) {
        return;
      }
    } else {
      assert(x >= 0 && x < width && y >= 0 && y < height);
    }
    const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                           static_cast<std::size_t>(x);
    if (p.z < depth[at]) {
      depth[at] = p.z;
      colour[at] = palette_index;
    }
  }
};

}  // namespace octopoint
