#pragma once
// Encoding a voxel set as the depth-first child-mask byte stream of octopoint/model.h, and
// reading the voxel keys back out of such a stream.

#include <cstdint>
#include <span>
#include <vector>

namespace octopoint::prepare {

// `sorted_keys` are the voxels' Morton keys at `depth` (codegen/voxelizer.h), ascending and unique,
// which is already the order in which the stream meets the leaves. Returns the node bytes.
std::vector<std::uint8_t> encodeOctree(std::span<const std::uint64_t> sorted_keys, int depth);

// Appends to `out` the stream of depth `depth` of the subtree below one node at `level` (0 = the
// root), level < depth. The keys are Morton keys at `key_depth` >= depth, ascending, all sharing
// their first `level` octal digits; keys that differ only below `depth` stand for the same voxel.
// The whole stream is the root's subtree; the streamed preparer encodes each bin's subtree apart,
// every depth from the finest depth's keys.
void encodeSubtree(std::span<const std::uint64_t> sorted_keys, int level, int depth, int key_depth,
                   std::vector<std::uint8_t>& out);

// The leaf keys of a valid stream of `depth`, in stream order (ascending).
std::vector<std::uint64_t> decodeLeafKeys(std::span<const std::uint8_t> nodes, int depth);

}  // namespace octopoint::prepare
