// Samples coarser than the voxel (docs/splats.md): airborne-like scans on a 1 m grid of scan lines
// and at 1 m irregular spacing, in a 225 m cube, drawn at depths whose voxels are finer than that
// spacing. Widened by the reach the preparer measures (codegen/sample_reach.h), box and smooth
// splats leave at most 1% (grid) and 3% (irregular) of the surface the coarsest depth covers
// empty; one footprint leaves the confetti and the grid of empty lines the issue shows.
#include "codegen/sample_reach.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "codegen/depth_range.h"
#include "codegen/level_voxels.h"
#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "tests/support/airborne_scans.h"
#include "tests/support/surface_cover.h"

namespace octopoint {
namespace {

using testing::AirborneSampling;

constexpr int kReferenceDepth = 6;  // 3.5 m voxels: every one of them sampled
constexpr std::array<int, 3> kFineDepths = {7, 8, 9};

struct AirborneModel {
  prepare::PreparedModel prepared;
  std::vector<std::uint8_t> image;
  std::optional<ModelView> view;
};

AirborneModel prepareAirborne(AirborneSampling sampling) {
  prepare::PrepareOptions options;
  options.name = "airborne";
  options.depths = {kReferenceDepth, 7, 8, 9};
  AirborneModel model;
  model.prepared =
      prepare::prepareModel(testing::airborneScan(sampling, 1.0, 7), "airborne.ply", options);
  model.image = prepare::serializeModel(model.prepared);
  ModelIssue issue;
  model.view = ModelView::fromBytes(model.image, &issue);  // the view points into the moved image
  EXPECT_TRUE(model.view.has_value()) << describe(issue.error);
  return model;
}

std::int32_t measuredReach(const AirborneModel& model, int depth) {
  std::vector<prepare::LevelVoxels> levels;
  for (const prepare::PreparedLevel& level : model.prepared.levels)
    levels.push_back(prepare::decodeLevel(level));
  const std::vector<std::int32_t> reaches = prepare::measureSampleReaches(levels);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (levels[i].depth == depth) return reaches[i];
  }
  ADD_FAILURE() << "no depth " << depth;
  return kOneSampleReach;
}

// Which pixels a level covers: its box frame, or its smooth frame (blended outline); the frame is
// written as `picture`.ppm into OCTOPOINT_SAMPLE_REACH_PICTURES when that is set.
std::vector<bool> coverage(const ModelView& model, int depth, const Camera& camera,
                           std::int32_t reach, bool smooth, const std::string& picture) {
  const char* folder = std::getenv("OCTOPOINT_SAMPLE_REACH_PICTURES");
  const std::vector<bool> covered = testing::levelCover(
      model, *model.levelOfDepth(depth), camera, reach, smooth,
      folder != nullptr ? std::string(folder) + "/" + picture + ".ppm" : std::string());
  EXPECT_FALSE(covered.empty()) << picture;
  return covered;
}

Camera airborneCamera(int width, int height) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  return camera;
}

void expectHoleFree(AirborneSampling sampling, int limit_per_mille, const char* name) {
  const AirborneModel model = prepareAirborne(sampling);
  ASSERT_TRUE(model.view.has_value());
  for (const int depth : kFineDepths) {
    const std::int32_t reach = measuredReach(model, depth);
    for (const auto& [width, height] : {std::pair{480, 360}, {640, 480}, {1280, 960}}) {
      const Camera camera = airborneCamera(width, height);
      const std::vector<bool> reference =
          testing::referenceSurface(*model.view, kReferenceDepth, camera);
      for (const bool smooth : {false, true}) {
        const std::string picture = std::string(name) + "_d" + std::to_string(depth) + "_" +
                                    std::to_string(width) + (smooth ? "_smooth" : "_box");
        const int before = testing::emptyPerMille(
            reference,
            coverage(*model.view, depth, camera, kOneSampleReach, smooth, picture + "_unwidened"));
        const int after = testing::emptyPerMille(
            reference, coverage(*model.view, depth, camera, reach, smooth, picture));
        std::printf("%s depth %d %dx%d %s: reach %d/16, empty %d.%d%% -> %d.%d%%\n", name, depth,
                    width, height, smooth ? "smooth" : "box", reach, before / 10, before % 10,
                    after / 10, after % 10);
        EXPECT_LE(after, limit_per_mille) << picture << " reach " << reach;
        // Depths 8 and 9 (0.88 and 0.44 m voxels under 1 m samples) need the reach: without it
        // they are the confetti and the grid of empty lines (the test fails unwidened).
        if (depth >= 8) {
          EXPECT_GT(before, limit_per_mille) << picture;
        }
      }
    }
  }
}

TEST(SampleReach, GridScanLinesLeaveAtMostOnePercentOfTheSurfaceEmpty) {
  expectHoleFree(AirborneSampling::kGrid, 10, "grid");
}

TEST(SampleReach, IrregularSamplesLeaveAtMostThreePercentOfTheSurfaceEmpty) {
  expectHoleFree(AirborneSampling::kIrregular, 30, "irregular");
}

// The real scans' densely sampled depths (the default model's 6..8, lms400's) need no reach: once
// a model carries the measured reach, their frames are what they were.
TEST(SampleReach, DenselySampledDepthsOfTheRealScansNeedOneFootprint) {
  for (const char* name : {"milk_cartoon_all_small_clorox.pcd", "table_scene_lms400.pcd"}) {
    const std::filesystem::path path = std::filesystem::path(OCTOPOINT_TEST_SCANS_DIR) / name;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " absent (data/ not linked)";
    prepare::PrepareOptions options;
    options.name = "real";
    options.depths = {6, 7, 8, 9, 10};
    if (std::string(name).starts_with("milk")) {  // the default model (scripts/regenerate-models)
      options.axes = prepare::ScanAxes::kYUp;
      options.crop = prepare::parseCropBox("--crop", "-0.35,-0.25,-1.1,0.35,0.45,-0.45");
    }
    const prepare::PreparedModel model =
        prepare::prepareModel(prepare::loadScan(path), path.string(), options);
    std::vector<std::size_t> counts;
    for (const prepare::PreparedLevel& level : model.levels) counts.push_back(level.leaves.size());
    const std::size_t dense = prepare::denseDepthCount(counts);
    std::vector<prepare::LevelVoxels> levels;
    for (const prepare::PreparedLevel& level : model.levels)
      levels.push_back(prepare::decodeLevel(level));
    const std::vector<std::int32_t> reaches = prepare::measureSampleReaches(levels);
    for (std::size_t i = 1; i < model.levels.size(); ++i) {
      const int depth = model.levels[i].depth;
      const std::int32_t reach = reaches[i];
      std::printf("%s depth %d (%s): reach %d/16\n", name, depth, i < dense ? "dense" : "sparse",
                  reach);
      if (i < dense) {
        EXPECT_EQ(reach, kOneSampleReach) << name << " depth " << depth;
      }
    }
  }
}

TEST(SampleReach, OneFootprintIsTheSetUpOfBeforeAndTheRangeIsChecked) {
  Camera camera = airborneCamera(640, 480);
  camera.zoom = Q16::fromRaw(3 * Q16::kOneRaw);
  FrameSetup plain, one, wide;
  ASSERT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &plain), CameraError::kNone);
  ASSERT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &one, kOneSampleReach),
            CameraError::kNone);
  EXPECT_EQ(std::memcmp(&plain.splat, &one.splat, sizeof plain.splat), 0);
  ASSERT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &wide, 2 * kOneSampleReach),
            CameraError::kNone);
  // 640x480 zoom 3, depth 8: 5.6-pixel voxels, 6 pixels a side; twice as wide, 12.
  EXPECT_EQ(one.splat.columns, 6);
  EXPECT_EQ(wide.splat.columns, 12);
  EXPECT_EQ(wide.splat.extent_x, 2 * one.splat.extent_x);
  EXPECT_EQ(wide.sample_reach, 2 * kOneSampleReach);
  EXPECT_EQ(checkFrameSetup(wide), RenderError::kNone);
  for (const std::int32_t refused : {0, kOneSampleReach - 1, kMaxSampleReach + 1}) {
    FrameSetup edited = wide;
    edited.sample_reach = refused;  // what the smooth kernel would scale by
    EXPECT_EQ(checkFrameSetup(edited), RenderError::kBadSetup) << refused;
    EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &wide, refused),
              CameraError::kBadSampleReach);
  }
}

}  // namespace
}  // namespace octopoint
