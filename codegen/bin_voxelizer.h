#pragma once
// Turning binned points into octree streams, one bin at a time, and joining the bins' subtrees
// into the whole tree. A bin is a node of the octree at some level (its key prefix): every voxel of
// a depth deeper than that level lies inside it, so the bin alone decides that part of the stream;
// the voxels at its own level and above it span several bins, so a bin hands up only the sum of
// its points' colours and the join (combineNodes) makes those voxels. Colours are summed as
// integers, so neither the order of the points nor how they were split changes a single byte.

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "codegen/colour_store.h"
#include "codegen/intensity_grey.h"
#include "codegen/point_bins.h"
#include "codegen/prepared_model.h"

namespace octopoint::prepare {

// The colours of a set of points, summed per channel.
struct ColourSum {
  std::array<std::uint64_t, 3> rgb{};
  std::uint64_t count = 0;

  void add(std::uint32_t packed) {
    rgb[0] += packed >> 16 & 0xffu;
    rgb[1] += packed >> 8 & 0xffu;
    rgb[2] += packed & 0xffu;
    ++count;
  }
  void merge(const ColourSum& other) {
    for (std::size_t ch = 0; ch < 3; ++ch) rgb[ch] += other.rgb[ch];
    count += other.count;
  }
};

// How points and voxels get their colours, fixed once the passes have seen every point.
struct VoxelColouring {
  enum class Payload { kRgb, kIntensity, kNone };
  std::vector<int> depths;  // the model's depths, ascending; the keys are at the last one
  Payload payload = Payload::kNone;
  IntensityRange intensity;  // kIntensity: the payload is a float's bits
  std::uint32_t near_z = 0;  // kNone: the smallest and largest z index at the finest
  std::uint32_t far_z = 0;   // depth, for the depth shade
  bool greyscale = false;

  int finest() const { return depths.back(); }
  // A point's payload as 0xRRGGBB.
  std::uint32_t pointColour(std::uint32_t payload) const;
  // The colour (0xRRGGBB) of the voxel `key` at `depth` whose points sum to `sum`.
  std::uint32_t voxelColour(const ColourSum& sum, std::uint64_t key, int depth) const;
};

// One depth's part of a subtree: its node bytes and leaf colours, in stream order, as pieces that
// are joined only once at the end.
struct SubtreePieces {
  std::vector<std::vector<std::uint8_t>> nodes;
  std::vector<std::span<const std::uint32_t>> colours;  // 0xRRGGBB per leaf, in a ColourStore
};

// What a node of the octree (a bin) contributes: the colour sum of all its points, and for each of
// the model's depths deeper than the node its subtree (levels[i] belongs to depths[i]; empty for
// depths at or above the node).
struct NodeResult {
  ColourSum sum;
  std::vector<SubtreePieces> levels;
};

// Scratch space of one worker thread.
struct VoxelizerBuffers {
  PointBuffer points;  // a bin's points
  PointBuffer scratch;
  std::vector<std::uint64_t> keys;
};

// The node at `level` from all of its points, given in `points` (the call reorders them, and
// buffers.scratch). Leaf colours go into `store`, which must outlive the result.
NodeResult voxelizeNode(std::span<BinnedPoint> points, int level, const VoxelColouring& colouring,
                        VoxelizerBuffers& buffers, ColourStore& store);

// A node at `level` from its descendants at `child_level` (their key prefixes ascending and all
// inside that one node); the colours of the voxels it makes go into `store`.
NodeResult combineNodes(int level, int child_level,
                        std::vector<std::pair<std::uint64_t, NodeResult>> children,
                        const VoxelColouring& colouring, ColourStore& store);

// Rec. 601 luma in 8.8 fixed point (77 + 150 + 29 = 256): the --scene "greyscale" palette.
Rgb8 toGrey(const Rgb8& colour);

}  // namespace octopoint::prepare
