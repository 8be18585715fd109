#pragma once
// How a decoder writes a leaf into a Framebuffer: the z-test on raw pointers held by value, so the
// decoder's inner loop needs no call into Framebuffer. Two flavours: with the per-pixel bounds
// check, and without it for subtrees proven to lie on screen (hierarchical clipping).

#include <cassert>
#include <cstdint>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "renderer/subtree_clip.h"

namespace octopoint {

// What every integer decoder needs to write pixels: the frame's words and size, and the set-up's
// screen (Q(32-F).F) and depth-key formats. Taking them tells the frame where the decoder may
// write (FrameView::drawnRect): the pixels of the set-up's whole cube, root +- the reach of level
// 0 widened by the splat (one pixel per leaf lies inside that too: a splat's first pixel offset is
// <= 0 <= its last's), so the next clear empties no more than that.
struct PlotTarget {
  PlotTarget(FrameView& frame, const FrameSetup& setup)
      : pixel(frame.pixelsToDraw(SubtreeClip(setup, setup.splat).pixelBounds(0, setup.root))),
        width(frame.width()),
        height(frame.height()),
        fraction_bits(setup.fraction_bits),
        depth_bias(setup.depth_bias),
        depth_shift(setup.depth_shift) {}

  // FrameSetup::depthKey in two steps: z (Q(32-F).F) plus the bias, mod 2^32, then the shift.
  std::uint32_t biasedDepth(std::int32_t z) const {
    return static_cast<std::uint32_t>(z) + depth_bias;
  }
  std::uint32_t depthKey(std::int32_t z) const { return biasedDepth(z) >> depth_shift; }

  std::uint32_t* pixel;
  std::int32_t width;
  std::int32_t height;
  int fraction_bits;
  std::uint32_t depth_bias;
  int depth_shift;
};

template <bool kChecked, PixelPayload kPayload = PixelPayload::kColour>
struct FixedPlot : PlotTarget {
  using PlotTarget::PlotTarget;
  explicit FixedPlot(const PlotTarget& target) : PlotTarget(target) {}

  // `p` in Q(32-F).F screen pixels; the pixel is p >> F (floor). `payload`: the palette index
  // (and normal index << 8 for kColourNormal), as the leaf cursor gives it.
  void operator()(const Vec3& p, std::uint32_t payload) const {
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
    const std::size_t at =
        static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
    const std::uint32_t word = Framebuffer::packLeaf<kPayload>(depthKey(p.z), payload);
    if (word < pixel[at]) pixel[at] = word;
  }
};

}  // namespace octopoint
