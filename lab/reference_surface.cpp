// The reference's surface: PCL's OrganizedFastMesh for a depth image, PCL's k-d tree for the splat
// radii of an unorganized scan. The only file under lab/ that includes PCL headers.
#include "lab/reference_surface.h"

#include <pcl/Vertices.h>
#include <pcl/common/angles.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/surface/organized_fast_mesh.h>

#include <Eigen/Eigenvalues>
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

using Vec3 = std::array<double, 3>;

// A point's place in the depth image's grid (column, row).
std::array<double, 2> gridOf(const prepare::Scan& points, std::uint32_t i) {
  const std::uint32_t cell = points.grid_index[i];
  return {double(cell % points.grid_width), double(cell / points.grid_width)};
}

Vec3 spaceOf(const ReferenceSurface& surface, std::uint32_t i) {
  const auto& p = surface.positions[i];
  return {p[0], p[1], p[2]};
}

// Grid steps `g` in space, by an affine map's two columns (space per step along columns, rows).
Vec3 lift(const std::array<Vec3, 2>& map, const std::array<double, 2>& g) {
  return Vec3{map[0][0] * g[0] + map[1][0] * g[1], map[0][1] * g[0] + map[1][1] * g[1],
              map[0][2] * g[0] + map[1][2] * g[1]};
}

Vec3 plus(const Vec3& p, const Vec3& d) { return Vec3{p[0] + d[0], p[1] + d[1], p[2] + d[2]}; }

// Adds a vertex at `p` with the colour of vertex `colour_of`; returns its index.
std::uint32_t appendVertex(ReferenceSurface& surface, const Vec3& p, std::uint32_t colour_of) {
  surface.positions.push_back(
      {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
  if (!surface.colours.empty()) {
    const std::array<std::uint8_t, 3> colour = surface.colours[colour_of];
    surface.colours.push_back(colour);
  }
  return static_cast<std::uint32_t>(surface.positions.size() - 1);
}

// A triangle's edge, keyed by its two vertices; a key seen once is a boundary edge.
struct Side {
  std::uint64_t key;
  std::uint32_t from, to, opposite;
};

// Every triangle's edges, sorted by key.
std::vector<Side> sortedSides(const ReferenceSurface& surface) {
  std::vector<Side> sides;
  sides.reserve(surface.triangles.size() * 3);
  for (const auto& t : surface.triangles) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t from = t[k], to = t[(k + 1) % 3], opposite = t[(k + 2) % 3];
      sides.push_back(
          {std::uint64_t{std::min(from, to)} << 32 | std::max(from, to), from, to, opposite});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) { return x.key < y.key; });
  return sides;
}

// A boundary edge at a vertex: its outward unit normal in the grid and the affine map (grid to
// space) of its triangle, to fill the corner between two of them.
struct Outward {
  std::uint32_t vertex;
  std::array<double, 2> normal;  // grid steps
  std::array<Vec3, 2> map;       // space per grid step along the grid's columns, rows
};

// The strip outward from each boundary edge (see extendBoundary); returns the edges at their two
// vertices.
std::vector<Outward> extrudeBoundaryEdges(const prepare::Scan& points, double steps,
                                          ReferenceSurface& surface) {
  const std::vector<Side> sides = sortedSides(surface);
  std::vector<Outward> outward;
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const bool shared = (i > 0 && sides[i - 1].key == sides[i].key) ||
                        (i + 1 < sides.size() && sides[i + 1].key == sides[i].key);
    if (shared) continue;
    const Side& side = sides[i];
    const auto ga = gridOf(points, side.from), gb = gridOf(points, side.to),
               gc = gridOf(points, side.opposite);
    // The triangle's affine map: [gb - ga, gc - ga] (grid) to [pb - pa, pc - pa] (space).
    const double e0[2] = {gb[0] - ga[0], gb[1] - ga[1]}, e1[2] = {gc[0] - ga[0], gc[1] - ga[1]};
    const double det = e0[0] * e1[1] - e0[1] * e1[0];
    if (!(std::fabs(det) > 0)) continue;
    const Vec3 pa = spaceOf(surface, side.from), pb = spaceOf(surface, side.to),
               pc = spaceOf(surface, side.opposite);
    std::array<Vec3, 2> map;
    for (std::size_t k = 0; k < 3; ++k) {
      const double d0 = pb[k] - pa[k], d1 = pc[k] - pa[k];
      // Inverse of [[e0x, e1x], [e0y, e1y]], applied on the right.
      map[0][k] = (d0 * e1[1] - d1 * e0[1]) / det;
      map[1][k] = (-d0 * e1[0] + d1 * e0[0]) / det;
    }
    const double length = std::hypot(e0[0], e0[1]);
    std::array<double, 2> normal = {-e0[1] / length, e0[0] / length};
    if (normal[0] * e1[0] + normal[1] * e1[1] > 0) normal = {-normal[0], -normal[1]};
    const Vec3 offset = lift(map, {normal[0] * steps, normal[1] * steps});
    const std::uint32_t a_out = appendVertex(surface, plus(pa, offset), side.from);
    const std::uint32_t b_out = appendVertex(surface, plus(pb, offset), side.to);
    surface.triangles.push_back({side.from, side.to, b_out});
    surface.triangles.push_back({side.from, b_out, a_out});
    outward.push_back({side.from, normal, map});
    outward.push_back({side.to, normal, map});
  }
  return outward;
}

// Fills the wedge between the strips of a vertex where exactly two boundary edges meet.
void fillCorners(double steps, std::vector<Outward>& outward, ReferenceSurface& surface) {
  std::sort(outward.begin(), outward.end(),
            [](const Outward& x, const Outward& y) { return x.vertex < y.vertex; });
  for (std::size_t i = 0; i < outward.size();) {
    std::size_t end = i + 1;
    while (end < outward.size() && outward[end].vertex == outward[i].vertex) ++end;
    // A vertex where more than two boundary edges meet (the mesh touches itself there) is left
    // as it is: which strips are neighbours is not clear, and the gap is at most a corner's.
    if (end - i == 2) {
      const Outward& x = outward[i];
      const Outward& y = outward[i + 1];
      const std::array<double, 2> sum = {x.normal[0] + y.normal[0], x.normal[1] + y.normal[1]};
      const double norm = std::hypot(sum[0], sum[1]);
      if (norm > 1e-9) {
        const std::uint32_t v = x.vertex;
        const Vec3 p = spaceOf(surface, v);
        const std::array<double, 2> mid = {sum[0] / norm * steps, sum[1] / norm * steps};
        const Vec3 to_mid_x = lift(x.map, mid), to_mid_y = lift(y.map, mid);
        const Vec3 to_mid = {(to_mid_x[0] + to_mid_y[0]) / 2, (to_mid_x[1] + to_mid_y[1]) / 2,
                             (to_mid_x[2] + to_mid_y[2]) / 2};
        const std::uint32_t xs = appendVertex(
            surface, plus(p, lift(x.map, {x.normal[0] * steps, x.normal[1] * steps})), v);
        const std::uint32_t ms = appendVertex(surface, plus(p, to_mid), v);
        const std::uint32_t ys = appendVertex(
            surface, plus(p, lift(y.map, {y.normal[0] * steps, y.normal[1] * steps})), v);
        surface.triangles.push_back({v, xs, ms});
        surface.triangles.push_back({v, ms, ys});
      }
    }
    i = end;
  }
}

// Extends the mesh past its boundary by `steps` grid steps (kMeshExtensionSteps): for each edge
// used by one triangle only, a strip outward from that triangle, `steps` wide in grid coordinates
// and lifted into space by the triangle's own affine map from grid to space (so the strip lies in
// its plane and is as wide as the local grid step there); at a boundary vertex where exactly two
// boundary edges meet, the wedge between their strips is filled (two triangles through the
// bisector), so a convex corner is rounded rather than notched. Colours are the edge's own.
void extendBoundary(const prepare::Scan& points, double steps, ReferenceSurface& surface) {
  if (!(steps > 0)) return;
  std::vector<Outward> outward = extrudeBoundaryEdges(points, steps, surface);
  fillCorners(steps, outward, surface);
}

void meshGrid(const prepare::Scan& points, double extension, ReferenceSurface& surface) {
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
  extendBoundary(points, extension, surface);
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

namespace {

// Per position on the outline (outlinePoints), the unit vector in its neighbours' plane from it
// toward their centroid (inward); {0, 0, 0} for a position inside.
std::vector<std::array<float, 3>> outlineInward(const std::vector<std::array<float, 3>>& positions,
                                                int neighbour, double gap_degrees) {
  std::vector<std::array<float, 3>> outline(positions.size(), {0.0f, 0.0f, 0.0f});
  const double gap_limit = gap_degrees * 3.14159265358979323846 / 180;
  std::vector<double> angles;
  forEachNeighbourhood(
      positions, neighbour,
      [&](std::size_t i, const pcl::Indices& found, const std::vector<float>&) {
        if (found.size() < 3) return;
        // The plane through the position and its neighbours: centroid and covariance (double).
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        const auto at = [&](std::size_t k) {
          const auto& p = positions[static_cast<std::size_t>(found[k])];
          return Eigen::Vector3d(p[0], p[1], p[2]);
        };
        for (std::size_t k = 0; k < found.size(); ++k) centroid += at(k);
        centroid /= static_cast<double>(found.size());
        Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
        for (std::size_t k = 0; k < found.size(); ++k) {
          const Eigen::Vector3d d = at(k) - centroid;
          covariance += d * d.transpose();
        }
        // Eigenvalues ascending: column 0 is the normal, 2 and 1 span the plane.
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
        const Eigen::Vector3d u = solver.eigenvectors().col(2), v = solver.eigenvectors().col(1);
        const Eigen::Vector3d self = at(0);
        angles.clear();
        for (std::size_t k = 1; k < found.size(); ++k) {
          const Eigen::Vector3d d = at(k) - self;
          const double x = d.dot(u), y = d.dot(v);
          if (x != 0 || y != 0) angles.push_back(std::atan2(y, x));
        }
        if (angles.size() < 2) return;
        std::sort(angles.begin(), angles.end());
        double widest = angles.front() + 2 * 3.14159265358979323846 - angles.back();
        for (std::size_t k = 1; k < angles.size(); ++k)
          widest = std::max(widest, angles[k] - angles[k - 1]);
        if (!(widest > gap_limit)) return;
        const Eigen::Vector3d to_centroid = centroid - self;
        Eigen::Vector3d inward = to_centroid.dot(u) * u + to_centroid.dot(v) * v;
        if (!(inward.norm() > 0)) inward = u;  // neighbours all round it, a gap yet: any way in
        inward.normalize();
        outline[i] = {static_cast<float>(inward.x()), static_cast<float>(inward.y()),
                      static_cast<float>(inward.z())};
      });
  return outline;
}

// 1 for each position outlineInward found on the outline, 0 for the others.
std::vector<std::uint8_t> outlineFlags(const std::vector<std::array<float, 3>>& inward) {
  std::vector<std::uint8_t> outline(inward.size(), 0);
  for (std::size_t i = 0; i < inward.size(); ++i)
    outline[i] = inward[i][0] != 0 || inward[i][1] != 0 || inward[i][2] != 0 ? 1 : 0;
  return outline;
}

}  // namespace

std::vector<std::uint8_t> outlinePoints(const std::vector<std::array<float, 3>>& positions,
                                        int neighbour, double gap_degrees) {
  return outlineFlags(outlineInward(positions, neighbour, gap_degrees));
}

std::vector<std::uint8_t> strayPoints(const std::vector<float>& neighbour_distance,
                                      const SplatRule& rule,
                                      const std::vector<float>& centroid_offset) {
  std::vector<std::uint8_t> stray(neighbour_distance.size(), 0);
  if (stray.empty()) return stray;
  double sparse_limit = std::numeric_limits<double>::infinity();
  if (rule.sparse_factor > 0) {
    std::vector<float> sorted = neighbour_distance;
    const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
    std::nth_element(sorted.begin(), middle, sorted.end());
    sparse_limit = rule.sparse_factor * static_cast<double>(*middle);
  }
  const bool edges = rule.edge_offset > 0 && centroid_offset.size() == stray.size();
  for (std::size_t i = 0; i < stray.size(); ++i) {
    const bool on_edge = edges && centroid_offset[i] > rule.edge_offset;
    stray[i] = on_edge || static_cast<double>(neighbour_distance[i]) > sparse_limit ? 1 : 0;
  }
  return stray;
}

std::vector<float> splatRadii(const std::vector<float>& neighbour_distance, const SplatRule& rule,
                              const std::vector<std::uint8_t>& stray,
                              const std::vector<std::uint8_t>& outline) {
  std::vector<float> radius(neighbour_distance.size(), 0.0f);
  if (radius.empty()) return radius;
  // The cap: the rule's quantile of the neighbour distances (nth_element on a copy).
  std::vector<float> sorted = neighbour_distance;
  const auto rank =
      static_cast<std::size_t>(rule.cap_quantile * static_cast<double>(sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(rank),
                   sorted.end());
  const double limit = sorted[rank];
  const bool strays = stray.size() == radius.size();
  const bool outlines = rule.outline_neighbours > 0 && outline.size() == radius.size();
  for (std::size_t i = 0; i < radius.size(); ++i) {
    const bool on_outline = outlines && outline[i] != 0;
    const double scale = strays && stray[i] != 0 ? rule.edge_scale
                         : on_outline            ? rule.outline_scale
                                                 : rule.scale;
    radius[i] =
        static_cast<float>(scale * std::min(static_cast<double>(neighbour_distance[i]), limit));
  }
  return radius;
}

ReferenceSurface buildReferenceSurface(const prepare::Scan& points, const SplatRule& rule,
                                       double mesh_extension) {
  ReferenceSurface surface;
  surface.positions = points.positions;
  surface.colours = points.colours;
  const bool gridded = !points.grid_index.empty() &&
                       points.grid_index.size() == points.positions.size() &&
                       points.grid_width > 0 && points.grid_height > 1;
  if (gridded) {
    meshGrid(points, mesh_extension, surface);
    return surface;
  }
  const std::vector<float> offsets = rule.edge_offset > 0
                                         ? centroidOffsets(points.positions, rule.neighbour)
                                         : std::vector<float>{};
  std::vector<std::array<float, 3>> inward;
  std::vector<std::uint8_t> outline;
  if (rule.outline_neighbours > 0) {
    inward = outlineInward(points.positions, rule.outline_neighbours, rule.outline_gap_degrees);
    outline = outlineFlags(inward);
  }
  const std::vector<float> distance = neighbourDistances(points.positions, rule.neighbour);
  const std::vector<std::uint8_t> stray = strayPoints(distance, rule, offsets);
  surface.splat_radius = splatRadii(distance, rule, stray, outline);
  if (rule.outline_shift > 0) {
    for (std::size_t i = 0; i < outline.size(); ++i) {
      if (outline[i] == 0 || stray[i] != 0) continue;
      const double by = rule.outline_shift * surface.splat_radius[i];
      for (std::size_t axis = 0; axis < 3; ++axis)
        surface.positions[i][axis] += static_cast<float>(by * inward[i][axis]);
    }
  }
  return surface;
}

}  // namespace octopoint::tradeoff
