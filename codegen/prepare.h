#pragma once
// The preparer's pipeline, from a loaded scan to a model: fit the cube, voxelize at every requested
// depth, build one palette from the finest depth's voxel colours, encode each depth's stream.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "codegen/normal_estimation.h"
#include "codegen/normal_palette.h"
#include "codegen/prepared_model.h"
#include "codegen/scan_loader.h"
#include "octopoint/camera.h"
#include "tools/scan_eye.h"

namespace octopoint::prepare {

// An axis-aligned box in scan units; points outside it are dropped before fitting the cube, which
// removes the far-away junk and the background a range scan sees around its subject.
// The corners are kept as given: scans of float coordinates (PCD, PLY) are compared with the box
// rounded to float, as they always were; LAS coordinates, doubles of any size (UTM northings reach
// 10^7), with the box itself.
struct CropBox {
  std::array<double, 3> low{};
  std::array<double, 3> high{};
};
// The largest |corner| a crop box may have: past any LAS coordinate (codegen/las_reader.h).
inline constexpr double kMaxCropCoordinate = 1e13;

// How the scan's axes are laid out. The model is always stored in the sensor frame: x right, y
// down, z away from the sensor (what PCL's OpenNI grabber and OpenCV use), so that the identity
// camera shows the scan as it was taken.
enum class ScanAxes {
  kYDown,  // x right, y down, z away from the viewer: kept as it is
  kYUp,    // x right, y up, z toward the viewer (OpenGL): turned 180 degrees about x
};

// Statistical outlier removal: a point is dropped when the mean distance to its k nearest
// neighbours exceeds the mean of that distance over all points plus `stddev_factor` standard
// deviations of it (the rule of PCL's StatisticalOutlierRemoval).
struct OutlierRemoval {
  int neighbours = 8;
  double stddev_factor = 2.0;
};

// A perspective view an app will show (a scene's "eyes" and "paths", docs/scene.md): an eye in the
// scan's own units and axes (octopoint-render --eye's frame) and a look, with the vertical field
// of view; angles as octopoint-render's --look and --fov round them.
struct SceneEye {
  ScanPoint eye{};
  Look look;
  Angle fov = Angle::fromDegrees(60);
};

struct PrepareOptions {
  std::string name;                  // the model's C++ identifier
  std::string source_description;    // for the generated comments
  std::vector<int> depths = {7, 8};  // strictly ascending, each 1..format::kMaxDepth
  // Keep only the depths the scan samples densely (codegen/depth_range.h): octopoint-prepare's
  // default range and a scene's "depths": "auto" set it; an explicit list does not.
  bool stop_at_sparse_depth = false;
  double metres_per_scan_unit = 1.0;  // to record the cube's metric size
  int palette_colours = 256;
  std::optional<CropBox> crop;  // in the scan's own axes, before they are turned
  ScanAxes axes = ScanAxes::kYDown;
  std::optional<OutlierRemoval> outliers;  // after cropping
  bool greyscale = false;                  // palette of greys (luma) instead of colours
  // Normals (octopoint-prepare --normals): estimated per point, averaged per voxel, stored per leaf
  // as an index into a normal palette of `normal_palette_entries` (docs/styles.md).
  std::optional<NormalOptions> normals;
  NormalPaletteKind normal_palette = NormalPaletteKind::kAdaptive;
  int normal_palette_entries = kNormalPaletteEntries;
  // Visibility pruning: when not empty, a voxel is kept only if it wins the z-test at some pixel
  // for at least one of these cameras (codegen/visibility.h). Each camera's size is its frame's.
  std::vector<Camera> visibility_cameras;
  // And these perspective views, on frames of eye_width x eye_height, each drawn as
  // octopoint-render --eye draws it: with detail by distance over the model's stored depths and
  // the model's near plane (codegen/eye_visibility.h). A voxel either kind of view sees is kept.
  std::vector<SceneEye> visibility_eyes;
  int eye_width = 320;
  int eye_height = 240;
};

// The points of `scan` inside `box` (inclusive), with their colours. Throws PrepareError naming
// `scan_path` when none is left.
Scan cropScan(const Scan& scan, const CropBox& box, const std::string& scan_path);

// Parses "X0,Y0,Z0,X1,Y1,Z1" (scan units); throws PrepareError naming `flag` when it is not six
// numbers or the box is empty.
CropBox parseCropBox(const std::string& flag, const std::string& text);

// The points a model is made of: the scan cropped, cleaned of outliers and turned into the model's
// axes, as `options` asks. prepareModel voxelizes exactly these; a reference render draws them.
Scan modelPoints(const Scan& scan, const std::string& scan_path, const PrepareOptions& options);
// Its two steps: cropping and outlier removal, in the scan's own axes; then turning the axes
// (positions, normals and the sensor alike). Normals are estimated between the two.
Scan cleanScan(const Scan& scan, const std::string& scan_path, const PrepareOptions& options);
void turnAxes(Scan& scan, ScanAxes axes);

// Throws PrepareError (naming `scan_path`) when the scan cannot be made into a model. The scan is
// in memory already, so it is prepared in memory (codegen/streamed_prepare.h, with a budget that
// holds it all) on `threads` threads (0: every core); the output does not depend on their number.
// With normals (options.normals) it runs the whole-scan pipeline normal estimation was written on;
// its k-NN PCA takes `threads` too, at most one per core (NormalOptions::threads).
PreparedModel prepareModel(const Scan& scan, const std::string& scan_path,
                           const PrepareOptions& options, unsigned threads = 0);

}  // namespace octopoint::prepare
