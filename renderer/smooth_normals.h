#pragma once
// Smooth splats with normals (octopoint/smooth.h, docs/splats.md "Smooth splats"): a model's normal
// palette turned into a frame's view axes for blending, and a blended sum of normals made a unit
// vector again. Integers only.

#include <array>
#include <cstdint>

#include "octopoint/fixed.h"
#include "octopoint/model.h"
#include "octopoint/styles.h"

namespace octopoint {

// A normal as it is blended: view axes, Q1.10, turned toward the viewer (z <= 0). A weight (Q12,
// at most 4,096) times a component is below 2^22 in magnitude, so a pixel's signed 32-bit sums hold
// 512 full-weight contributions, where the leaves within a kernel's reach are a few dozen.
struct BlendNormal {
  std::int16_t x = 0, y = 0, z = 0;
};
inline constexpr int kBlendNormalBits = 10;

// The entries [0, count) of a normal palette (Q1.14, the model's axes) turned by `model_to_view`,
// each flipped where it faces away from the viewer: the shading is two-sided (ShadingTable), and
// a scan's normals point either way, so that two neighbours facing opposite ways add up instead of
// cancelling. Entries past `count` are zero.
void turnNormalsToViewer(const std::array<NormalQ14, 256>& palette, int count,
                         const Rotation& model_to_view, std::array<BlendNormal, 256>& turned);

// The unit vector (Q1.14) along the sum (x, y, z) of weighted normals, in integers: scaled so that
// its largest component has 15 bits, then divided by the integer square root of its squared
// length. A zero sum (no contribution) faces the viewer.
DirectionQ14 unitDirection(std::int32_t x, std::int32_t y, std::int32_t z);

}  // namespace octopoint
