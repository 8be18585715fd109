// octopoint-reference-truth: where does a scan's surface end? The disc reference
// (lab/reference_surface.h kSplatRule), the depth image's mesh (kMeshExtensionSteps) and
// octopoint's model of the same points, each against the exact silhouette of a sampled square
// (lab/reference_truth.h, docs/tradeoff.md "The reference render"). lab/scripts/reference-truth
// runs it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "codegen/depth_range.h"
#include "lab/reference_closure.h"
#include "lab/reference_render.h"
#include "lab/reference_truth.h"
#include "lab/splat_rule_flag.h"
#include "lab/tradeoff.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"

namespace {

using namespace octopoint;
using tradeoff::Sampling;
using tradeoff::TruthMatch;

constexpr const char* kUsage =
    R"(usage: octopoint-reference-truth [--cells N] [--lines N] [--strays K] [--rule RULE]
                                 [--outline K,GAP,SCALE,SHIFT] [--mesh-extension STEPS]
                                 [--organized-only] [--outline-sweep]

Prints (markdown) how far the reference's discs (lab/reference_surface.h) and octopoint's model of
the same points reach past the true edge of a sampled square, and the holes each leaves inside it,
as shares of the truth's pixels (docs/tradeoff.md, "The reference render"). The square is sampled
(a) jittered, one point anywhere in each of N x N cells, and (b) as a line scanner, N lines with
points along each 1.5 times closer; the square is turned 20 degrees in its plane; each with
and without K stray returns 0.5 to 3 sample steps off its edge; seen head-on and turned 30
degrees, at sizes and zooms where the sample spacing spans about 1 to 10 pixels. octopoint draws
a model of depth d, whose voxel is to the spacing what lms400's depth 9 is to its own (4.0 mm /
1.77 mm), and the default model at depth auto.
(c) A depth camera (an organized scan: rays from the origin through a grid's pixel centres, NaN
where they miss) sees the square N grid steps across from 1 and 2 times its side away, tilted 0
to 60 degrees; its mesh reference is drawn ending at the last samples and with the extension.

  --cells N     samples across the square (jittered), 16..400 (default 73)
  --lines N     lines across the square (line scanner), 16..400 (default 139)
  --strays K    stray returns in the cases with strays, 1..1000 (default 40)
  --rule K,SCALE,QUANTILE[,OFFSET,EDGE_SCALE]  the reference's disc rule (default kSplatRule);
                K 1..64, SCALE 0.1..4, QUANTILE 0..1, OFFSET 0..1, EDGE_SCALE 0..4
  --mesh-extension STEPS  the depth image mesh's strip past its boundary, in grid steps, 0..4
                (default kMeshExtensionSteps)
  --organized-only  only the depth camera's cases
  --outline K,GAP,SCALE,SHIFT  outline points (K nearest neighbours leave an angular gap wider
                than GAP degrees) get discs of SCALE x d8 moved inward by SHIFT x their radius
                (lab/reference_surface.h SplatRule); K 3..64, GAP 30..359, SCALE 0..4, SHIFT
                0..1, or none (default kSplatRule's; --rule keeps it)
  --outline-sweep  instead, for outline detectors and scales, the reach of the reference over
                every size 1x1..1920x1080 and zoom 0.25..8 (tests/lab/reference_truth_test.cpp's
                views) on the four scanned squares, and the holes it leaves in the 200 x 200
                jittered plane (lab/reference_closure.h)
  -h, --help    show this help

On any error prints one line on stderr and exits with status 1.
)";

// lms400's depth-9 voxel (its 2.06 m cube / 512 = 4.02 mm) over its sample spacing h = 1.77 mm.
constexpr double kVoxelPerSpacing = 4.02 / 1.77;
// Holes count as inside when more than this many sample spacings inside the truth's outline.
constexpr double kInsetSpacings = 2;

struct View {
  int width, height;
  double zoom;
};
const std::vector<View> kViews = {{176, 208, 0.5}, {320, 240, 0.5}, {320, 240, 1},
                                  {640, 480, 1},   {1280, 960, 1},  {1920, 1080, 1}};

Camera cameraFor(const View& view, int yaw_degrees) {
  Camera camera;
  camera.width = view.width;
  camera.height = view.height;
  camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(std::lround(view.zoom * Q16::kOneRaw)));
  camera.yaw = Angle::fromDegrees(yaw_degrees);
  return camera;
}

// octopoint's silhouette of `level` for `camera` (the default variant, footprint splats).
cv::Mat octopointCovered(const LevelView& level, const Camera& camera) {
  FrameSetup setup;
  if (buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup) != CameraError::kNone)
    throw cli::Error("the camera is refused at depth " + std::to_string(level.depth));
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  if (!renderLevel(defaultVariant(), level, setup, frame))
    throw cli::Error(std::string("draw refused: ") + describe(checkRender(level, setup, frame)));
  cv::Mat covered = cv::Mat::zeros(camera.height, camera.width, CV_8U);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x)
      if (frame.covered(x, y)) covered.at<std::uint8_t>(y, x) = 255;
  return covered;
}

// spill / holes (inner holes) / reach / signed reach (spill - holes over the outline), in h.
std::string signedCellOf(const TruthMatch& match, double spacing_px) {
  char text[112];
  std::snprintf(text, sizeof text, "%.2f%% / %.2f%% (%.2f%%) / %.2f h / %+.2f h",
                100 * match.spillShare(), 100 * match.holeShare(), 100 * match.innerHoleShare(),
                match.meanReachPx() / spacing_px, match.meanOffsetPx() / spacing_px);
  return text;
}

std::string cellOf(const TruthMatch& match, double spacing_px) {
  char text[96];
  std::snprintf(text, sizeof text, "%.2f%% / %.2f%% (%.2f%%) / %.2f h", 100 * match.spillShare(),
                100 * match.holeShare(), 100 * match.innerHoleShare(),
                match.meanReachPx() / spacing_px);
  return text;
}

// One table row per view, then one over all views, of how each of `references` (reference
// surfaces of `scene`'s points), octopoint's model `matched` at its one depth, and `automatic` at
// depth auto match the truth; `cell` formats a match.
void printViews(const tradeoff::TruthScan& truth, const tradeoff::Scene& scene, int yaw,
                const std::vector<const tradeoff::Scene*>& references,
                const tradeoff::InMemoryModel& matched, const tradeoff::InMemoryModel& automatic,
                std::string (*cell)(const TruthMatch&, double)) {
  std::vector<TruthMatch> all(references.size() + 2);
  double spacing_sum = 0;
  for (const View& view : kViews) {
    const Camera camera = cameraFor(view, yaw);
    const double spacing_px =
        truth.spacing * tradeoff::ScreenProjection(scene.fit, camera).pixelsPerUnit();
    const int inset = static_cast<int>(std::ceil(kInsetSpacings * spacing_px));
    const cv::Mat exact = tradeoff::truthMask(truth, scene.fit, camera);
    const LevelView* chosen = autoLevel(*automatic.view, camera);
    if (chosen == nullptr) throw cli::Error("depth auto refused the view");
    std::vector<TruthMatch> match;
    for (const tradeoff::Scene* reference : references)
      match.push_back(tradeoff::matchTruth(
          exact, tradeoff::referenceFor(*reference, camera).silhouette, inset));
    match.push_back(
        tradeoff::matchTruth(exact, octopointCovered(matched.view->finestLevel(), camera), inset));
    match.push_back(tradeoff::matchTruth(exact, octopointCovered(*chosen, camera), inset));
    for (std::size_t k = 0; k < match.size(); ++k) all[k].add(match[k]);
    spacing_sum += spacing_px * static_cast<double>(match[0].outline);
    char head[64];
    std::snprintf(head, sizeof head, "| %dx%d zoom %g | %.2f |", view.width, view.height, view.zoom,
                  spacing_px);
    std::string row = head;
    for (std::size_t k = 0; k + 1 < match.size(); ++k)
      row.append(" ").append(cell(match[k], spacing_px)).append(" |");
    row.append(" ").append(std::to_string(chosen->depth)).append(" | ");
    row.append(cell(match.back(), spacing_px)).append(" |");
    std::printf("%s\n", row.c_str());
  }
  // Over all views: the reach in spacings weighs each view by its outline.
  const double spacing_px = spacing_sum / static_cast<double>(all[0].outline);
  std::string row = "| all views | |";
  for (std::size_t k = 0; k + 1 < all.size(); ++k)
    row.append(" ").append(cell(all[k], spacing_px)).append(" |");
  row.append(" | ").append(cell(all.back(), spacing_px)).append(" |");
  std::printf("%s\n", row.c_str());
  std::fflush(stdout);
}

void runCase(Sampling sampling, int cells, int strays, int yaw, const tradeoff::SplatRule& rule) {
  const tradeoff::TruthScan truth = tradeoff::squareScan(sampling, cells, strays, 11);
  tradeoff::Scene scene;
  scene.scan_path = "synthetic square";
  scene.scan = truth.points;
  scene.prepare.name = "truth";
  scene.fit = prepare::fitCube(truth.points.positions, scene.scan_path);
  scene.surface = tradeoff::buildReferenceSurface(truth.points, rule);
  const int depth =
      static_cast<int>(std::lround(std::log2(scene.fit.edge / (kVoxelPerSpacing * truth.spacing))));
  const auto matched = tradeoff::prepareInMemory(scene, {depth});
  const auto automatic = tradeoff::prepareInMemory(scene, prepare::defaultDepths(), true);
  std::printf(
      "\n### %s, %d stray returns, yaw %d\n\n%zu points, h = %.4g, depth %d: voxel = %.2f h\n\n"
      "| view | h in px | reference | octopoint depth %d | depth auto | octopoint depth auto |\n"
      "|---|---|---|---|---|---|\n",
      sampling == Sampling::kJittered ? "jittered" : "line scanner", strays, yaw,
      truth.points.positions.size(), truth.spacing, depth,
      scene.fit.edge / (1 << depth) / truth.spacing, depth);
  printViews(truth, scene, yaw, {&scene}, *matched, *automatic, cellOf);
}

// The depth camera's square (lab/reference_truth.h depthCameraScan): its mesh ending at the last
// samples, its mesh with `extension` grid steps past them, and octopoint's models.
void runOrganizedCase(int across, double distance, double tilt, int yaw, double extension) {
  const tradeoff::TruthScan truth = tradeoff::depthCameraScan(across, distance, tilt, 11);
  tradeoff::Scene scene;
  scene.scan_path = "synthetic depth image";
  scene.scan = truth.points;
  scene.prepare.name = "truth";
  scene.fit = prepare::fitCube(truth.points.positions, scene.scan_path);
  scene.surface = tradeoff::buildReferenceSurface(truth.points, tradeoff::kSplatRule, extension);
  tradeoff::Scene before = scene;
  before.surface = tradeoff::buildReferenceSurface(truth.points, tradeoff::kSplatRule, 0);
  const int depth =
      static_cast<int>(std::lround(std::log2(scene.fit.edge / (kVoxelPerSpacing * truth.spacing))));
  const auto matched = tradeoff::prepareInMemory(scene, {depth});
  const auto automatic = tradeoff::prepareInMemory(scene, prepare::defaultDepths(), true);
  std::printf(
      "\n### depth camera, distance %g, tilt %g, yaw %d\n\n%u x %u grid, %zu points, h = %.4g, "
      "%zu triangles (%zu with the extension), depth %d: voxel = %.2f h\n\n"
      "| view | h in px | mesh, extension 0 | mesh, extension %g | octopoint depth %d | depth auto "
      "| octopoint depth auto |\n|---|---|---|---|---|---|---|\n",
      distance, tilt, yaw, truth.points.grid_width, truth.points.grid_height,
      truth.points.positions.size(), truth.spacing, before.surface.triangles.size(),
      scene.surface.triangles.size(), depth, scene.fit.edge / (1 << depth) / truth.spacing,
      extension, depth);
  printViews(truth, scene, yaw, {&before, &scene}, *matched, *automatic, signedCellOf);
}

// The measurement that chose kSplatRule's outline rule: per detector (neighbours, gap), the share
// of points it calls outline on each square and how many it calls outline more than 2 cells
// inside the 200 x 200 jittered plane; per outline scale, each square's reach over every view and
// the plane's holes.
void outlineSweep(int cells, int lines, int strays, tradeoff::SplatRule base,
                  const std::vector<int>& neighbours, const std::vector<double>& gaps,
                  const std::vector<std::pair<double, double>>& discs) {
  struct Square {
    const char* name;
    tradeoff::TruthScan scan;
  };
  const std::vector<Square> squares = {
      {"jittered", tradeoff::squareScan(Sampling::kJittered, cells, 0, 11)},
      {"jittered + strays", tradeoff::squareScan(Sampling::kJittered, cells, strays, 11)},
      {"lines", tradeoff::squareScan(Sampling::kLines, lines, 0, 11)},
      {"lines + strays", tradeoff::squareScan(Sampling::kLines, lines, strays, 11)}};
  const prepare::Scan plane = tradeoff::jitteredPlane(200, 7);
  std::printf(
      "\nEach square cell: reach / signed reach (h) / holes more than 2 h inside (pixels); plane: "
      "holes more than 2 cells inside the 200 x 200 jittered plane (pixels), points called outline "
      "more than 2 cells inside it.\n\n| detector | scale | outline share (squares) |");
  for (const Square& square : squares) std::printf(" %s |", square.name);
  std::printf(" plane holes | plane false outlines |\n|---|---|---|---|---|---|---|---|---|\n");
  const auto row = [&](const tradeoff::SplatRule& rule, const std::string& shares,
                       std::int64_t false_outlines) {
    if (rule.outline_neighbours == 0)
      std::printf("| none | - | - |");
    else
      std::printf("| %d, %g deg | %.2f, shift %.2f | %s |", rule.outline_neighbours,
                  rule.outline_gap_degrees, rule.outline_scale, rule.outline_shift, shares.c_str());
    for (const Square& square : squares) {
      const tradeoff::TruthReach reach = tradeoff::reachOverViews(
          square.scan, tradeoff::buildReferenceSurface(square.scan.points, rule));
      std::printf(" %.2f / %+.2f / %lld |", reach.spacings, reach.signed_spacings,
                  static_cast<long long>(reach.inner_holes));
    }
    const tradeoff::PlaneCoverage coverage = tradeoff::jitteredPlaneCoverage(rule);
    std::printf(" %lld | %lld |\n", static_cast<long long>(coverage.holes),
                static_cast<long long>(false_outlines));
    std::fflush(stdout);
  };
  base.outline_neighbours = 0;
  row(base, "-", 0);
  for (const int neighbour : neighbours) {
    for (const double gap : gaps) {
      std::string shares;
      for (const Square& square : squares) {
        const auto outline = tradeoff::outlinePoints(square.scan.points.positions, neighbour, gap);
        char text[16];
        std::snprintf(text, sizeof text, "%s%.1f%%", shares.empty() ? "" : " ",
                      100.0 * static_cast<double>(std::count(outline.begin(), outline.end(), 1)) /
                          static_cast<double>(outline.size()));
        shares += text;
      }
      const auto outline = tradeoff::outlinePoints(plane.positions, neighbour, gap);
      std::int64_t false_outlines = 0;
      const float inside = 1.0f - 2 * 2.0f / 200;
      for (std::size_t i = 0; i < outline.size(); ++i) {
        const auto& p = plane.positions[i];
        false_outlines += outline[i] != 0 && std::fabs(p[0]) < inside && std::fabs(p[1]) < inside;
      }
      for (const auto& [scale, shift] : discs) {
        tradeoff::SplatRule rule = base;
        rule.outline_neighbours = neighbour;
        rule.outline_gap_degrees = gap;
        rule.outline_scale = scale;
        rule.outline_shift = shift;
        row(rule, shares, false_outlines);
      }
    }
  }
}

struct TruthOptions {
  // The defaults put lms400's voxel-to-spacing ratio (2.27) at depth 6 (jittered) and 7 (lines).
  int cells = 73, lines = 139, strays = 40;
  tradeoff::SplatRule rule = tradeoff::kSplatRule;
  double extension = tradeoff::kMeshExtensionSteps;
  bool organized_only = false, outline_sweep = false;
};

// Returns nullopt when --help was asked for (after printing the usage).
std::optional<TruthOptions> parseTruthOptions(int argc, char** argv) {
  TruthOptions options;
  tradeoff::SplatRule& rule = options.rule;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << kUsage;
      return std::nullopt;
    } else if (args.is("--cells")) {
      const std::string name = args.name();
      options.cells = cli::parseInt(name, args.value(), 16, 400);
    } else if (args.is("--lines")) {
      const std::string name = args.name();
      options.lines = cli::parseInt(name, args.value(), 16, 400);
    } else if (args.is("--strays")) {
      const std::string name = args.name();
      options.strays = cli::parseInt(name, args.value(), 1, 1000);
    } else if (args.is("--rule")) {
      const std::string name = args.name();
      const tradeoff::SplatRule outline = rule;
      rule = tradeoff::parseSplatRule(name, args.value());
      rule.outline_neighbours = outline.outline_neighbours;
      rule.outline_gap_degrees = outline.outline_gap_degrees;
      rule.outline_scale = outline.outline_scale;
      rule.outline_shift = outline.outline_shift;
    } else if (args.is("--mesh-extension")) {
      const std::string name = args.name();
      options.extension = cli::parseReal(name, args.value(), 0.0, 4.0);
    } else if (args.is("--organized-only")) {
      options.organized_only = true;
    } else if (args.is("--outline")) {
      const std::string name = args.name();
      tradeoff::parseOutlineRule(name, args.value(), rule);
    } else if (args.is("--outline-sweep")) {
      options.outline_sweep = true;
    } else {
      args.refuseUnknown();
    }
  }
  return options;
}

int run(int argc, char** argv) {
  const std::optional<TruthOptions> parsed = parseTruthOptions(argc, argv);
  if (!parsed) return 0;
  const auto& [cells, lines, strays, rule, extension, organized_only, outline_sweep] = *parsed;
  if (outline_sweep) {
    // (scale, shift) of the outline's discs: smaller, or as large and moved inward.
    outlineSweep(cells, lines, strays, rule, {16, 24}, {120, 150},
                 {{0.4, 0},
                  {0.45, 0},
                  {0.5, 0},
                  {0.55, 0},
                  {0.7, 0.3},
                  {0.7, 0.4},
                  {0.7, 0.5},
                  {0.7, 0.55},
                  {0.7, 0.6},
                  {0.6, 0.2},
                  {0.6, 0.3},
                  {0.6, 0.4}});
    return 0;
  }
  std::printf(
      "Each cell: spill / holes (holes more than %g h inside the outline) / mean reach past the "
      "edge (spill over the truth's outline, in sample spacings h), as shares of the truth's "
      "pixels.\nReference rule: k %d, scale %.2f, cap quantile %.2f, edge offset %.2f, edge scale "
      "%.2f, outline %d neighbours, gap %.0f degrees, scale %.2f, shift %.2f\n",
      kInsetSpacings, rule.neighbour, rule.scale, rule.cap_quantile, rule.edge_offset,
      rule.edge_scale, rule.outline_neighbours, rule.outline_gap_degrees, rule.outline_scale,
      rule.outline_shift);
  for (const Sampling sampling : {Sampling::kJittered, Sampling::kLines}) {
    if (organized_only) break;
    for (const int stray_count : {0, strays}) {
      const int across = sampling == Sampling::kLines ? lines : cells;
      for (const int yaw : {0, 30}) runCase(sampling, across, stray_count, yaw, rule);
    }
  }
  std::printf(
      "\nDepth camera: each cell spill / holes (inner) / reach / signed reach ((spill - holes) "
      "over the outline, in h; negative: short of the true edge).\n");
  struct Pose {
    double distance, tilt;
  };
  for (const Pose pose : {Pose{4, 0}, Pose{4, 30}, Pose{4, 60}, Pose{2, 45}}) {
    for (const int yaw : {0, 30}) runOrganizedCase(cells, pose.distance, pose.tilt, yaw, extension);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-reference-truth", argc, argv, run);
}
