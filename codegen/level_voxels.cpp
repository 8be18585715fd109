#include "codegen/level_voxels.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <limits>

#include "codegen/octree_encoder.h"

namespace octopoint::prepare {
namespace {

void decodeNode(const std::uint8_t*& node, int level, int depth, std::uint64_t prefix,
                std::vector<std::uint64_t>& keys) {
  for (unsigned mask = *node++; mask != 0; mask &= mask - 1) {
    const std::uint64_t key = prefix << 3 | static_cast<unsigned>(std::countr_zero(mask));
    if (level + 1 == depth) {
      keys.push_back(key);
    } else {
      decodeNode(node, level + 1, depth, key, keys);
    }
  }
}

std::uint8_t nearestPaletteIndex(const std::array<std::uint64_t, 3>& sum, std::uint64_t count,
                                 std::span<const Rgb8> palette) {
  std::array<std::int64_t, 3> mean{};
  for (std::size_t ch = 0; ch < 3; ++ch)
    mean[ch] = static_cast<std::int64_t>((sum[ch] + count / 2) / count);
  std::int64_t best = std::numeric_limits<std::int64_t>::max();
  std::size_t best_index = 0;
  for (std::size_t i = 0; i < palette.size(); ++i) {
    std::int64_t distance = 0;
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const std::int64_t d = mean[ch] - palette[i][ch];
      distance += d * d;
    }
    if (distance < best) {
      best = distance;
      best_index = i;
    }
  }
  return static_cast<std::uint8_t>(best_index);
}

}  // namespace

LevelVoxels decodeLevel(const PreparedLevel& level) {
  LevelVoxels voxels;
  voxels.depth = level.depth;
  voxels.keys.reserve(level.leaves.size());
  if (!level.nodes.empty()) {
    const std::uint8_t* node = level.nodes.data();
    decodeNode(node, 0, level.depth, 0, voxels.keys);
  }
  assert(voxels.keys.size() == level.leaves.size());
  voxels.colours = level.leaves;
  return voxels;
}

PreparedLevel encodeLevel(const LevelVoxels& voxels) {
  PreparedLevel level;
  level.depth = voxels.depth;
  level.nodes = encodeOctree(voxels.keys, voxels.depth);
  level.leaves = voxels.colours;
  return level;
}

LevelVoxels coarsen(const LevelVoxels& voxels, int depth, std::span<const Rgb8> palette) {
  assert(depth >= 1 && depth < voxels.depth);
  const int shift = 3 * (voxels.depth - depth);
  LevelVoxels coarse;
  coarse.depth = depth;
  for (std::size_t begin = 0; begin < voxels.keys.size();) {
    const std::uint64_t cell = voxels.keys[begin] >> shift;
    std::array<std::uint64_t, 3> sum{};
    std::size_t end = begin;
    for (; end < voxels.keys.size() && voxels.keys[end] >> shift == cell; ++end) {
      for (std::size_t ch = 0; ch < 3; ++ch) sum[ch] += palette[voxels.colours[end]][ch];
    }
    coarse.keys.push_back(cell);
    coarse.colours.push_back(nearestPaletteIndex(sum, end - begin, palette));
    begin = end;
  }
  return coarse;
}

std::size_t nestLevels(PreparedModel& model) {
  std::size_t added = 0;
  for (std::size_t j = model.levels.size() - 1; j > 0; --j) {
    LevelVoxels coarse = decodeLevel(model.levels[j - 1]);
    const LevelVoxels parents = coarsen(decodeLevel(model.levels[j]), coarse.depth, model.palette);
    LevelVoxels merged;
    merged.depth = coarse.depth;
    std::size_t a = 0, b = 0;
    while (a < coarse.keys.size() || b < parents.keys.size()) {
      const bool take_coarse =
          b == parents.keys.size() || (a < coarse.keys.size() && coarse.keys[a] <= parents.keys[b]);
      if (take_coarse) {
        if (b < parents.keys.size() && coarse.keys[a] == parents.keys[b]) ++b;  // already there
        merged.keys.push_back(coarse.keys[a]);
        merged.colours.push_back(coarse.colours[a++]);
      } else {
        merged.keys.push_back(parents.keys[b]);
        merged.colours.push_back(parents.colours[b++]);
        ++added;
      }
    }
    if (merged.keys.size() != coarse.keys.size()) {
      PreparedLevel& level = model.levels[j - 1];
      PreparedLevel rebuilt = encodeLevel(merged);
      level.nodes = std::move(rebuilt.nodes);
      level.leaves = std::move(rebuilt.leaves);
    }
  }
  return added;
}

}  // namespace octopoint::prepare
