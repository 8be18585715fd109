#pragma once
// The surface the dense reference render draws (docs/tradeoff.md, "The reference render"): a scan's
// points made into something that covers the object at every size and zoom.
//
// - Organized scan (a depth image: Scan::grid_width x grid_height): the grid is triangulated with
//   PCL's OrganizedFastMesh, neighbours in the grid joined by triangles, except across a depth
//   discontinuity (an edge longer than kMaxEdgeGridSteps grid steps).
// - Unorganized scan: every point becomes a disc facing the viewer whose radius is kSplatRule:
//   0.7 x the distance to its 8th nearest neighbour (PCL k-d tree), that distance at most its 90%
//   quantile over the scan: the smallest discs that close the reference's own surface
//   (lab/reference_closure.h measures it); 0.25 x that distance for a stray return (neighbours on
//   one side only) or a sparse outlier (its neighbours more than 1.9 times as far as the scan's
//   median point's), which the exact silhouette of sampled squares supports
//   (lab/reference_truth.h); a point on the surface's outline (its 16 nearest neighbours leave a
//   gap wider than 120 degrees around it) keeps its disc but moves it inward by 0.55 x its radius,
//   which puts the discs' outline nearest the true edge of sampled squares with no hole inside.
//
// Building it is view-independent and done once per scan; lab/reference_render.h draws it per view.
// This file's .cpp is the only one under lab/ that includes PCL headers (they compile slowly).

#include <array>
#include <cstdint>
#include <vector>

#include "codegen/scan_loader.h"

namespace octopoint::tradeoff {

// An edge between grid neighbours longer than this many grid steps at its distance from the sensor
// (kMaxEdgeGridSteps x pitch x range, the pitch measured as the median over neighbours) is a
// jump in depth, not a surface: a surface seen at up to acos(1/8) = 83 degrees from face-on, or a
// depth camera's quantized depth (a Kinect's step is about 1.7 grid steps at 1 m), stays joined.
inline constexpr double kMaxEdgeGridSteps = 8;
// How far past its last samples a depth image's mesh goes, in grid steps: a depth camera's sample
// is the ray through a pixel centre, so the surface's true edge lies somewhere between the last ray
// that hit it and the first that missed, and a mesh that ends at the last hits falls short of it.
// Each boundary edge of the triangulation (an edge of one triangle only) gets a strip this many
// grid steps wide, outward in the grid and lifted onto the boundary triangle's own plane; a convex
// corner between two such strips is filled. 0.45 puts the mesh's end closest to the exact
// silhouette of a square seen by a synthetic depth camera (lab/scripts/reference-truth
// --mesh-extension); the measurement is in docs/tradeoff.md, "Where a depth image's surface ends".
inline constexpr double kMeshExtensionSteps = 0.45;
// How an unorganized scan's points become discs: a point's radius is `scale` x the distance to its
// `neighbour`-th nearest neighbour, that distance capped at its `cap_quantile` quantile over the
// scan (a stray return far from everything samples no surface, and gets no wider disc than most
// points). Stray returns and sparse outliers get smaller discs, since they sample no surface; an
// outline point (found by the angular gap its neighbours leave around it, as PCL's
// BoundaryEstimation does) keeps its disc but moves it inward, which pulls the outline in further
// than a smaller disc could before holes open. kSplatRule's values are the smallest discs that
// close the reference's own surface (lab/scripts/reference-closure) with the outline nearest the
// exact silhouette of sampled squares (lab/scripts/reference-truth); every measurement behind
// them is in docs/tradeoff.md, "The reference render".
struct SplatRule {
  int neighbour = 8;
  double scale = 0.7;
  double cap_quantile = 0.9;
  // A point whose `neighbour` nearest neighbours have their centroid more than edge_offset x its
  // neighbour distance away from it has them on one side: a stray return (or, at lower offsets,
  // an outline point), and its disc is edge_scale x that (capped) distance instead. 0: none is.
  double edge_offset = 0;
  double edge_scale = 0;
  // A point whose `outline_neighbours` nearest neighbours, seen from it in their own plane (PCA),
  // leave an angular gap wider than outline_gap_degrees around it lies on the surface's outline
  // (outlinePoints), and its disc is outline_scale x its (capped) neighbour distance instead (a
  // stray return keeps edge_scale), its centre moved inward (toward those neighbours' centroid,
  // in their plane) by outline_shift x its radius. 0 neighbours: no point is.
  int outline_neighbours = 0;
  double outline_gap_degrees = 0;
  double outline_scale = 0;
  double outline_shift = 0;
  // A point whose neighbour distance exceeds sparse_factor x the scan's median one sits where the
  // scan samples at under 1 / sparse_factor^2 of its typical density: a sparse outlier (the
  // criterion of PCL's statistical outlier removal, a distance far out in the scan's own
  // distribution, made scale-free), drawn as a stray return (edge_scale). 0: none is.
  double sparse_factor = 0;
};
// The values chosen in docs/tradeoff.md, "The reference render" (sparse_factor: the smallest, in
// steps of 0.1, at which no view of lms400's closure measurement has more holes inside).
inline constexpr SplatRule kSplatRule{8, 0.7, 0.9, 0.6, 0.25, 16, 120, 0.7, 0.55, 1.9};

struct ReferenceSurface {
  // The points (model axes, scan units) and their colours, as given but for an unorganized scan's
  // outline points, moved inward (SplatRule::outline_shift); an organized scan's mesh extension
  // (kMeshExtensionSteps) appends the outer corners of its strips after them.
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<std::uint8_t, 3>> colours;  // empty: the points are drawn light grey
  // Organized scan: triangles as indices into positions (wound as the grid gives them), then the
  // strips past the boundary.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // Unorganized scan: one splat radius per position, in scan units (empty when organized).
  std::vector<float> splat_radius;
};

// Builds the surface of `points` (the model's points, prepare::modelPoints). An organized scan
// whose sensor sat at the origin of its own frame (true of depth-camera clouds; the model's axes
// only turn about that origin) is meshed; any other is splatted (with fewer than rule.neighbour +
// 1 points, the farthest other point gives the radius; a single point has radius 0).
// `mesh_extension` is the strip past an organized scan's boundary, in grid steps (0: the mesh
// ends at the last samples).
ReferenceSurface buildReferenceSurface(const prepare::Scan& points,
                                       const SplatRule& rule = kSplatRule,
                                       double mesh_extension = kMeshExtensionSteps);

// Each position's distance to its `neighbour`-th nearest other position (PCL k-d tree; with fewer
// others, the farthest; 0 for a single position).
std::vector<float> neighbourDistances(const std::vector<std::array<float, 3>>& positions,
                                      int neighbour);

// Each position's distance to the centroid of its `neighbour` nearest other positions, over its
// distance to the farthest of them (about 0.42 on a straight outline, near 0 inside a surface).
std::vector<float> centroidOffsets(const std::vector<std::array<float, 3>>& positions,
                                   int neighbour);

// Which positions lie on the outline of the surface they sample (1) or inside it (0): the
// directions to a position's `neighbour` nearest other positions, projected on the plane those
// neighbours and the position span (the normal: their covariance's least eigenvector), leave an
// angular gap wider than `gap_degrees` around it (as PCL's BoundaryEstimation, with its own
// normal). With fewer than 2 others, none is.
std::vector<std::uint8_t> outlinePoints(const std::vector<std::array<float, 3>>& positions,
                                        int neighbour, double gap_degrees);

// Which points `rule` draws as stray returns (1): their `centroid_offset` (when given) exceeds
// rule.edge_offset, or their neighbour distance exceeds rule.sparse_factor x the median one.
std::vector<std::uint8_t> strayPoints(const std::vector<float>& neighbour_distance,
                                      const SplatRule& rule,
                                      const std::vector<float>& centroid_offset = {});

// The disc radii `rule` gives for those distances: rule.scale x min(distance, the rule's quantile
// of the distances), rule.edge_scale instead of rule.scale where `stray` (strayPoints, when given)
// is non-zero, else rule.outline_scale where `outline` (when given) is non-zero.
std::vector<float> splatRadii(const std::vector<float>& neighbour_distance, const SplatRule& rule,
                              const std::vector<std::uint8_t>& stray = {},
                              const std::vector<std::uint8_t>& outline = {});

}  // namespace octopoint::tradeoff
