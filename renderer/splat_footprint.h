#pragma once
// The footprint splat of one frame: which pixels a leaf covers when a voxel of the drawn depth
// projects to more than one pixel (docs/splats.md).
//
// Orthographic projection maps every leaf cube of a level to the same shape, so its screen extent
// per axis is the same for all leaves of the frame: W_a = e * (|R[a][0]| + |R[a][1]| + |R[a][2]|)
// pixels for a voxel edge of e pixels and the rotation R. FrameSetup holds the child offsets of
// the last level, +-e/2 along each rotated axis, so W_a = 2 * max_k |child_offset[depth-1][k].a|
// (Q(32-F).F, rounded once, within one unit in the last place).
//
// - W_x and W_y both at most one pixel (2^F): no splat. A leaf sets the one pixel p >> F, exactly
//   as the decoders always did, and that is hole-free: a pixel centre c inside the projected cube
//   of a leaf at p has |c - p| < W/2 <= 1/2 per axis, so p lies in c's pixel.
// - Otherwise, per axis with W_a > 1 pixel: the extent is padded by `depth + 1` units on each
//   side (a leaf position is within depth/2 units of exact, W within one), P_a = W_a + 2(depth+1),
//   and the leaf covers the pixels whose centre lies in (p - P_a/2, p + P_a/2]: from
//   floor(p + 1/2 - P_a/2) to floor(p - 1/2 + P_a/2), that is from (p + offset) >> F to
//   (p + offset + span) >> F with offset = 2^(F-1) - P_a/2 and span = P_a - 2^F. That is
//   floor(P_a) or ceil(P_a) pixels, never more than `columns` = ceil(P_x) (`rows` = ceil(P_y)).
//   An axis with W_a <= 1 keeps offset 0, span 0: the one pixel p >> F, as above.
// The splat thus covers every pixel centre inside the projection of the leaf's cube (within the
// leaf's axis-aligned bounding box, padded by the rounding): a surface sampled densely enough to
// leave no empty voxel along it draws with no hole inside its silhouette. The padding is a few
// units of 2^-F pixel, so an exactly 4-pixel voxel still covers 4 pixels, not 5.
// Everything is integer; the set-up computes it once per frame (buildFrameSetup).

#include <cstdint>

namespace octopoint {

struct SplatFootprint {
  std::int32_t columns = 1;   // the most pixels a leaf covers along x
  std::int32_t rows = 1;      // the most pixels a leaf covers along y
  // Q(32-F).F: a leaf at p covers the columns (p.x + offset_x) >> F .. (p.x + offset_x + span_x) >> F
  // and the rows (p.y + offset_y) >> F .. (p.y + offset_y + span_y) >> F.
  std::int32_t offset_x = 0;
  std::int32_t offset_y = 0;
  std::int32_t span_x = 0;
  std::int32_t span_y = 0;
  // The projected voxel extent W per axis, Q(32-F).F, unpadded (what depth by projected size uses).
  std::int32_t extent_x = 0;
  std::int32_t extent_y = 0;

  // Whether leaves cover more than their one pixel (the decoders' splat path).
  bool active() const { return columns > 1 || rows > 1; }
};

// The footprint for a last level whose largest child offsets per axis are `half_x`, `half_y`
// (Q(32-F).F, >= 0), drawn at `depth` with `fraction_bits` F. Offsets and sizes fit 32 bits when
// buildFrameSetup accepted the camera (it checks the splat's reach too).
SplatFootprint splatFootprint(std::int64_t half_x, std::int64_t half_y, int depth, int fraction_bits);

}  // namespace octopoint
