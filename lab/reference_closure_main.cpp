// octopoint-reference-closure: the measurements that chose the unorganized-scan reference's splat
// rule (lab/reference_surface.h kSplatRule, docs/tradeoff.md "The reference render"), on the
// reference alone (lab/reference_closure.h). lab/scripts/reference-closure runs it on lms400.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "codegen/cube_fit.h"
#include "codegen/prepare.h"
#include "lab/reference_closure.h"
#include "lab/reference_surface.h"
#include "lab/splat_rule_flag.h"

namespace {

using namespace octopoint;
using tradeoff::SplatRule;

constexpr const char* kUsage =
    R"(usage: octopoint-reference-closure SCAN [--yaw DEG] [--pictures DIR [--rule K,SCALE,QUANTILE]
                                  [--no-outline] [--sparse F]]

Prints (markdown) how closed the surface reference of an unorganized scan is, for disc radius =
scale x the distance to the k-th nearest neighbour, that distance capped at a quantile of the
scan's (lab/reference_surface.h):
1. A jittered plane (one point anywhere in each of 200 x 200 cells) at every size 1x1..1920x1080
   and zoom 0.25..8: per k, the smallest scale (steps of 0.05) that leaves no hole, and the median
   disc it gives, in cells.
2. SCAN, turned by --yaw, at 640x480 zoom 8, 1280x960 zoom 4 and 8, 1920x1080 zoom 2, 4 and 8:
   holes inside the morphological closing of the covered set (lab/reference_closure.h), as a share
   of the covered pixels over all views (the worst view in brackets; after the comma, the empty
   pixels of the closing near its outline), per k, cap quantile and scale.

  --yaw DEG         the view's yaw, |DEG| <= 1e6 (default 30)
  --pictures DIR    instead, for one rule, write WxH_zoomZ_holes.png per view of table 2 into
                    the directory DIR (covered white, holes red, empty near the outline
                    orange) and print its shares
  --rule K,SCALE,QUANTILE[,EDGE_OFFSET,EDGE_SCALE]  that rule (default the reference's,
                    kSplatRule); K 1..64, SCALE 0.1..4, QUANTILE 0..1, EDGE_OFFSET 0..1,
                    EDGE_SCALE 0..4 (lab/reference_surface.h SplatRule), with kSplatRule's
                    outline discs and sparse outliers
  --no-outline      the rule without outline discs (every point's disc on its point)
  --sparse F        the rule's sparse outliers: a point whose k-th neighbour is more than F
                    times as far as the median point's is drawn as a stray return; F 0 (none)
                    or 1..10 (default kSplatRule's, 1.9)
  -h, --help        show this help

On any error prints one line on stderr and exits with status 1.
)";

const std::vector<tradeoff::View> kViews = {{640, 480, 8},   {1280, 960, 4},  {1280, 960, 8},
                                            {1920, 1080, 2}, {1920, 1080, 4}, {1920, 1080, 8}};

double median(std::vector<float> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

void printJitteredPlaneTable() {
  std::printf(
      "Jittered plane: the smallest scale that closes it\n\n"
      "| k | scale | median disc (cells) |\n|---|---|---|\n");
  for (const int neighbour : {4, 6, 8, 10, 12, 16}) {
    for (int hundredths = 50; hundredths <= 150; hundredths += 5) {
      const tradeoff::PlaneCoverage coverage =
          tradeoff::jitteredPlaneCoverage({neighbour, hundredths / 100.0, 0.9});
      if (coverage.holes > 0) continue;
      std::printf("| %d | %.2f | %.3f |\n", neighbour, hundredths / 100.0, coverage.median_radius);
      std::fflush(stdout);
      break;
    }
  }
}

struct ScanSurface {
  prepare::Scan points;
  prepare::CubeFit fit;
  double spacing = 0;  // median nearest-neighbour distance
};

tradeoff::Closure closureOf(const ScanSurface& scan, const std::vector<float>& distance,
                            const SplatRule& rule, Angle yaw, const std::string& pictures = {}) {
  tradeoff::ReferenceSurface surface;
  if (rule.outline_neighbours > 0) {
    surface = tradeoff::buildReferenceSurface(scan.points, rule);  // moves outline discs inward
  } else {
    surface.positions = scan.points.positions;
    const std::vector<float> offsets =
        rule.edge_offset > 0 ? tradeoff::centroidOffsets(scan.points.positions, rule.neighbour)
                             : std::vector<float>{};
    surface.splat_radius =
        tradeoff::splatRadii(distance, rule, tradeoff::strayPoints(distance, rule, offsets));
  }
  return tradeoff::measureClosure(surface, scan.fit, scan.spacing, kViews, yaw, pictures);
}

std::string percent(std::int64_t part, std::int64_t whole) {
  char text[32];
  std::snprintf(
      text, sizeof text, "%.3f%%",
      100.0 * static_cast<double>(part) / static_cast<double>(std::max<std::int64_t>(1, whole)));
  return text;
}

void printScanTable(const ScanSurface& scan, Angle yaw) {
  const SplatRule chosen = tradeoff::kSplatRule;
  const std::vector<double> scales = {0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  std::printf(
      "\nThe scan: holes inside the closing of its covered set\n\n"
      "| k | cap quantile | median k-th distance | cap |");
  for (const double scale : scales) std::printf(" scale %.1f |", scale);
  std::printf("\n|---|---|---|---|");
  for (std::size_t i = 0; i < scales.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (const int neighbour : {4, 6, 8, 10, 12}) {
    const std::vector<float> distance =
        tradeoff::neighbourDistances(scan.points.positions, neighbour);
    for (const double quantile : {0.75, 0.9, 0.99}) {
      if (neighbour != chosen.neighbour && quantile != chosen.cap_quantile) continue;
      const std::vector<float> cap = tradeoff::splatRadii(distance, {neighbour, 1.0, quantile});
      std::printf("| %d | %.2f | %.3g | %.3g |", neighbour, quantile, median(distance),
                  static_cast<double>(*std::max_element(cap.begin(), cap.end())));
      for (const double scale : scales) {
        const tradeoff::Closure closure =
            closureOf(scan, distance, {neighbour, scale, quantile}, yaw);
        std::printf(" %s (%.2f%%), %s |", percent(closure.holes, closure.covered).c_str(),
                    100.0 * closure.worst_share,
                    percent(closure.outline_holes, closure.covered).c_str());
        std::fflush(stdout);
      }
      std::printf("\n");
    }
  }
}

int run(int argc, char** argv) {
  std::string scan_path, pictures;
  Angle yaw = Angle::fromDegrees(30);
  SplatRule picture_rule = tradeoff::kSplatRule;
  bool no_outline = false;
  double sparse_factor = tradeoff::kSplatRule.sparse_factor;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << kUsage;
      return 0;
    } else if (args.is("--yaw")) {
      yaw = cli::parseDegrees(args.name(), args.value());
    } else if (args.is("--pictures")) {
      pictures = args.value();
    } else if (args.is("--rule")) {
      const std::string name = args.name();
      const SplatRule outline = picture_rule;
      picture_rule = tradeoff::parseSplatRule(name, args.value());
      picture_rule.outline_neighbours = outline.outline_neighbours;
      picture_rule.outline_gap_degrees = outline.outline_gap_degrees;
      picture_rule.outline_scale = outline.outline_scale;
      picture_rule.outline_shift = outline.outline_shift;
    } else if (args.is("--no-outline")) {
      no_outline = true;
    } else if (args.is("--sparse")) {
      const std::string name = args.name();
      sparse_factor = tradeoff::parseSparseFactor(name, args.value());
    } else if (args.isPlain() && scan_path.empty()) {
      scan_path = args.current();
    } else {
      args.refuseUnknown();
    }
  }
  if (scan_path.empty()) throw cli::Error("no SCAN given (see --help)");
  if (no_outline) picture_rule.outline_neighbours = 0;
  picture_rule.sparse_factor = sparse_factor;
  std::error_code error;
  if (!pictures.empty() && !std::filesystem::is_directory(pictures, error))
    throw cli::Error("--pictures: " + cli::inQuotes(pictures) + " is not a directory");
  ScanSurface scan;
  scan.points = prepare::modelPoints(prepare::loadScan(scan_path), scan_path, {});
  if (scan.points.positions.size() < 2) throw cli::Error(scan_path + ": fewer than 2 points");
  scan.fit = prepare::fitCube(scan.points.positions, scan_path);
  scan.spacing = median(tradeoff::neighbourDistances(scan.points.positions, 1));
  std::printf("%s: %zu points, median nearest-neighbour distance h = %.4g (cube edge %.4g)\n\n",
              scan_path.c_str(), scan.points.positions.size(), scan.spacing, scan.fit.edge);
  if (!pictures.empty()) {
    const tradeoff::Closure closure =
        closureOf(scan, tradeoff::neighbourDistances(scan.points.positions, picture_rule.neighbour),
                  picture_rule, yaw, pictures);
    std::printf(
        "k %d, scale %.2f, cap quantile %.2f, edge offset %.2f, edge scale %.2f, outline %d "
        "neighbours gap %.0f degrees scale %.2f shift %.2f, sparse factor %.2f: holes inside %s of "
        "covered (worst view %.3f%%), empty near the outline %s\n",
        picture_rule.neighbour, picture_rule.scale, picture_rule.cap_quantile,
        picture_rule.edge_offset, picture_rule.edge_scale, picture_rule.outline_neighbours,
        picture_rule.outline_gap_degrees, picture_rule.outline_scale, picture_rule.outline_shift,
        picture_rule.sparse_factor, percent(closure.holes, closure.covered).c_str(),
        100.0 * closure.worst_share, percent(closure.outline_holes, closure.covered).c_str());
    return 0;
  }
  printJitteredPlaneTable();
  printScanTable(scan, yaw);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-reference-closure", argc, argv, run);
}
