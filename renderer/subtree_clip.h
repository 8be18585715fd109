#pragma once
// Hierarchical clipping (fixed_clipped, fixed_fast): whether all leaves of a subtree land on
// screen, all off screen, or some of each, decided once per node instead of once per leaf.
//
// Leaves of a node at tree level l lie within reach[l] = sum over l' >= l of max_k |offset[l'][k]|
// of its centre, per axis (Q(32-F).F). A leaf at p covers the pixels (p + low) >> F to
// (p + high) >> F per axis: low = high = 0 for one pixel per leaf, the splat's first and last
// pixel otherwise (octopoint/camera.h), so a subtree is on screen when its reach widened by
// them is. Screen edges are kept in 64 bits: width << F does not fit 32 bits at F = 24. When every
// bound of this set-up's tree fits 32 bits (F = 15 and the usual sizes), the test runs in 32 bits:
// a 32-bit CPU (Cortex-M0+) compares 64-bit values in several instructions and two branches.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"

namespace octopoint {

enum class Clip { kOutside, kInside, kStraddling };

class SubtreeClip {
 public:
  // `splat`: the footprint the decoder draws (one pixel per leaf by default).
  explicit SubtreeClip(const FrameSetup& setup, const SplatFootprint& splat = SplatFootprint{})
      : fraction_bits_(setup.fraction_bits),
        x_end_(std::int64_t{setup.width} << setup.fraction_bits),
        y_end_(std::int64_t{setup.height} << setup.fraction_bits),
        low_x_(splat.offset_x),
        low_y_(splat.offset_y),
        high_x_(std::int64_t{splat.offset_x} + splat.span_x),
        high_y_(std::int64_t{splat.offset_y} + splat.span_y) {
    // Magnitudes and sums in 32 bits: buildFrameSetup bounds |root| plus the sum of the largest
    // offsets below 2^31. A decoder builds this per call, a band renderer once per subtree and
    // band.
    const auto magnitude = [](std::int32_t v) {
      return v < 0 ? std::uint32_t{0} - static_cast<std::uint32_t>(v)
                   : static_cast<std::uint32_t>(v);
    };
    std::uint32_t x = 0, y = 0;
    for (int l = setup.depth - 1; l >= 0; --l) {
      std::uint32_t widest_x = 0, widest_y = 0;
      for (const Vec3& d : setup.child_offset[static_cast<std::size_t>(l)]) {
        widest_x = std::max(widest_x, magnitude(d.x));
        widest_y = std::max(widest_y, magnitude(d.y));
      }
      reach_x_[static_cast<std::size_t>(l)] = static_cast<std::int32_t>(x += widest_x);
      reach_y_[static_cast<std::size_t>(l)] = static_cast<std::int32_t>(y += widest_y);
    }
    // Every node centre of this tree lies within |root| + reach[0] of 0; with the splat's pixels
    // and the screen edges below 2^31, no 32-bit sum in classify can wrap.
    const auto fits = [](std::int64_t root, std::int64_t reach, std::int64_t low, std::int64_t high,
                         std::int64_t end) {
      return std::llabs(root) + reach + std::max(std::llabs(low), std::llabs(high)) < INT32_MAX &&
             end <= INT32_MAX;
    };
    narrow_ = fits(setup.root.x, x, low_x_, high_x_, x_end_) &&
              fits(setup.root.y, y, low_y_, high_y_, y_end_);
  }

  Clip classify(int level, const Vec3& centre) const {
    if (narrow_) {
      const std::int32_t rx = reach_x_[static_cast<std::size_t>(level)];
      const std::int32_t ry = reach_y_[static_cast<std::size_t>(level)];
      const std::int32_t left = centre.x - rx + static_cast<std::int32_t>(low_x_);
      const std::int32_t right = centre.x + rx + static_cast<std::int32_t>(high_x_);
      const std::int32_t top = centre.y - ry + static_cast<std::int32_t>(low_y_);
      const std::int32_t bottom = centre.y + ry + static_cast<std::int32_t>(high_y_);
      const auto x_end = static_cast<std::int32_t>(x_end_),
                 y_end = static_cast<std::int32_t>(y_end_);
      if (right < 0 || left >= x_end || bottom < 0 || top >= y_end) return Clip::kOutside;
      if (left >= 0 && right < x_end && top >= 0 && bottom < y_end) return Clip::kInside;
      return Clip::kStraddling;
    }
    const std::int64_t rx = reach_x_[static_cast<std::size_t>(level)];
    const std::int64_t ry = reach_y_[static_cast<std::size_t>(level)];
    const std::int64_t left = centre.x - rx + low_x_, right = centre.x + rx + high_x_;
    const std::int64_t top = centre.y - ry + low_y_, bottom = centre.y + ry + high_y_;
    if (right < 0 || left >= x_end_ || bottom < 0 || top >= y_end_) return Clip::kOutside;
    if (left >= 0 && right < x_end_ && top >= 0 && bottom < y_end_) return Clip::kInside;
    return Clip::kStraddling;
  }

  // The pixels the leaves of the subtree at `level` centred at `centre` can write (their splats
  // included), whether on screen or not: from the first pixel of the leftmost possible leaf to
  // the last of the rightmost, per axis. Unclipped (Framebuffer::pixelsToDraw clips); 64-bit
  // edges shifted to pixels, saturated to 32 bits.
  PixelRect pixelBounds(int level, const Vec3& centre) const {
    const std::int64_t rx = reach_x_[static_cast<std::size_t>(level)];
    const std::int64_t ry = reach_y_[static_cast<std::size_t>(level)];
    return PixelRect{toPixel(centre.x - rx + low_x_), toPixel(centre.x + rx + high_x_) + 1,
                     toPixel(centre.y - ry + low_y_), toPixel(centre.y + ry + high_y_) + 1};
  }

 private:
  std::int32_t toPixel(std::int64_t position) const {  // floor(position / 2^F), within 32 bits
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(
        position >> fraction_bits_, -(std::int64_t{1} << 30), std::int64_t{1} << 30));
  }

  int fraction_bits_;
  std::int64_t x_end_, y_end_;
  std::int64_t low_x_, low_y_, high_x_, high_y_;
  bool narrow_ = false;  // every bound fits 32 bits: classify in 32-bit arithmetic
  std::array<std::int32_t, kMaxRenderDepth> reach_x_{}, reach_y_{};
};

}  // namespace octopoint
