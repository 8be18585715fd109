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

// Interleaves the bits of a voxel's indices, x highest, so that ascending keys are exactly the
// depth-first order of the octree with child k = (x << 2) | (y << 1) | z.
std::uint64_t mortonKey(std::uint32_t x, std::uint32_t y, std::uint32_t z, int depth);
std::array<std::uint32_t, 3> mortonDecode(std::uint64_t key, int depth);

struct VoxelSet {
  int depth = 0;
  std::vector<std::uint64_t> keys;  // ascending, unique
  std::vector<Rgb8> colours;        // one per key
  std::vector<std::array<float, 3>> normals;  // one unit vector per key; empty without normals
};

VoxelSet voxelize(const Scan& scan, const CubeFit& fit, int depth);

// How many voxels of the 2^depth grid the scan's points occupy.
std::size_t occupiedVoxels(const Scan& scan, const CubeFit& fit, int depth);

}  // namespace octopoint::prepare
