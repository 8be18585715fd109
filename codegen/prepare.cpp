#include "codegen/prepare.h"

#include <cmath>
#include <limits>

#include "codegen/cube_fit.h"
#include "codegen/octree_encoder.h"
#include "codegen/palette.h"
#include "codegen/prepare_error.h"
#include "codegen/voxelizer.h"

namespace octopoint::prepare {

Scan cropScan(const Scan& scan, const CropBox& box, const std::string& scan_path) {
  Scan cropped;
  cropped.shading = scan.shading;
  cropped.points_in_file = scan.points_in_file;
  cropped.dropped_non_finite = scan.dropped_non_finite;
  cropped.organized = scan.organized;
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    const auto& p = scan.positions[i];
    bool inside = true;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      inside = inside && p[axis] >= box.low[axis] && p[axis] <= box.high[axis];
    }
    if (!inside) continue;
    cropped.positions.push_back(p);
    if (!scan.colours.empty()) cropped.colours.push_back(scan.colours[i]);
  }
  if (cropped.positions.empty()) {
    throw PrepareError(scan_path + ": no point of the " + std::to_string(scan.positions.size()) +
                       " points lies inside the crop box");
  }
  return cropped;
}

PreparedModel prepareModel(const Scan& full_scan, const std::string& scan_path, const PrepareOptions& options) {
  if (full_scan.positions.empty()) throw PrepareError(scan_path + ": the scan has no usable points");
  Scan scan = options.crop ? cropScan(full_scan, *options.crop, scan_path) : full_scan;
  if (options.axes == ScanAxes::kYUp) {
    for (auto& p : scan.positions) p = {p[0], -p[1], -p[2]};  // a rotation: no mirror image
  }
  const CubeFit fit = fitCube(scan.positions, scan_path);

  std::vector<VoxelSet> voxel_sets;
  for (int depth : options.depths) voxel_sets.push_back(voxelize(scan, fit, depth));
  const Palette palette = Palette::build(voxel_sets.back().colours, options.palette_colours);

  PreparedModel model;
  model.name = options.name;
  model.source_description = options.source_description;
  const double edge_um = fit.edge * options.metres_per_scan_unit * 1e6;
  model.cube_edge_um = static_cast<std::uint32_t>(
      std::min(std::round(edge_um), double{std::numeric_limits<std::uint32_t>::max()}));
  model.palette = palette.colours();
  for (const VoxelSet& voxels : voxel_sets) {
    PreparedLevel level;
    level.depth = voxels.depth;
    level.nodes = encodeOctree(voxels.keys, voxels.depth);
    level.leaves.reserve(voxels.colours.size());
    for (const Rgb8& colour : voxels.colours) level.leaves.push_back(palette.indexOf(colour));
    model.levels.push_back(std::move(level));
  }
  return model;
}

}  // namespace octopoint::prepare
