#pragma once
// The depth a perspective frame's pixel words carry (docs/perspective.md, "Styles and hole
// filling"), and how far apart the depths of two neighbouring pixels on one surface may lie.
//
// A colour frame's key is camera-space z, linear: z >> kPerspectiveDepthShift, units of 2^-14 cube
// edge in 24 bits. A frame that carries normals (PixelPayload::kColourNormal) keeps 16 bits of the
// key, which linear would leave at 2^-6 cube edge (four voxels of depth 8): near the eye the
// z-test would mix surfaces centimetres apart and every silhouette there would vanish. Its key is
// instead a small float of z: 5 bits of exponent and 11 of mantissa, monotonic in z (so nearest
// still wins by one comparison, and occlusion culling's bound holds), its step 2^-11 to 2^-12 of
// the depth, as a perspective view needs (a pixel spans z / f across at depth z).

#include <algorithm>
#include <bit>
#include <cstdint>

#include "octopoint/framebuffer.h"
#include "octopoint/render.h"
#include "renderer/perspective.h"

namespace octopoint {

// Depths below 2^-18 cube edge are one step (z >> 6); the code counts that unit linearly up to
// 2^11 units, then by 2^11 steps per octave.
inline constexpr int kNormalDepthUnitShift = 6;  // Q.24 z >> 6: 2^-18 cube edge units
inline constexpr int kNormalDepthMantissaBits = 11;

// The 16-bit depth code of camera-space z (Q.24, below 2^34) in a kColourNormal frame. Monotonic:
// z <= z' gives code(z) <= code(z'). The largest is (28 - 11) << 11 | 2047 < 2^16.
inline std::uint32_t perspectiveNormalDepthCode(std::int64_t z) {
  constexpr std::uint64_t kLargest = (std::uint64_t{1} << 28) - 1;
  const std::uint64_t u = std::min<std::uint64_t>(
      static_cast<std::uint64_t>(std::max<std::int64_t>(z, 0)) >> kNormalDepthUnitShift, kLargest);
  constexpr std::uint64_t kLinear = std::uint64_t{1} << kNormalDepthMantissaBits;
  if (u < kLinear) return static_cast<std::uint32_t>(u);
  const int bits = std::bit_width(u);  // 12..28
  const int octave = bits - kNormalDepthMantissaBits;
  return static_cast<std::uint32_t>(octave) << kNormalDepthMantissaBits |
         static_cast<std::uint32_t>((u >> (octave - 1)) & (kLinear - 1));
}

// The smallest depth (2^-18 cube edge units) whose code is `code`.
inline std::uint64_t perspectiveNormalDepthOfCode(std::uint32_t code) {
  constexpr std::uint32_t kLinear = std::uint32_t{1} << kNormalDepthMantissaBits;
  if (code < kLinear) return code;
  const int octave = static_cast<int>(code >> kNormalDepthMantissaBits);
  return std::uint64_t{kLinear | (code & (kLinear - 1))} << (octave - 1);
}

// The 24-bit key (FrameView::packColourNormal keeps its top 16 bits) of z in a kColourNormal frame.
inline std::uint32_t perspectiveNormalDepthKey(std::int64_t z) {
  return perspectiveNormalDepthCode(z) << 8;
}

// A pixel word's depth in 2^-18 cube edge units (the code's smallest in a kColourNormal frame).
inline std::uint64_t perspectiveWordDepth(std::uint32_t word, PixelPayload payload) {
  return payload == PixelPayload::kColourNormal
             ? perspectiveNormalDepthOfCode(word >> 16)
             : std::uint64_t{FrameView::depthKeyOf(word)}
                   << (kPerspectiveDepthShift - kNormalDepthUnitShift);
}

// The hole filler's rule for frames of `view` whose finest depth drawn is `finest_depth`
// (PerspectiveBridge): kBridgeDepthVoxelEdges pixels across at the nearer pixel's depth, or as many
// of that depth's voxel edges where they are larger.
inline PerspectiveBridge perspectiveBridge(const PerspectiveView& view, int finest_depth) {
  constexpr int kUnitBits = kPerspectiveUnitBits - kNormalDepthUnitShift;  // 2^-18 cube edge
  PerspectiveBridge bridge;
  bridge.least = std::uint64_t{kBridgeDepthVoxelEdges} << (kUnitBits - finest_depth);
  // 4 / f in Q.16 with f in Q.16: (4 << 32) / f, rounded up.
  const auto focal = static_cast<std::uint64_t>(std::max<std::int64_t>(view.focal_q16, 1));
  bridge.per_depth_q16 = ((std::uint64_t{kBridgeDepthVoxelEdges} << 32) + focal - 1) / focal;
  return bridge;
}

}  // namespace octopoint
