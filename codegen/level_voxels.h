#pragma once
// A prepared level as a list of voxels (Morton keys and palette indices) and back, and the two
// operations the chunked writer needs on them: coarsening to a lower depth, and making the levels
// of a model nested (every voxel's parent present in the next coarser level).

#include <cstdint>
#include <span>
#include <vector>

#include "codegen/prepared_model.h"

namespace octopoint::prepare {

struct LevelVoxels {
  int depth = 0;
  std::vector<std::uint64_t> keys;    // Morton keys (codegen/voxelizer.h), ascending
  std::vector<std::uint8_t> colours;  // palette index per key
};

// The voxels of a level's stream, in stream order (which is ascending key order).
LevelVoxels decodeLevel(const PreparedLevel& level);
PreparedLevel encodeLevel(const LevelVoxels& voxels);

// The cells of depth `depth` (< voxels.depth) that hold some voxel, each coloured with the palette
// entry nearest to the mean colour of the voxels in it.
LevelVoxels coarsen(const LevelVoxels& voxels, int depth, std::span<const Rgb8> palette);

// Adds to each level the parents of the next finer level's voxels that it lacks (coloured as by
// coarsen), finest first, so that every level refines the one above it. Levels made from one scan
// are nested already; visibility pruning, which decides per depth, can break that. Returns the
// number of voxels added.
std::size_t nestLevels(PreparedModel& model);

}  // namespace octopoint::prepare
