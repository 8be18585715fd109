#pragma once
// Where does a sampled surface end? The reference (lab/reference_surface.h: discs for an
// unorganized scan, a mesh for a depth image) judged against ground truth (docs/tradeoff.md, "The
// reference render"): synthetic scans of a square whose exact silhouette is known, sampled as a
// scanner or a depth camera would, with or without stray returns off its edge. The truth is
// rasterized with the reference's own coverage rule (a pixel whose centre lies inside the projected
// square); anything drawn of the scan (the reference, or octopoint's model of the same points) is
// compared with it pixel by pixel:
//   spill = covered pixels outside the truth, holes = truth pixels not covered,
// both as shares of the truth's pixels. octopoint-reference-truth prints the whole experiment.

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "codegen/cube_fit.h"
#include "codegen/scan_loader.h"
#include "lab/reference_surface.h"
#include "octopoint/camera.h"

namespace octopoint::tradeoff {

enum class Sampling {
  kJittered,  // one point anywhere in each cell of a square grid (lab/reference_closure.h)
  kLines,     // a line scanner: lines spaced a, points along each spaced b = a / 1.5, jittered
};

struct TruthScan {
  prepare::Scan points;  // model axes; the square lies in z = 0
  // The square's corners, in order: the truth's outline.
  std::array<std::array<float, 3>, 4> corners;
  double spacing = 0;  // h: the median nearest-neighbour distance of the samples on the square
};

// The square [-1, 1]^2 at z = 0, turned 20 degrees about z (so that its edges slant across the
// voxel grid), sampled by `sampling` with about `cells` samples (jittered) or lines (line scanner)
// across it, plus `strays` stray returns: points in its plane, outside it, between 0.5 and 3
// spacings from its edge (a mixed-pixel return seen from aside), and one point at z = 0.001 inside
// it so that the fitted cube has depth. Seeded: always the same points.
TruthScan squareScan(Sampling sampling, int cells, int strays, unsigned seed);

// The same square seen by a depth camera (an organized scan, as a Kinect's): a grid of rays from
// the sensor at the origin through pixel centres, the camera looking along +z with a focal length
// that gives `across` grid steps across the square at its centre; the square's centre on the axis
// at `distance` (in square half-sides, so 2 x the square's side at 4), tilted by `tilt_degrees`
// about the camera's x axis (its rows foreshorten). A ray that hits the square gives the hit point;
// one that misses is NaN (no position, as a real depth image's NaN), and the grid spans the
// square's image with a margin. The grid's origin is shifted by a seeded fraction of a pixel, so
// that the edges fall anywhere between the rays. Scan::grid_width/grid_height/grid_index are set.
TruthScan depthCameraScan(int across, double distance, double tilt_degrees, unsigned seed);

// The truth for `camera`: CV_8U, 255 where the pixel centre lies inside the projected square (or on
// its edge).
cv::Mat truthMask(const TruthScan& scan, const prepare::CubeFit& fit, const Camera& camera);

// How a drawn silhouette (CV_8U, non-zero = covered) meets the truth.
struct TruthMatch {
  std::int64_t truth = 0;        // pixels of the truth
  std::int64_t spill = 0;        // covered pixels outside the truth
  std::int64_t holes = 0;        // truth pixels left empty
  std::int64_t inner_holes = 0;  // of those, more than `inset` pixels inside the truth's outline
  std::int64_t outline = 0;      // the truth's outline length, in pixels (its boundary pixels)
  void add(const TruthMatch& other);
  double spillShare() const;
  double holeShare() const;
  double innerHoleShare() const;
  // The spill spread along the outline: how far past the truth's edge the drawing reaches on
  // average, in pixels (spill / outline).
  double meanReachPx() const;
  // The same, signed: (spill - holes) over the outline, in pixels. Negative: the drawing falls
  // short of the true edge on average (its outline lies inside the truth's).
  double meanOffsetPx() const;
};
TruthMatch matchTruth(const cv::Mat& truth, const cv::Mat& covered, int inset);

// `surface` (the reference of `scan`) against the truth at every size 1x1, 7x5, 176x208, 320x240,
// 1280x960, 1920x1080 and zoom 0.25 to 8, head-on and turned 30 degrees (the bounds of
// tests/lab/reference_truth_test.cpp and octopoint-reference-truth --outline-sweep).
struct TruthReach {
  double spacings = 0;           // mean reach past the true edge (spill over the outline), in h
  double signed_spacings = 0;    // (spill - holes) over the outline, in h
  std::int64_t inner_holes = 0;  // truth pixels more than 2 h inside left empty
  std::string first_hole;        // the first view with one ("WxH zoom Z yaw Y"), empty if none
};
TruthReach reachOverViews(const TruthScan& scan, const ReferenceSurface& surface);

}  // namespace octopoint::tradeoff
