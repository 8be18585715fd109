#include "codegen/model_assembly.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "codegen/depth_range.h"
#include "codegen/huge_pages.h"
#include "codegen/octree_encoder.h"
#include "codegen/palette.h"
#include "codegen/parallel.h"
#include "codegen/prepare_error.h"

namespace octopoint::prepare {
namespace {

// Above this many leaves the palette's direct lookup table (18 MB) pays for itself.
constexpr std::size_t kLookupTableLeaves = std::size_t{1} << 20;

Rgb8 unpack(std::uint32_t c) {
  return {static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 8),
          static_cast<std::uint8_t>(c)};
}

}  // namespace

PreparedModel assembleModel(std::vector<EncodedLevel> levels, const CubeFit& fit,
                            const PrepareOptions& options, const std::string& path,
                            unsigned threads) {
  // Depths finer than the scan samples, which their sample reach does not draw whole, are left
  // out when asked (codegen/depth_range.h, drawableDepthCount).
  std::vector<int> sparse_depths;
  std::vector<std::int32_t> reaches;  // measured by the cut, when it ran
  if (options.stop_at_sparse_depth) {
    std::vector<int> depths;
    std::vector<std::size_t> counts;
    for (const EncodedLevel& level : levels) {
      depths.push_back(level.depth);
      counts.push_back(level.leaves);
    }
    const std::size_t dense = drawableDepthCount(
        depths, counts,
        [&](std::size_t i) { return decodeLeafKeys(levels[i].nodes, levels[i].depth); }, &reaches);
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
  model.sample_reaches_measured = !reaches.empty();
  for (EncodedLevel& encoded : levels) {
    PreparedLevel level;
    level.depth = encoded.depth;
    if (!reaches.empty())
      level.sample_reach = static_cast<std::uint8_t>(reaches[model.levels.size()]);
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
    model.levels.push_back(std::move(level));
  }
  return model;
}

}  // namespace octopoint::prepare
