// The reference's surface: PCL's OrganizedFastMesh for a depth image, PCL's k-d tree for the splat
// radii of an unorganized scan. The only file under app/ that includes PCL headers.
#include "app/reference_surface.h"

#include <pcl/Vertices.h>
#include <pcl/common/angles.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/surface/organized_fast_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace octopoint::tradeoff {
namespace {

// The grid's angular pitch: the median over horizontally adjacent points of their distance
// divided by their distance from the sensor (radians per grid step; a Kinect's is about 1/580).
double gridPitch(const pcl::PointCloud<pcl::PointXYZ>& grid) {
  std::vector<double> ratios;
  for (std::uint32_t row = 0; row < grid.height; ++row) {
    for (std::uint32_t col = 0; col + 1 < grid.width; ++col) {
      const pcl::PointXYZ& a = grid.at(col, row);
      const pcl::PointXYZ& b = grid.at(col + 1, row);
      if (!pcl::isFinite(a) || !pcl::isFinite(b)) continue;
      const double range = a.getVector3fMap().cast<double>().norm();
      if (range > 0)
        ratios.push_back((a.getVector3fMap() - b.getVector3fMap()).cast<double>().norm() / range);
    }
  }
  if (ratios.empty()) return 0;
  std::nth_element(ratios.begin(), ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2),
                   ratios.end());
  return ratios[ratios.size() / 2];
}

void meshGrid(const prepare::Scan& points, ReferenceSurface& surface) {
  const std::size_t cells = std::size_t{points.grid_width} * points.grid_height;
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  auto grid = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(
      points.grid_width, points.grid_height, pcl::PointXYZ(kNaN, kNaN, kNaN));
  grid->is_dense = false;
  // Which position sits in each grid cell (-1: none, the scan had NaN there or it was cropped).
  std::vector<std::int32_t> position_of_cell(cells, -1);
  for (std::size_t i = 0; i < points.positions.size(); ++i) {
    const std::uint32_t cell = points.grid_index[i];
    if (cell >= cells)
      throw std::invalid_argument("reference surface: grid index outside the scan's grid");
    const auto& p = points.positions[i];
    (*grid)[cell] = pcl::PointXYZ(p[0], p[1], p[2]);
    position_of_cell[cell] = static_cast<std::int32_t>(i);
  }
  pcl::OrganizedFastMesh<pcl::PointXYZ> mesher;
  mesher.setInputCloud(grid);
  // Of the two triangles a grid quad can be cut into, the cut across the smaller jump in depth.
  mesher.setTriangulationType(pcl::OrganizedFastMesh<pcl::PointXYZ>::TRIANGLE_ADAPTIVE_CUT);
  mesher.setViewpoint(Eigen::Vector3f::Zero());
  const double pitch = gridPitch(*grid);
  if (pitch > 0) mesher.setMaxEdgeLength(0.0f, static_cast<float>(kMaxEdgeGridSteps * pitch));
  std::vector<pcl::Vertices> polygons;
  mesher.reconstruct(polygons);
  surface.triangles.reserve(polygons.size());
  for (const pcl::Vertices& polygon : polygons) {
    std::array<std::uint32_t, 3> triangle{};
    for (std::size_t k = 0; k < 3; ++k) {
      triangle[k] = static_cast<std::uint32_t>(
          position_of_cell[static_cast<std::size_t>(polygon.vertices[k])]);
    }
    surface.triangles.push_back(triangle);
  }
}

}  // namespace

namespace {

// For every position, its `neighbour` nearest other positions (PCL k-d tree; with fewer others, all
// of them), handed to `visit(i, found, squared)` (found[0] is the position itself).
template <typename Visit>
void forEachNeighbourhood(const std::vector<std::array<float, 3>>& positions, int neighbour,
                          Visit visit) {
  const std::size_t count = positions.size();
  if (count < 2 || neighbour < 1) return;
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(count);
  for (const auto& p : positions) cloud->push_back({p[0], p[1], p[2]});
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  // The point itself comes back first (distance 0): ask for one more.
  const int wanted =
      static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(neighbour), count - 1)) + 1;
  pcl::Indices found;
  std::vector<float> squared;
  for (std::size_t i = 0; i < count; ++i) {
    tree.nearestKSearch((*cloud)[i], wanted, found, squared);
    visit(i, found, squared);
  }
}

}  // namespace

std::vector<float> neighbourDistances(const std::vector<std::array<float, 3>>& positions,
                                      int neighbour) {
  std::vector<float> distance(positions.size(), 0.0f);
  forEachNeighbourhood(positions, neighbour,
                       [&](std::size_t i, const pcl::Indices&, const std::vector<float>& squared) {
                         distance[i] = squared.empty() ? 0.0f : std::sqrt(squared.back());
                       });
  return distance;
}

std::vector<float> centroidOffsets(const std::vector<std::array<float, 3>>& positions,
                                   int neighbour) {
  std::vector<float> offset(positions.size(), 0.0f);
  forEachNeighbourhood(
      positions, neighbour,
      [&](std::size_t i, const pcl::Indices& found, const std::vector<float>& squared) {
        if (found.size() < 2 || !(squared.back() > 0)) return;
        double centroid[3] = {0, 0, 0};
        for (std::size_t k = 1; k < found.size(); ++k) {
          for (std::size_t axis = 0; axis < 3; ++axis)
            centroid[axis] += positions[static_cast<std::size_t>(found[k])][axis];
        }
        double off_squared = 0;
        for (std::size_t axis = 0; axis < 3; ++axis) {
          const double d =
              centroid[axis] / static_cast<double>(found.size() - 1) - positions[i][axis];
          off_squared += d * d;
        }
        offset[i] = static_cast<float>(std::sqrt(off_squared / squared.back()));
      });
  return offset;
}

std::vector<float> splatRadii(const std::vector<float>& neighbour_distance, const SplatRule& rule,
                              const std::vector<float>& centroid_offset) {
  std::vector<float> radius(neighbour_distance.size(), 0.0f);
  if (radius.empty()) return radius;
  // The cap: the rule's quantile of the neighbour distances (nth_element on a copy).
  std::vector<float> sorted = neighbour_distance;
  const auto rank =
      static_cast<std::size_t>(rule.cap_quantile * static_cast<double>(sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(rank),
                   sorted.end());
  const double limit = sorted[rank];
  const bool edges = rule.edge_offset > 0 && centroid_offset.size() == radius.size();
  for (std::size_t i = 0; i < radius.size(); ++i) {
    const bool on_edge = edges && centroid_offset[i] > rule.edge_offset;
    radius[i] = static_cast<float>((on_edge ? rule.edge_scale : rule.scale) *
                                   std::min(static_cast<double>(neighbour_distance[i]), limit));
  }
  return radius;
}

ReferenceSurface buildReferenceSurface(const prepare::Scan& points, const SplatRule& rule) {
  ReferenceSurface surface;
  surface.positions = points.positions;
  surface.colours = points.colours;
  const bool gridded = !points.grid_index.empty() &&
                       points.grid_index.size() == points.positions.size() &&
                       points.grid_width > 0 && points.grid_height > 1;
  if (gridded)
    meshGrid(points, surface);
  else
    surface.splat_radius =
        splatRadii(neighbourDistances(points.positions, rule.neighbour), rule,
                   rule.edge_offset > 0 ? centroidOffsets(points.positions, rule.neighbour)
                                        : std::vector<float>{});
  return surface;
}

}  // namespace octopoint::tradeoff
