// Surface normals with PCL (codegen/normal_estimation.h says what and why). PCL headers compile
// slowly: this file, scan_loader.cpp and outlier_filter.cpp are the only ones that include them.
#include "codegen/normal_estimation.h"

#include <pcl/features/integral_image_normal.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <thread>

#include "codegen/prepare_error.h"
#include "codegen/progress.h"

namespace octopoint::prepare {
namespace {

using Vec3f = std::array<float, 3>;
constexpr double kPi = 3.14159265358979323846;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kLeastWindowShare = 0.75f;

// A point's normal and the curvature of the neighbourhood it came from (PCL's surface variation:
// smallest eigenvalue over the sum, 0 for a plane, 1/3 for an isotropic blob); NaN when unknown.
struct Estimate {
  Vec3f normal{kNaN, kNaN, kNaN};
  float curvature = kNaN;
  std::size_t anchor = 0;  // the point whose neighbourhood gave the normal (sharpening moves it)
};

bool known(const Estimate& e) { return std::isfinite(e.normal[0]) && std::isfinite(e.curvature); }

Estimate fromPcl(const pcl::Normal& n, std::size_t point) {
  Estimate e;
  e.anchor = point;
  if (std::isfinite(n.normal_x) && std::isfinite(n.normal_y) && std::isfinite(n.normal_z) &&
      std::isfinite(n.curvature)) {
    e.normal = {n.normal_x, n.normal_y, n.normal_z};
    e.curvature = n.curvature;
  }
  return e;
}

float dot(const Vec3f& a, const Vec3f& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3f minus(const Vec3f& a, const Vec3f& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// The spacing of an organized scan's grid: the median distance between horizontally neighbouring
// points, in scan units (what a pixel spans where the surfaces are).
double gridSpacing(const Scan& scan) {
  std::vector<double> distances;
  for (std::size_t i = 1; i < scan.positions.size(); ++i) {
    if (scan.grid_index[i] != scan.grid_index[i - 1] + 1 ||
        scan.grid_index[i] % scan.grid_width == 0)
      continue;
    const Vec3f d = minus(scan.positions[i], scan.positions[i - 1]);
    distances.push_back(std::sqrt(static_cast<double>(dot(d, d))));
  }
  if (distances.empty()) return 0;
  const auto middle = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
  std::nth_element(distances.begin(), middle, distances.end());
  return *middle;
}

// How far (in grid pixels, 8-neighbour chamfer steps) each grid cell lies from the nearest cell
// without a point or across a depth step of more than `max_depth_change` x depth: where PCL's
// integral images shrink their window (its depth-dependent smoothing stops at such edges).
std::vector<float> distanceToEdges(const Scan& scan, float max_depth_change) {
  const std::size_t width = scan.grid_width, height = scan.grid_height;
  constexpr float kFar = 1e9f;
  std::vector<float> z(width * height, kNaN);
  for (std::size_t i = 0; i < scan.positions.size(); ++i)
    z[scan.grid_index[i]] = scan.positions[i][2];
  std::vector<float> distance(width * height, kFar);
  const auto step = [&](std::size_t a, std::size_t b) {  // is a-b an edge?
    return !std::isfinite(z[b]) || std::fabs(z[a] - z[b]) > max_depth_change * std::fabs(z[a]);
  };
  for (std::size_t y = 0; y < height; ++y) {
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t at = y * width + x;
      if (!std::isfinite(z[at])) {
        distance[at] = 0;
      } else if (x == 0 || y == 0 || x + 1 == width || y + 1 == height || step(at, at - 1) ||
                 step(at, at + 1) || step(at, at - width) || step(at, at + width)) {
        distance[at] = 1;
      }
    }
  }
  // Two chamfer passes over the inner cells (the outer ones are at distance 0 or 1 already).
  constexpr float kDiagonal = 1.4142136f;
  const auto w = static_cast<std::ptrdiff_t>(width), h = static_cast<std::ptrdiff_t>(height);
  const auto at = [&](std::ptrdiff_t x, std::ptrdiff_t y) -> float& {
    return distance[static_cast<std::size_t>(y * w + x)];
  };
  for (std::ptrdiff_t y = 1; y + 1 < h; ++y) {
    for (std::ptrdiff_t x = 1; x + 1 < w; ++x) {
      at(x, y) = std::min({at(x, y), at(x - 1, y) + 1, at(x, y - 1) + 1,
                           at(x - 1, y - 1) + kDiagonal, at(x + 1, y - 1) + kDiagonal});
    }
  }
  for (std::ptrdiff_t y = h - 2; y >= 1; --y) {
    for (std::ptrdiff_t x = w - 2; x >= 1; --x) {
      at(x, y) = std::min({at(x, y), at(x + 1, y) + 1, at(x, y + 1) + 1,
                           at(x + 1, y + 1) + kDiagonal, at(x - 1, y + 1) + kDiagonal});
    }
  }
  return distance;
}

// PCL's integral images trust their input's shape: they skip a border of int(smoothing) cells
// with unsigned loops that run wild on a grid narrower than twice that (1xN, 3x3), and read a
// window of up to smoothing + depth / 10 cells around a point, unchecked, so that a scan in
// millimetres (depth 1000: 100 more cells) reads far outside the grid. Where either could happen
// the grid gets a margin of NaN cells: PCL ends its windows at depth gaps, so no window then
// reaches past the margin, and its loops have room. Otherwise none, and the estimates are the ones
// PCL gives on the bare grid.
std::size_t integralImageMargin(const Scan& scan, float smoothing) {
  const auto border = static_cast<std::size_t>(smoothing);
  float deepest = 0;
  for (const Vec3f& p : scan.positions) deepest = std::max(deepest, p[2]);
  const double widest_window = std::floor(static_cast<double>(smoothing) + deepest / 10.0);
  const bool fits = scan.grid_width > 2 * border && scan.grid_height > 2 * border &&
                    (widest_window + 1) / 2 <= static_cast<double>(border);
  return fits ? 0 : border + 1;
}

// The scan's sensor grid as PCL takes it, `margin` NaN cells wide on every side; sets `cell[i]`
// (one per point) to where point i lies in it.
pcl::PointCloud<pcl::PointXYZ>::Ptr paddedGrid(const Scan& scan, std::size_t margin,
                                               std::vector<std::size_t>& cell) {
  const std::size_t width = scan.grid_width + 2 * margin;
  const std::size_t height = scan.grid_height + 2 * margin;
  auto grid = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(static_cast<std::uint32_t>(width),
                                                               static_cast<std::uint32_t>(height),
                                                               pcl::PointXYZ(kNaN, kNaN, kNaN));
  grid->is_dense = false;
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    const std::size_t x = scan.grid_index[i] % scan.grid_width;
    const std::size_t y = scan.grid_index[i] / scan.grid_width;
    cell[i] = (y + margin) * width + x + margin;
    const Vec3f& p = scan.positions[i];
    (*grid)[cell[i]] = pcl::PointXYZ(p[0], p[1], p[2]);
  }
  return grid;
}

// Integral images over the sensor grid. Points whose window was cut to less than
// kLeastWindowShare of its size by an edge nearby, or held too little, get no estimate (k-NN PCA
// then gives them one).
std::vector<Estimate> integralImageEstimates(const Scan& scan, double voxel_edge,
                                             const NormalOptions& options) {
  float smoothing = options.smoothing_pixels;
  if (smoothing <= 0) {  // kSmoothingVoxels voxel edges, in grid pixels
    const double spacing = gridSpacing(scan);
    smoothing = spacing > 0
                    ? static_cast<float>(std::clamp(kSmoothingVoxels * voxel_edge / spacing,
                                                    kMinSmoothingPixels, kMaxSmoothingPixels))
                    : kMinSmoothingPixels;
  }
  const std::vector<float> edge_distance = distanceToEdges(scan, options.max_depth_change);
  std::vector<Estimate> estimates(scan.positions.size());
  const auto kept = [&](std::size_t i) {
    return edge_distance[scan.grid_index[i]] >= kLeastWindowShare * smoothing;
  };
  bool any_kept = false;
  for (std::size_t i = 0; i < scan.positions.size() && !any_kept; ++i) any_kept = kept(i);
  if (!any_kept) return estimates;  // a grid too narrow for the window: k-NN PCA for every point

  std::vector<std::size_t> cell(scan.positions.size());
  const pcl::PointCloud<pcl::PointXYZ>::Ptr grid =
      paddedGrid(scan, integralImageMargin(scan, smoothing), cell);
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setNormalEstimationMethod(
      estimation.COVARIANCE_MATRIX);  // the only one with curvature
  estimation.setNormalSmoothingSize(smoothing);
  estimation.setMaxDepthChangeFactor(options.max_depth_change);
  estimation.setDepthDependentSmoothing(true);
  estimation.setViewPoint(scan.sensor_origin[0], scan.sensor_origin[1], scan.sensor_origin[2]);
  estimation.setInputCloud(grid);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    if (kept(i)) estimates[i] = fromPcl(normals[cell[i]], i);
  }
  return estimates;
}

// k-NN PCA for the points listed in `todo`.
void pcaEstimates(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                  const pcl::search::KdTree<pcl::PointXYZ>::Ptr& tree, const Scan& scan,
                  int neighbours, unsigned threads, const pcl::IndicesPtr& todo,
                  std::vector<Estimate>& estimates) {
  if (todo->empty()) return;
  // PCL's default (0) is a thread per core, whatever --threads said.
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation(
      threads == 0 ? cores : std::min(threads, cores));
  estimation.setInputCloud(cloud);
  estimation.setIndices(todo);
  estimation.setSearchMethod(tree);
  estimation.setKSearch(neighbours);
  estimation.setViewPoint(scan.sensor_origin[0], scan.sensor_origin[1], scan.sensor_origin[2]);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  for (std::size_t j = 0; j < todo->size(); ++j) {
    const auto point = static_cast<std::size_t>((*todo)[j]);
    estimates[point] = fromPcl(normals[j], point);
  }
}

// The sharpening step. A point whose neighbourhood is much less flat than is typical of the scan
// (curvature above kFeatureCurvature times the median) straddles a crease: its normal is a blend
// of the faces'. Such points take, pass after pass, the reliable normal (from a neighbourhood at
// most kFlatCurvature times the median: one lying wholly on a face) among their own and their
// kSharpenCandidates nearest neighbours' whose plane (the normal through the point its
// neighbourhood was centred on, its anchor) passes nearest to them, within `tolerance`: reliable
// normals spread inward from the faces, one candidate radius a pass, until the blend is gone
// (kSharpenPasses cover the widest neighbourhood), and each point ends on the face whose plane
// it lies on; the plane test against the anchor stops a face's normal from creeping past the
// crease onto the next face. Every
// other point keeps its own estimate: on a smooth curved surface a neighbour's normal is off by its
// distance over the radius of curvature. Each pass reads only the previous one: the result does not
// depend on the order points are visited in.
constexpr float kFeatureCurvature = 2.5f;
constexpr float kFlatCurvature =
    1.5f;  // a neighbourhood this flat (x median) gives a reliable normal
constexpr int kSharpenCandidates = 24;
constexpr int kSharpenPasses = 8;

float medianCurvature(const std::vector<Estimate>& estimates) {
  std::vector<float> curvatures;
  for (const Estimate& e : estimates) {
    if (known(e)) curvatures.push_back(e.curvature);
  }
  if (curvatures.empty()) return 0;
  const auto middle = curvatures.begin() + static_cast<std::ptrdiff_t>(curvatures.size() / 2);
  std::nth_element(curvatures.begin(), middle, curvatures.end());
  return *middle;
}

std::vector<Vec3f> sharpened(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                             const pcl::search::KdTree<pcl::PointXYZ>::Ptr& tree, const Scan& scan,
                             std::vector<Estimate> estimates, float tolerance) {
  const float median = medianCurvature(estimates);
  std::vector<std::size_t> features;
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    if (!known(estimates[i]) || estimates[i].curvature > kFeatureCurvature * median)
      features.push_back(i);
  }
  const int candidates = std::min<int>(kSharpenCandidates, static_cast<int>(estimates.size()));
  std::vector<pcl::index_t> neighbour(features.size() * static_cast<std::size_t>(candidates), -1);
  {
    Progress progress("normals: sharpening", features.size());
    pcl::Indices found;
    std::vector<float> squared;
    for (std::size_t f = 0; f < features.size(); ++f) {
      tree->nearestKSearch((*cloud)[features[f]], candidates, found, squared);
      std::copy(found.begin(), found.end(),
                neighbour.begin() +
                    static_cast<std::ptrdiff_t>(f * static_cast<std::size_t>(candidates)));
      if ((f & 0xffff) == 0) progress.update(f);
    }
  }
  const float reliable = kFlatCurvature * median;
  // How far `p` lies from the plane of `e` (its normal through its anchor).
  const auto offPlane = [&](const Estimate& e, const Vec3f& p) {
    return std::fabs(dot(e.normal, minus(p, scan.positions[e.anchor])));
  };
  for (int pass = 0; pass < kSharpenPasses; ++pass) {
    std::vector<Estimate> next = estimates;
    bool changed = false;
    for (std::size_t f = 0; f < features.size(); ++f) {
      const std::size_t i = features[f];
      const Vec3f& p = scan.positions[i];
      // The reliable plane nearest to the point, among its own (once it has taken one) and its
      // candidates'; within `tolerance` only.
      const Estimate* best = nullptr;
      float best_distance = tolerance;
      if (known(estimates[i]) && estimates[i].curvature <= reliable) {
        best = &estimates[i];
        best_distance = offPlane(estimates[i], p);
      }
      for (int c = 0; c < candidates; ++c) {
        const pcl::index_t j =
            neighbour[f * static_cast<std::size_t>(candidates) + static_cast<std::size_t>(c)];
        if (j < 0) break;
        const Estimate& candidate = estimates[static_cast<std::size_t>(j)];
        if (!known(candidate) || candidate.curvature > reliable) continue;
        const float distance = offPlane(candidate, p);
        if (distance < best_distance) {
          best = &candidate;
          best_distance = distance;
        }
      }
      if (best != nullptr && best != &estimates[i]) {
        next[i] = *best;
        changed = true;
      }
    }
    estimates = std::move(next);
    if (!changed) break;
  }
  std::vector<Vec3f> normals;
  normals.reserve(estimates.size());
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    Vec3f n = estimates[i].normal;
    if (dot(n, minus(scan.sensor_origin, scan.positions[i])) < 0)
      n = {-n[0], -n[1], -n[2]};  // toward the sensor
    normals.push_back(n);
  }
  return normals;
}

}  // namespace

int neighboursForDensity(double points_per_voxel) {
  const double within_radius =
      kPi * kNeighbourRadiusVoxels * kNeighbourRadiusVoxels * points_per_voxel;
  return static_cast<int>(
      std::clamp(std::lround(within_radius), long{kMinPcaNeighbours}, long{kMaxPcaNeighbours}));
}

std::vector<Vec3f> estimateNormals(const Scan& scan, double voxel_edge,
                                   const NormalOptions& options, const std::string& scan_path) {
  const std::size_t count = scan.positions.size();
  if (count < 3) {
    throw PrepareError(scan_path + ": normals need at least 3 points, the scan has " +
                       std::to_string(count));
  }
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(count);
  for (const Vec3f& p : scan.positions) cloud->push_back({p[0], p[1], p[2]});
  auto tree = std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>();
  tree->setInputCloud(cloud);

  const bool organized = scan.grid_width > 0 && scan.grid_index.size() == count;
  std::vector<Estimate> estimates =
      organized ? integralImageEstimates(scan, voxel_edge, options) : std::vector<Estimate>(count);
  auto todo = std::make_shared<pcl::Indices>();
  for (std::size_t i = 0; i < count; ++i) {
    if (!known(estimates[i])) todo->push_back(static_cast<pcl::index_t>(i));
  }
  const int neighbours = std::min<int>(
      options.neighbours > 0 ? options.neighbours : kMaxPcaNeighbours, static_cast<int>(count));
  pcaEstimates(cloud, tree, scan, neighbours, options.threads, todo, estimates);
  if (!options.sharpen) {
    std::vector<Vec3f> normals;
    for (const Estimate& e : estimates) normals.push_back(e.normal);
    return normals;
  }
  return sharpened(cloud, tree, scan, std::move(estimates), static_cast<float>(voxel_edge));
}

}  // namespace octopoint::prepare
