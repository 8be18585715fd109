// The k nearest neighbours come from PCL's k-d tree (FLANN): about 15x faster here than PCL's
// octree search on a 243k-point Kinect scan. PCL headers compile slowly: this is the only file
// besides scan_loader.cpp that includes them.
#include "codegen/outlier_filter.h"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>

#include "codegen/prepare_error.h"
#include "codegen/progress.h"

namespace octopoint::prepare {

Scan removeOutliers(const Scan& scan, const OutlierRemoval& rule, const std::string& scan_path) {
  const std::size_t count = scan.positions.size();
  if (count <= static_cast<std::size_t>(rule.neighbours)) {
    throw PrepareError(scan_path + ": outlier removal needs more than " +
                       std::to_string(rule.neighbours) + " points, the scan has " +
                       std::to_string(count));
  }
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(count);
  for (const auto& p : scan.positions) cloud->push_back({p[0], p[1], p[2]});
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);

  // Mean distance of each point to its k nearest neighbours (itself excluded).
  std::vector<double> mean_distance(count);
  pcl::Indices found;
  std::vector<float> squared;
  Progress progress("outlier removal", count);
  for (std::size_t i = 0; i < count; ++i) {
    tree.nearestKSearch((*cloud)[i], rule.neighbours + 1, found, squared);
    double sum = 0;
    for (std::size_t j = 1; j < squared.size(); ++j)
      sum += std::sqrt(static_cast<double>(squared[j]));
    mean_distance[i] = sum / std::max<std::size_t>(squared.size() - 1, 1);
    if ((i & 0xffff) == 0) progress.update(i);
  }
  double mean = 0, square_sum = 0;
  for (double d : mean_distance) mean += d;
  mean /= static_cast<double>(count);
  for (double d : mean_distance) square_sum += (d - mean) * (d - mean);
  const double stddev = std::sqrt(square_sum / static_cast<double>(count - 1));
  const double limit = mean + rule.stddev_factor * stddev;

  std::vector<std::uint8_t> inlier(count);
  for (std::size_t i = 0; i < count; ++i) inlier[i] = mean_distance[i] <= limit;
  Scan kept = keepPoints(scan, inlier);
  if (kept.positions.empty()) throw PrepareError(scan_path + ": outlier removal left no point");
  return kept;
}

}  // namespace octopoint::prepare
