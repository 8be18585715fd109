#pragma once
// Surface normals of a scan's points, the first step of `octopoint-prepare --normals`: estimated
// with PCL, oriented toward the sensor, then sharpened at edges. The voxelizer averages them per
// voxel and codegen/normal_palette.h quantizes the averages. A step of its own on the loaded
// points, so that how a scan is read (and whether it fits in memory) stays another file's business.
//
// - Organized scans (a sensor grid, Scan::grid_width x grid_height) use PCL's integral-image
//   estimation over the grid: covariance of a window of `smoothing_pixels`, smaller where depth
//   changes fast (depth-dependent smoothing), none across depth jumps (max_depth_change). It needs
//   the scan in its sensor's axes (z away from the sensor), so it runs before the axes are turned.
// - Points it leaves without a normal, and every point of an unorganized scan, get a k-nearest-
//   neighbour PCA normal (the smallest eigenvector of the neighbours' covariance, PCL's
//   NormalEstimation over its FLANN k-d tree).
// - Both average across an edge: a point within the neighbourhood's reach of a crease gets a
//   normal between its two faces, and the crease blurs over several voxels. So every normal is then
//   replaced by the one of the flattest neighbourhood among the point's nearest neighbours whose
//   plane passes within one voxel of the point ("shifted neighbourhoods"): on a face, that is a
//   neighbourhood lying wholly in the face, and creases stay one voxel sharp.
// Normals are oriented toward Scan::sensor_origin (n . (sensor - p) >= 0).
//
// Only this file and the loaders include PCL headers (they compile slowly).

#include <array>
#include <string>
#include <vector>

#include "codegen/scan_loader.h"

namespace octopoint::prepare {

struct NormalOptions {
  // k of the k-NN PCA; 0 chooses it from the density: the points within kNeighbourRadiusVoxels.
  int neighbours = 0;
  // Integral images: the covariance window's half size in grid pixels; 0 chooses kSmoothingVoxels
  // voxel edges of the finest depth, in pixels where the surfaces are.
  float smoothing_pixels = 0;
  float max_depth_change = 0.02f;  // integral images: a depth step of more than this x depth
  bool sharpen = true;             // the shifted-neighbourhood step (off: measurements only)
  // Threads of the k-NN PCA (PCL's OpenMP estimator): octopoint-prepare --threads, at most one
  // per core (libgomp ends the process when it cannot start one); 0: one per core.
  unsigned threads = 0;
};

// Measured on synthetic spheres and planes with half a voxel of noise (docs/styles.md): a
// neighbourhood of 4.5 voxel edges keeps the mean error under 5 degrees.
inline constexpr double kNeighbourRadiusVoxels = 4.5;
inline constexpr int kMinPcaNeighbours = 12;
inline constexpr int kMaxPcaNeighbours = 256;
inline constexpr double kSmoothingVoxels = 8.0;
inline constexpr double kMinSmoothingPixels = 4.0;
inline constexpr double kMaxSmoothingPixels = 40.0;

// k for k-NN PCA on a surface with `points_per_voxel` points per occupied voxel: the points
// within kNeighbourRadiusVoxels, clamped to kMinPcaNeighbours..kMaxPcaNeighbours.
int neighboursForDensity(double points_per_voxel);

// One unit normal per position of `scan` (oriented toward its sensor), NaN where no neighbourhood
// could give one (fewer than three distinct points). `voxel_edge` (scan units): the finest voxel,
// the sharpening step's tolerance. Throws PrepareError naming `scan_path` when the scan has fewer
// than 3 points.
std::vector<std::array<float, 3>> estimateNormals(const Scan& scan, double voxel_edge,
                                                  const NormalOptions& options,
                                                  const std::string& scan_path);

}  // namespace octopoint::prepare
