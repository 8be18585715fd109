#pragma once
// The surface the dense reference render draws (docs/tradeoff.md, "The reference render"): a scan's
// points made into something that covers the object at every size and zoom.
//
// - Organized scan (a depth image: Scan::grid_width x grid_height): the grid is triangulated with
//   PCL's OrganizedFastMesh, neighbours in the grid joined by triangles, except across a depth
//   discontinuity (an edge longer than kMaxEdgeGridSteps grid steps).
// - Unorganized scan: every point becomes a disc facing the viewer whose radius is the distance to
//   its kSplatNeighbour-th nearest neighbour (PCL k-d tree), at most the kMaxSplatQuantile
//   quantile of that distance over the scan, so that the discs of an evenly sampled surface
//   overlap without gaps.
//
// Building it is view-independent and done once per scan; app/reference_render.h draws it per view.
// This file's .cpp is the only one under app/ that includes PCL headers (they compile slowly).

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
// Which nearest neighbour's distance is a splat's radius. On a square grid of spacing h the 5th
// and 6th nearest lie at sqrt(2) h (h / sqrt(2) closes the grid's gaps); on a jittered grid (one
// point anywhere in each cell) the 5th is the least that leaves no hole
// (tests/reference_render_test.cpp), the 6th leaves a margin.
inline constexpr int kSplatNeighbour = 6;
// A point whose neighbours are far (stray returns, the sparse floor of a laser scan) samples no
// surface: no splat is wider than this quantile of the scan's splat radii.
inline constexpr double kMaxSplatQuantile = 0.9;

struct ReferenceSurface {
  // The points (model axes, scan units) and their colours, as given.
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<std::uint8_t, 3>> colours;  // empty: the points are drawn light grey
  // Organized scan: triangles as indices into positions (wound as the grid gives them).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // Unorganized scan: one splat radius per position, in scan units (empty when organized).
  std::vector<float> splat_radius;
};

// Builds the surface of `points` (the model's points, prepare::modelPoints). An organized scan
// whose sensor sat at the origin of its own frame (true of depth-camera clouds; the model's axes
// only turn about that origin) is meshed; any other is splatted (with fewer than kSplatNeighbour +
// 1 points, the farthest other point gives the radius; a single point has radius 0).
ReferenceSurface buildReferenceSurface(const prepare::Scan& points);

}  // namespace octopoint::tradeoff
