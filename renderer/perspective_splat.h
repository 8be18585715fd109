#pragma once
// Which pixels a perspective leaf writes (renderer/perspective_walk.cpp's plot), in a header of its
// own so that visibility pruning (codegen/eye_visibility.h) follows the very same rule.

#include <algorithm>
#include <cstdint>

#include "renderer/perspective_walk.h"

namespace octopoint {

// The pixels [first, last] whose centres lie within [p - half, p + half] on one axis (Q(32-F).F),
// clipped to [0, size); the pixel p >> F alone when no centre does.
struct PixelSpan {
  std::int64_t first, last;
};
inline PixelSpan pixelSpan(std::int64_t p, std::int64_t half, int fraction_bits,
                           std::int32_t size) {
  const std::int64_t one = std::int64_t{1} << fraction_bits, mid = one >> 1;
  std::int64_t first = (p - half - mid + one - 1) >> fraction_bits;
  std::int64_t last = (p + half - mid) >> fraction_bits;
  if (last < first) first = last = p >> fraction_bits;
  return {std::max<std::int64_t>(first, 0), std::min<std::int64_t>(last, size - 1)};
}

// How far a leaf may lie from its exact position (the affine map's error, the additions'
// rounding): its neighbour may lie as far the other way, so each widens its splat by that much.
inline std::int64_t splatPadding(const PerspectiveWalkTables& tables) {
  return tables.max_error + tables.depth + 1;
}

}  // namespace octopoint
