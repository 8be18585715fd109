#pragma once
// The distinct colours of a model's voxels and how many voxels have each, in ascending order of
// their 0xRRGGBB value: what the palette is built from. Tens of millions of voxels in the pieces
// the voxelizer made, without joining them first: grouped by red (one counting pass, one scatter),
// then each red counted by green and blue in a table that fits in the cache, on every thread.

#include <cstdint>
#include <span>
#include <vector>

namespace octopoint::prepare {

struct ColourCount {
  std::uint32_t packed;  // 0xRRGGBB
  std::uint32_t count;
};

// Every colour of every piece, counted; ascending by colour, whatever the pieces and threads.
std::vector<ColourCount> countColours(std::span<const std::span<const std::uint32_t>> pieces,
                                      unsigned threads);

}  // namespace octopoint::prepare
