#pragma once
// What a smooth frame (octopoint/smooth.h) blends for a set-up: whether it blends at all, how far
// a leaf's kernel reaches and which depths count as one surface. SmoothSplats draws by these, and
// visibility pruning (codegen/visibility.h) keeps every leaf they let into a sampled view's blend,
// so that a pruned model's smooth frames are the unpruned model's.

#include <cstdint>

#include "octopoint/camera.h"

namespace octopoint {

struct SmoothReach {
  // Whether the set-up blends: its splats are on and a voxel's edge, widened by the level's sample
  // reach, is over a pixel. Otherwise the smooth frame is the box frame.
  bool blends = false;
  // The kernel's radius, Q(32-F).F pixels: a leaf at p adds to the pixels whose centre c has
  // p - radius < c < p + radius on both axes.
  std::int64_t radius = 0;
  // A leaf adds to a pixel only where its depth key and the pixel's nearest (the box frame's)
  // differ by at most this, depth-key units (the normals' blend rounds it up to whole 256ths).
  std::uint32_t tolerance = 0;
};

SmoothReach smoothReachOf(const FrameSetup& setup);

// The pixels, along one axis, whose centre c = x 2^F + 2^(F-1) lies strictly within `radius` of
// `at` (both Q(32-F).F), clipped to [0, size): [begin, end), empty when begin >= end.
struct KernelSpan {
  std::int32_t begin, end;
};
inline KernelSpan kernelSpan(std::int32_t at, std::int64_t radius, int fraction_bits,
                             std::int32_t size) {
  const std::int64_t half = std::int64_t{1} << (fraction_bits - 1);
  const std::int64_t first = ((at - radius - half) >> fraction_bits) + 1;
  const std::int64_t last = (at + radius - half - 1) >> fraction_bits;
  return {static_cast<std::int32_t>(first > 0 ? first : 0),
          static_cast<std::int32_t>(last + 1 < size ? last + 1 : size)};
}

}  // namespace octopoint
