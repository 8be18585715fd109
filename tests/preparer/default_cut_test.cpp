// The preparer's default depth cut follows the sample reach (docs/splats.md, "The default depth
// cut"): airborne-like scans sampled 1 m apart (a regular grid of scan lines and irregular
// samples) prepared with octopoint-prepare's default --depths keep the depths finer than their
// samples that their measured reach draws whole, and depth auto draws them with at most 1% (grid)
// and 3% (irregular) of the surface the coarsest depth covers empty, box and smooth, at every size
// of the sweep. The voxel-count rule alone (the cut before) keeps depths 6 and 7 of both.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "codegen/depth_range.h"
#include "codegen/level_voxels.h"
#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "codegen/sample_reach.h"
#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/level_of_detail.h"
#include "tests/support/airborne_scans.h"
#include "tests/support/surface_cover.h"

namespace octopoint {
namespace {

using testing::AirborneSampling;

struct PreparedAirborne {
  prepare::PreparedModel prepared;
  std::vector<std::uint8_t> image;
  std::optional<ModelView> view;
  std::vector<int> depths;
};

// The scan prepared as octopoint-prepare does without --depths, or with `depths` given.
PreparedAirborne prepareAirborneScan(AirborneSampling sampling,
                                     const std::vector<int>& depths = {}) {
  prepare::PrepareOptions options;
  options.name = "airborne";
  options.depths = depths.empty() ? prepare::defaultDepths() : depths;
  options.stop_at_sparse_depth = depths.empty();
  PreparedAirborne model;
  model.prepared =
      prepare::prepareModel(testing::airborneScan(sampling, 1.0, 7), "airborne.ply", options);
  model.image = prepare::serializeModel(model.prepared);
  ModelIssue issue;
  model.view = ModelView::fromBytes(model.image, &issue);  // points into the moved image
  EXPECT_TRUE(model.view.has_value()) << describe(issue.error);
  for (const prepare::PreparedLevel& level : model.prepared.levels)
    model.depths.push_back(level.depth);
  return model;
}

// The voxel-count rule alone (the cut before), on all of the default range's levels.
std::vector<int> countRuleDepths(const PreparedAirborne& all) {
  std::vector<std::size_t> counts;
  for (const prepare::PreparedLevel& level : all.prepared.levels)
    counts.push_back(level.leaves.size());
  std::vector<int> depths = all.depths;
  depths.resize(prepare::denseDepthCount(counts));
  return depths;
}

std::string bytesOf(const PreparedAirborne& model) { return std::to_string(model.image.size()); }

// The sweep's sizes (scripts' tradeoff sweep), identity camera (the ground head-on), zoom 1.
constexpr std::array<std::pair<int, int>, 5> kSweepSizes = {
    {{176, 208}, {320, 240}, {640, 480}, {1280, 960}, {1920, 1080}}};

// Per mille of the coarsest depth's surface that depth auto leaves empty, in box or smooth splats.
int autoEmptyPerMille(const PreparedAirborne& model, int width, int height, bool smooth,
                      int* drawn_depth) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  const LevelView* level = autoLevel(*model.view, camera);
  EXPECT_NE(level, nullptr);
  if (level == nullptr) return 1000;
  *drawn_depth = level->depth;
  const std::vector<bool> reference =
      testing::referenceSurface(*model.view, model.depths.front(), camera);
  return testing::emptyPerMille(
      reference, testing::levelCover(*model.view, *level, camera,
                                     model.view->sampleReachOfDepth(level->depth), smooth));
}

// Why the cap (kMaxKeptSampleReach): the scans prepared at every default depth, each depth's
// voxels, bytes and measured reach, and which depths the cut leaves out. Past the cap a depth's
// voxels are the scan's samples again (the grid's depth 10 holds the 22,500 points its depth 8
// does), drawn as wide: bytes without detail.
void expectCutAtTheCap(const PreparedAirborne& all, std::size_t kept, const char* name) {
  std::vector<prepare::LevelVoxels> levels;
  for (const prepare::PreparedLevel& level : all.prepared.levels)
    levels.push_back(prepare::decodeLevel(level));
  std::int32_t coarse_reach = kOneSampleReach;
  for (std::size_t i = 1; i < levels.size(); ++i) {
    const prepare::MeasuredReach reach = prepare::measureReach(
        levels[i].keys, levels[i].depth, levels[i - 1].keys, levels[i - 1].depth, coarse_reach);
    const prepare::PreparedLevel& level = all.prepared.levels[i];
    std::printf("%s depth %d: %zu voxels, %zu bytes, reach %d/16%s%s\n", name, level.depth,
                level.leaves.size(), level.nodes.size() + level.leaves.size(), reach.reach,
                reach.whole_in_every_view ? "" : " (not whole)", i < kept ? "" : ", left out");
    if (i == kept) {
      EXPECT_TRUE(reach.reach > prepare::kMaxKeptSampleReach || !reach.whole_in_every_view)
          << name << " depth " << level.depth;
    }
    coarse_reach = reach.reach;
  }
}

void expectFinerDepthsKeptAndWhole(AirborneSampling sampling, const std::vector<int>& expected,
                                   int limit_per_mille, const char* name) {
  const PreparedAirborne model = prepareAirborneScan(sampling);
  ASSERT_TRUE(model.view.has_value());
  const PreparedAirborne all = prepareAirborneScan(sampling, prepare::defaultDepths());
  const std::vector<int> before = countRuleDepths(all);
  const PreparedAirborne cut_before = prepareAirborneScan(sampling, before);
  std::printf("%s: default cut keeps %s (%s bytes), the voxel-count rule %s (%s bytes)\n", name,
              prepare::describeDepths(model.depths).c_str(), bytesOf(model).c_str(),
              prepare::describeDepths(before).c_str(), bytesOf(cut_before).c_str());
  EXPECT_EQ(model.depths, expected) << name;
  EXPECT_LT(before.size(), expected.size()) << "the count rule alone keeps these depths too";
  expectCutAtTheCap(all, model.depths.size(), name);
  for (std::size_t i = 0; i < model.depths.size(); ++i) {
    std::printf("  depth %d: %zu voxels, reach %d/16\n", model.depths[i],
                model.prepared.levels[i].leaves.size(), model.view->sampleReach(int(i)));
  }
  for (const auto& [width, height] : kSweepSizes) {
    for (const bool smooth : {false, true}) {
      int depth = 0, depth_before = 0;
      const int empty = autoEmptyPerMille(model, width, height, smooth, &depth);
      const int empty_before = autoEmptyPerMille(cut_before, width, height, smooth, &depth_before);
      std::printf("  %dx%d %s: depth %d %d.%d%% empty (the count rule's cut: depth %d %d.%d%%)\n",
                  width, height, smooth ? "smooth" : "box", depth, empty / 10, empty % 10,
                  depth_before, empty_before / 10, empty_before % 10);
      EXPECT_LE(empty, limit_per_mille) << name << ' ' << width << 'x' << height;
      // From 640x480 on the finest kept depth's voxels are over a pixel: depth auto counts it.
      if (width >= 640) {
        EXPECT_EQ(depth, model.depths.back()) << name << ' ' << width << 'x' << height;
      }
    }
  }
}

TEST(DefaultDepthCut, KeepsTheGridScanDepthsItsReachDrawsWhole) {
  expectFinerDepthsKeptAndWhole(AirborneSampling::kGrid, {6, 7, 8, 9}, 10, "grid");
}

TEST(DefaultDepthCut, KeepsTheIrregularScanDepthsItsReachDrawsWhole) {
  expectFinerDepthsKeptAndWhole(AirborneSampling::kIrregular, {6, 7, 8}, 30, "irregular");
}

// The densely sampled real scans keep the cut they had: the default model's scan (cropped and
// turned as scripts/regenerate-models does) depths 6..8, although its depth 9 measures a reach of
// two footprints (whole seen from the front, not from above).
TEST(DefaultDepthCut, TheDefaultModelsScanKeepsDepths6To8) {
  const std::filesystem::path path =
      std::filesystem::path(OCTOPOINT_TEST_SCANS_DIR) / "milk_cartoon_all_small_clorox.pcd";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " absent (data/ not linked)";
  prepare::PrepareOptions options;
  options.name = "tabletop";
  options.depths = prepare::defaultDepths();
  options.stop_at_sparse_depth = true;
  options.axes = prepare::ScanAxes::kYUp;
  options.crop = prepare::parseCropBox("--crop", "-0.35,-0.25,-1.1,0.35,0.45,-0.45");
  const prepare::PreparedModel model =
      prepare::prepareModel(prepare::loadScan(path), path.string(), options);
  std::vector<int> depths;
  for (const prepare::PreparedLevel& level : model.levels) depths.push_back(level.depth);
  EXPECT_EQ(depths, (std::vector<int>{6, 7, 8}));
  EXPECT_EQ(model.sparse_depths_dropped, (std::vector<int>{9, 10}));
}

}  // namespace
}  // namespace octopoint
