#pragma once
// How closed the unorganized-scan reference (lab/reference_surface.h) is, measured on the
// reference alone, nothing of octopoint's: the measurements that chose kSplatRule
// (docs/tradeoff.md, "The reference render"; octopoint-reference-closure prints them).
//
// - A jittered plane (one point anywhere in each cell of a square grid, as a scanner's irregular
//   samples), drawn at every size 1x1..1920x1080 and zoom 0.25..8: its holes away from its ragged
//   border are exact, and a rule closes it or not.
// - A real scan (lms400): a hole is a pixel the reference leaves empty inside the morphological
//   closing of its covered set by a disc of radius max(1, round(h / 2 x pixels per unit)), h the
//   scan's median nearest-neighbour distance (its sample spacing), and at least 3 such radii from
//   that closing's outline: a gap narrower than a sample spacing, inside the surface, is the
//   reference failing to join its own samples, where a ragged outline or gaps among loose stray
//   returns are the scan's.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "codegen/cube_fit.h"
#include "codegen/scan_loader.h"
#include "lab/reference_surface.h"
#include "octopoint/camera.h"

namespace octopoint::tradeoff {

// A 2 x 2 square at z = 0 sampled by one point anywhere in each of side x side cells (seeded, so
// always the same points), plus one point at z = 0.001 so that the fitted cube has depth.
prepare::Scan jitteredPlane(int side, unsigned seed);

struct PlaneCoverage {
  std::int64_t holes = 0;    // empty pixel centres more than 2 cells inside the square
  std::int64_t spills = 0;   // covered pixel centres beyond the largest disc outside it
  std::string first_hole;    // the first view with a hole ("WxH zoom Z"), empty if none
  double median_radius = 0;  // the rule's median disc, in cells
};

// The jitteredPlane(200, 7) drawn with `rule` at the sizes 1x1, 7x5, 176x208, 320x240, 1280x960,
// 1920x1080 and zooms 0.25, 0.5, 1, 2, 4, 8, head-on.
PlaneCoverage jitteredPlaneCoverage(const SplatRule& rule);

struct View {
  int width, height;
  double zoom;
};

struct Closure {
  std::int64_t holes = 0;          // holes inside the surface, over all views
  std::int64_t outline_holes = 0;  // empty pixels of the closing nearer its outline
  std::int64_t covered = 0;        // covered pixels, over all views
  double worst_share = 0;          // the largest holes / covered of a single view
};

// The closure of `surface` (fitted into `fit`, sample spacing `spacing` in scan units) seen from
// `views` turned by `yaw`. With `pictures` a directory, also writes there WxH_zoomZ_holes.png per
// view (covered white, holes inside red, near the outline orange) and prints each view's share.
Closure measureClosure(const ReferenceSurface& surface, const prepare::CubeFit& fit, double spacing,
                       const std::vector<View>& views, Angle yaw, const std::string& pictures = {});

}  // namespace octopoint::tradeoff
