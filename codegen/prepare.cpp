#include "codegen/prepare.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "cli/real_numbers.h"
#include "cli/text.h"
#include "codegen/cube_fit.h"
#include "codegen/depth_range.h"
#include "codegen/octree_encoder.h"
#include "codegen/outlier_filter.h"
#include "codegen/palette.h"
#include "codegen/point_source.h"
#include "codegen/prepare_error.h"
#include "codegen/progress.h"
#include "codegen/sample_reach.h"
#include "codegen/scene_pruning.h"
#include "codegen/streamed_prepare.h"
#include "codegen/voxelizer.h"

namespace octopoint::prepare {

Scan cropScan(const Scan& scan, const CropBox& box, const std::string& scan_path) {
  std::vector<std::uint8_t> inside(scan.positions.size());
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    const auto& p = scan.positions[i];
    bool in = true;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      in = in && p[axis] >= static_cast<float>(box.low[axis]) &&
           p[axis] <= static_cast<float>(box.high[axis]);
    }
    inside[i] = in;
  }
  Scan cropped = keepPoints(scan, inside);
  if (cropped.positions.empty()) {
    throw PrepareError(scan_path + ": no point of the " + std::to_string(scan.positions.size()) +
                       " points lies inside the crop box");
  }
  return cropped;
}

Scan cleanScan(const Scan& full_scan, const std::string& scan_path, const PrepareOptions& options) {
  if (full_scan.positions.empty())
    throw PrepareError(scan_path + ": the scan has no usable points");
  Scan scan = options.crop ? cropScan(full_scan, *options.crop, scan_path) : full_scan;
  if (options.outliers) scan = removeOutliers(scan, *options.outliers, scan_path);
  return scan;
}

void turnAxes(Scan& scan, ScanAxes axes) {
  if (axes != ScanAxes::kYUp) return;
  // A rotation about x (no mirror image), of positions, normals and the sensor alike.
  const auto turn = [](std::array<float, 3>& p) { p = {p[0], -p[1], -p[2]}; };
  for (auto& p : scan.positions) turn(p);
  for (auto& n : scan.normals) turn(n);
  turn(scan.sensor_origin);
}

Scan modelPoints(const Scan& full_scan, const std::string& scan_path,
                 const PrepareOptions& options) {
  Scan scan = cleanScan(full_scan, scan_path, options);
  turnAxes(scan, options.axes);
  return scan;
}

namespace {

// Rec. 601 luma in 8.8 fixed point (77 + 150 + 29 = 256).
Rgb8 toGrey(const Rgb8& c) {
  const auto grey = static_cast<std::uint8_t>((77 * c[0] + 150 * c[1] + 29 * c[2] + 128) >> 8);
  return {grey, grey, grey};
}

// Estimates the scan's normals, in the scan's own axes (integral images need the sensor's);
// turning them moves no extent, so this fit's edge is the model's. Returns the neighbours used.
int estimateScanNormals(Scan& scan, const std::string& scan_path, const PrepareOptions& options,
                        unsigned threads) {
  const CubeFit scan_fit = fitCube(scan.positions, scan_path);
  // The finest depth the model will keep (the same cut as voxelizeDepths', on the same voxels:
  // turning the scan mirrors them, which changes neither a count nor a reach).
  std::vector<std::vector<std::uint64_t>> keys;
  std::vector<std::size_t> counts;
  for (int depth : options.depths) {
    keys.push_back(occupiedVoxelKeys(scan, scan_fit, depth));
    counts.push_back(keys.back().size());
  }
  const std::size_t kept =
      options.stop_at_sparse_depth
          ? drawableDepthCount(options.depths, counts,
                               [&](std::size_t i) { return std::move(keys[i]); })
          : counts.size();
  keys = {};
  const int finest = options.depths[kept - 1];
  NormalOptions normal_options = *options.normals;
  normal_options.threads = threads;
  if (normal_options.neighbours == 0) {
    const auto voxels = static_cast<double>(counts[kept - 1]);
    normal_options.neighbours =
        neighboursForDensity(static_cast<double>(scan.positions.size()) / voxels);
  }
  scan.normals =
      estimateNormals(scan, scan_fit.edge / std::ldexp(1.0, finest), normal_options, scan_path);
  return normal_options.neighbours;
}

// The scan voxelized at each depth; the depths the default cut leaves out (drawableDepthCount:
// finer than the scan samples, and not drawn whole by their sample reach) left out (into
// `sparse_depths`, the kept depths' reaches the cut measured into `cut_reaches`) when the options
// say so; grey when they say so.
std::vector<VoxelSet> voxelizeDepths(const Scan& scan, const CubeFit& fit,
                                     const PrepareOptions& options, std::vector<int>& sparse_depths,
                                     std::vector<std::int32_t>& cut_reaches) {
  std::vector<VoxelSet> voxel_sets;
  Progress progress("voxelizing", options.depths.size());
  for (int depth : options.depths) {
    voxel_sets.push_back(voxelize(scan, fit, depth));
    progress.update(voxel_sets.size());
  }
  if (options.stop_at_sparse_depth) {
    std::vector<std::size_t> counts;
    for (const VoxelSet& voxels : voxel_sets) counts.push_back(voxels.keys.size());
    const std::size_t dense = drawableDepthCount(
        options.depths, counts, [&](std::size_t i) { return voxel_sets[i].keys; }, &cut_reaches);
    for (std::size_t i = dense; i < voxel_sets.size(); ++i)
      sparse_depths.push_back(voxel_sets[i].depth);
    voxel_sets.resize(dense);
  }
  if (options.greyscale) {
    for (VoxelSet& voxels : voxel_sets) {
      for (Rgb8& colour : voxels.colours) colour = toGrey(colour);
    }
  }
  return voxel_sets;
}

// The palette of the finest depth's normals, recorded in `model` with its errors.
NormalPalette buildNormalPalette(const std::vector<Normal3f>& finest_normals,
                                 const PrepareOptions& options, PreparedModel& model) {
  NormalPalette normal_palette =
      NormalPalette::build(finest_normals, options.normal_palette, options.normal_palette_entries);
  model.normal_palette = normal_palette.entries();
  double error_sum = 0;
  for (const Normal3f& n : finest_normals) {
    const double error = normal_palette.errorDegrees(n);
    error_sum += error;
    model.normal_error_max_deg = std::max(model.normal_error_max_deg, error);
  }
  model.normal_error_mean_deg = error_sum / static_cast<double>(finest_normals.size());
  return normal_palette;
}

// One depth as stored: its voxels encoded with their palette indices (pruned later,
// codegen/scene_pruning.h).
PreparedLevel storedLevel(const VoxelSet& voxels, const Palette& palette,
                          const std::optional<NormalPalette>& normal_palette) {
  PreparedLevel level;
  level.depth = voxels.depth;
  level.nodes = encodeOctree(voxels.keys, voxels.depth);
  level.leaves.reserve(voxels.colours.size());
  for (const Rgb8& colour : voxels.colours) level.leaves.push_back(palette.indexOf(colour));
  if (normal_palette) {
    level.normals.reserve(voxels.normals.size());
    for (const Normal3f& normal : voxels.normals)
      level.normals.push_back(normal_palette->indexOf(normal));
  }
  return level;
}

// The whole-scan pipeline, kept for models with normals: estimating a point's normal needs its
// neighbours, which the streamed preparer's bins do not keep together.
PreparedModel prepareWithNormals(const Scan& full_scan, const std::string& scan_path,
                                 const PrepareOptions& options, unsigned threads) {
  Scan scan = cleanScan(full_scan, scan_path, options);
  const auto normals_start = std::chrono::steady_clock::now();
  const int normal_neighbours =
      options.normals ? estimateScanNormals(scan, scan_path, options, threads) : 0;
  turnAxes(scan, options.axes);
  const CubeFit fit = fitCube(scan.positions, scan_path);
  std::vector<int> sparse_depths;
  std::vector<std::int32_t> cut_reaches;
  std::vector<VoxelSet> voxel_sets = voxelizeDepths(scan, fit, options, sparse_depths, cut_reaches);
  // The palette comes from all voxels, before pruning: pruning then changes no voxel's colour
  // index, so pruned and unpruned models draw the same pixels at every sampled view.
  const Palette palette = Palette::build(voxel_sets.back().colours, options.palette_colours);

  PreparedModel model;
  model.name = options.name;
  model.source_description = options.source_description;
  model.cube_edge_pm = cubeEdgePicometres(fit, options.metres_per_scan_unit, scan_path);
  model.cube = cubePlacement(fit, options.axes == ScanAxes::kYUp);
  model.palette = palette.colours();
  model.sparse_depths_dropped = sparse_depths;
  model.synthetic_colour = scan.shading == ScanShading::kNone && !options.greyscale;
  std::optional<NormalPalette> normal_palette;
  if (options.normals) {
    normal_palette = buildNormalPalette(voxel_sets.back().normals, options, model);
    model.normal_neighbours = normal_neighbours;
    model.normals_from_integral_images = scan.grid_width > 0;
    model.normal_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - normals_start).count();
  }
  for (VoxelSet& voxels : voxel_sets) {
    model.levels.push_back(storedLevel(voxels, palette, normal_palette));
    if (!cut_reaches.empty())
      model.levels.back().sample_reach =
          static_cast<std::uint8_t>(cut_reaches[model.levels.size() - 1]);
  }
  model.sample_reaches_measured = !cut_reaches.empty();
  pruneModel(model, options, scan_path);
  recordSampleReaches(model);
  return model;
}

}  // namespace

PreparedModel prepareModel(const Scan& full_scan, const std::string& scan_path,
                           const PrepareOptions& options, unsigned threads) {
  if (options.normals) return prepareWithNormals(full_scan, scan_path, options, threads);
  const Scan scan = modelPoints(full_scan, scan_path, options);
  PrepareOptions streamed = options;  // the points are cropped, cleaned and turned already
  // Pruned below, once the cube's placement is the scan's (the eyes are in the scan's axes).
  streamed.visibility_cameras.clear();
  streamed.visibility_eyes.clear();
  streamed.crop.reset();
  streamed.outliers.reset();
  streamed.axes = ScanAxes::kYDown;
  StreamOptions stream;
  stream.threads = threads;
  stream.memory_bytes = std::max<std::uint64_t>(kDefaultMemoryBytes, 64 * scan.positions.size());
  PreparedModel model = prepareFromSource(*memorySource(scan), scan_path, streamed, stream);
  // The points were turned before the streamed preparer saw them: the placement it recorded is in
  // the model's axes, the scan's are the ones asked for.
  if (options.axes == ScanAxes::kYUp) {
    CubeFit fit;
    for (std::size_t axis = 0; axis < 3; ++axis)
      fit.origin[axis] = std::bit_cast<double>(model.cube.corner_bits[axis]);
    fit.edge = std::bit_cast<double>(model.cube.edge_bits);
    model.cube = cubePlacement(fit, true);
  }
  // Pruning, when asked for, changes the levels the streamed preparer measured.
  if (!options.visibility_cameras.empty() || !options.visibility_eyes.empty()) {
    pruneModel(model, options, scan_path);
    recordSampleReaches(model);
  }
  return model;
}

}  // namespace octopoint::prepare
