#pragma once
// The footprint splat of octopoint/camera.h written from its definition, for tests: every
// leaf (positions from the baseline walk) covers the pixels whose centre lies in
// (p - P/2, p + P/2] per axis, P = W + 2(depth + 1) when the footprint W exceeds a pixel on either
// axis (an axis with W <= 1 pixel keeps the one pixel p >> F), each pixel keeping the smallest
// packed word. Slow and plain: each pixel centre near a leaf is tested in 64-bit arithmetic.
#include <algorithm>
#include <cstdint>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "renderer/decode_baseline.h"

namespace octopoint::testing_support {

class ReferenceSplat {
 public:
  ReferenceSplat(const FrameSetup& setup, Framebuffer& frame) : setup_(setup), frame_(frame) {
    const std::int64_t one = std::int64_t{1} << setup.fraction_bits;
    splat_ = setup.splat.extent_x > one || setup.splat.extent_y > one;
  }

  // `payload`: the palette index, or (in a PixelPayload::kColourNormal frame) palette index |
  // normal index << 8.
  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t payload) {
    const std::uint32_t word =
        frame_.payload() == PixelPayload::kColourNormal
            ? Framebuffer::packColourNormal(setup_.depthKey(z), payload)
            : Framebuffer::pack(setup_.depthKey(z), static_cast<std::uint8_t>(payload));
    const auto [x0, x1] = pixelRange(x, setup_.splat.extent_x);
    const auto [y0, y1] = pixelRange(y, setup_.splat.extent_y);
    for (std::int64_t py = std::max<std::int64_t>(y0, 0);
         py <= std::min<std::int64_t>(y1, frame_.height() - 1); ++py) {
      for (std::int64_t px = std::max<std::int64_t>(x0, 0);
           px <= std::min<std::int64_t>(x1, frame_.width() - 1); ++px) {
        std::uint32_t& pixel = frame_.pixelData()[static_cast<std::size_t>(py) *
                                                      static_cast<std::size_t>(frame_.width()) +
                                                  static_cast<std::size_t>(px)];
        pixel = std::min(pixel, word);
      }
    }
  }

  // Draws a whole level (with its normals when `frame` carries them).
  static void draw(const LevelView& level, const FrameSetup& setup, Framebuffer& frame) {
    ReferenceSplat sink(setup, frame);
    if (frame.payload() == PixelPayload::kColourNormal) {
      BaselineWalk<ReferenceSplat, true>(level, setup, sink).run();
    } else {
      BaselineWalk<ReferenceSplat>(level, setup, sink).run();
    }
  }

 private:
  // First and last pixel (inclusive) along one axis for a leaf at p with extent W (Q.F).
  std::pair<std::int64_t, std::int64_t> pixelRange(std::int64_t p, std::int64_t extent) const {
    const int f = setup_.fraction_bits;
    const std::int64_t one = std::int64_t{1} << f;
    if (!splat_ || extent <= one) return {p >> f, p >> f};
    const std::int64_t padded = extent + 2 * (setup_.depth + 1);
    std::int64_t first = INT64_MAX, last = INT64_MIN;
    // Candidates around p; the centre of pixel c is c * one + one / 2.
    for (std::int64_t c = ((p - padded) >> f) - 1; c <= ((p + padded) >> f) + 1; ++c) {
      const std::int64_t twice_centre = 2 * (c * one + one / 2);
      if (twice_centre > 2 * p - padded && twice_centre <= 2 * p + padded) {
        first = std::min(first, c);
        last = std::max(last, c);
      }
    }
    return {first, last};
  }

  const FrameSetup& setup_;
  Framebuffer& frame_;
  bool splat_ = false;
};

}  // namespace octopoint::testing_support
