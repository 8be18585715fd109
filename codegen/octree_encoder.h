#pragma once
// Encoding a voxel set as the depth-first child-mask byte stream of renderer/model_format.h.

#include <cstdint>
#include <span>
#include <vector>

namespace octopoint::prepare {

// `sorted_keys` are the voxels' Morton keys at `depth` (codegen/voxelizer.h), ascending and unique,
// which is already the order in which the stream meets the leaves. Returns the node bytes.
std::vector<std::uint8_t> encodeOctree(std::span<const std::uint64_t> sorted_keys, int depth);

}  // namespace octopoint::prepare
