#pragma once
// Voxelizing a scan: every point falls into one voxel of the 2^depth grid; a voxel is occupied when
// some point falls in it, and its colour is the mean of its points' colours. Scans without colour
// get a depth shade (nearer is brighter) so that their shape reads on screen. A scan with normals
// (codegen/normal_estimation.h) gives each voxel the mean of its points' normals, robustly: where
// they disagree (a voxel on a crease holds points of both faces) the mean of the largest group
// that agrees within 30 degrees, so that a crease is not blurred into an in-between normal.

#include <cstdint>
#include <vector>

#include "codegen/cube_fit.h"
#include "codegen/prepared_model.h"
#include "codegen/scan_loader.h"

namespace octopoint::prepare {

// Spreads the low 21 bits of `v` so that bit b lands on bit 3b (the classic magic-number split).
constexpr std::uint64_t spreadBitsBy3(std::uint32_t v) {
  std::uint64_t x = v & 0x1fffffu;
  x = (x | x << 32) & 0x001f00000000ffffull;
  x = (x | x << 16) & 0x001f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

// Interleaves the bits of a voxel's indices, x highest, so that ascending keys are exactly the
// depth-first order of the octree with child k = (x << 2) | (y << 1) | z. Bits of an index at or
// above `depth` (at most 21) are dropped. Inline: the streamed preparer makes one key per point.
constexpr std::uint64_t mortonKey(std::uint32_t x, std::uint32_t y, std::uint32_t z, int depth) {
  const std::uint32_t mask = (std::uint32_t{1} << depth) - 1;
  return spreadBitsBy3(x & mask) << 2 | spreadBitsBy3(y & mask) << 1 | spreadBitsBy3(z & mask);
}
std::array<std::uint32_t, 3> mortonDecode(std::uint64_t key, int depth);

// The grey of a voxel of a scan without colour: nearer is brighter. `z` is the voxel's z index,
// `near` and `far` the smallest and largest z index of any voxel at that depth.
std::uint8_t depthShade(std::uint32_t z, std::uint32_t near, std::uint32_t far);

struct VoxelSet {
  int depth = 0;
  std::vector<std::uint64_t> keys;            // ascending, unique
  std::vector<Rgb8> colours;                  // one per key
  std::vector<std::array<float, 3>> normals;  // one unit vector per key; empty without normals
};

VoxelSet voxelize(const Scan& scan, const CubeFit& fit, int depth);

// The voxels of the 2^depth grid the scan's points occupy: their Morton keys, ascending, unique.
std::vector<std::uint64_t> occupiedVoxelKeys(const Scan& scan, const CubeFit& fit, int depth);

}  // namespace octopoint::prepare
