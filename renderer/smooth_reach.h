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

}  // namespace octopoint
