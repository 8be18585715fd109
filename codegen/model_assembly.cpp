#include "codegen/model_assembly.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "codegen/depth_range.h"
#include "codegen/huge_pages.h"
#include "codegen/octree_encoder.h"
#include "codegen/palette.h"
#include "codegen/parallel.h"
#include "codegen/prepare_error.h"
#include "codegen/visibility.h"

namespace octopoint::prepare {
namespace {

// Above this many leaves the palette's direct lookup table (18 MB) pays for itself.
constexpr std::size_t kLookupTableLeaves = std::size_t{1} << 20;

Rgb8 unpack(std::uint32_t c) {
  return {static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 8),
          static_cast<std::uint8_t>(c)};
}

// Keeps the voxels no camera of the scene can see out of `level` (nodes and leaves).
void prune(PreparedLevel& level, const std::vector<Camera>& cameras, const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  level.voxels_before_pruning = level.leaves.size();
  level.bytes_before_pruning = level.nodes.size() + level.leaves.size();
  const std::vector<std::uint64_t> keys = decodeLeafKeys(level.nodes, level.depth);
  const std::vector<std::uint8_t> visible = visibleVoxels(keys, level.depth, cameras);
  std::vector<std::uint64_t> kept_keys;
  std::vector<std::uint8_t> kept_leaves;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (!visible[i]) continue;
    kept_keys.push_back(keys[i]);
    kept_leaves.push_back(level.leaves[i]);
  }
  if (kept_keys.empty()) {
    throw PrepareError(path + ": no voxel at depth " + std::to_string(level.depth) +
                       " is visible from the scene's views");
  }
  level.nodes = encodeOctree(kept_keys, level.depth);
  level.leaves = std::move(kept_leaves);
  level.pruning_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PreparedModel assembleModel(std::vector<EncodedLevel> levels, const CubeFit& fit,
                            const PrepareOptions& options, const std::string& path,
                            unsigned threads) {
  // Depths finer than the scan samples densely are left out when asked (codegen/depth_range.h).
  std::vector<int> sparse_depths;
  if (options.stop_at_sparse_depth) {
    std::vector<std::size_t> counts;
    for (const EncodedLevel& level : levels) counts.push_back(level.leaves);
    const std::size_t dense = denseDepthCount(counts);
    for (std::size_t i = dense; i < levels.size(); ++i) sparse_depths.push_back(levels[i].depth);
    levels.resize(dense);
  }
  // The palette comes from all voxels, before pruning: pruning then changes no voxel's colour
  // index, so pruned and unpruned models draw the same pixels at every sampled view.
  const Palette palette =
      Palette::buildFromPieces(levels.back().colours, options.palette_colours, threads);
  std::size_t leaves = 0;
  for (const EncodedLevel& level : levels) leaves += level.leaves;
  std::optional<Palette::Lookup> lookup;
  if (leaves > kLookupTableLeaves) lookup.emplace(palette);
  PreparedModel model;
  model.name = options.name;
  model.source_description = options.source_description;
  model.cube_edge_pm = cubeEdgePicometres(fit, options.metres_per_scan_unit, path);
  model.cube = cubePlacement(fit, options.axes == ScanAxes::kYUp);
  model.palette = palette.colours();
  model.sparse_depths_dropped = sparse_depths;
  for (EncodedLevel& encoded : levels) {
    PreparedLevel level;
    level.depth = encoded.depth;
    level.nodes = std::move(encoded.nodes);
    level.leaves.reserve(encoded.leaves);
    adviseHugePages(level.leaves.data(), encoded.leaves);
    level.leaves.resize(encoded.leaves);
    // A palette index per leaf, the pieces spread over the threads.
    std::vector<std::size_t> starts = {0};
    for (const auto& piece : encoded.colours) starts.push_back(starts.back() + piece.size());
    parallelFor(threads, encoded.colours.size(), [&](std::size_t p, unsigned) {
      std::uint8_t* out = level.leaves.data() + starts[p];
      for (std::uint32_t colour : encoded.colours[p]) {
        *out++ = lookup ? lookup->indexOf(unpack(colour)) : palette.indexOf(unpack(colour));
      }
    });
    encoded.colours = {};
    if (!options.visibility_cameras.empty()) prune(level, options.visibility_cameras, path);
    model.levels.push_back(std::move(level));
  }
  return model;
}

}  // namespace octopoint::prepare
