// Scene files: parsing, the errors that name the key, the sampled cameras and the automatic depths.
#include "codegen/scene.h"

#include <gtest/gtest.h>

#include <cmath>

#include "codegen/depth_range.h"
#include "codegen/outlier_filter.h"
#include "codegen/prepare.h"
#include "codegen/prepare_error.h"
#include "codegen/scene_views.h"
#include "tests/support/synthetic_scans.h"

namespace octopoint::prepare {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseScene(text, "scene.json");
  } catch (const PrepareError& error) {
    return error.what();
  }
  return "no error";
}

TEST(SceneFile, ReadsEveryKey) {
  const Scene scene = parseScene(R"({
    "yaw": [-30, 30], "pitch": [-20, 20], "roll": 5, "zoom": [1, 2], "framebuffer": [640, 480],
    "depths": [6, 9], "palette": {"mode": "greyscale", "colours": 64},
    "crop": {"min": [-1, -2, -3], "max": [1, 2, 3]},
    "outliers": {"method": "statistical", "neighbours": 12, "stddev": 1.5},
    "axes": "y-up", "scan_unit": "mm", "prune": false, "angle_step": 2, "zoom_step": 1.5})",
                                 "scene.json");
  EXPECT_EQ(scene.yaw_deg->low, -30);
  EXPECT_EQ(scene.pitch_deg->high, 20);
  EXPECT_EQ(scene.roll_deg, 5);
  EXPECT_EQ(scene.zoom.high, 2);
  EXPECT_EQ(scene.width, 640);
  EXPECT_EQ(scene.height, 480);
  EXPECT_FALSE(scene.auto_depths);
  EXPECT_EQ(scene.depths, (std::vector<int>{6, 9}));
  EXPECT_TRUE(scene.greyscale);
  EXPECT_EQ(scene.palette_colours, 64);
  EXPECT_EQ(scene.crop->low[2], -3);
  EXPECT_EQ(scene.outliers->neighbours, 12);
  EXPECT_EQ(scene.outliers->stddev_factor, 1.5);
  EXPECT_EQ(scene.axes, ScanAxes::kYUp);
  EXPECT_EQ(scene.metres_per_scan_unit, 0.001);
  EXPECT_FALSE(scene.prune);
  EXPECT_EQ(scene.angle_step_deg, 2);
  EXPECT_EQ(scene.zoom_step, 1.5);
}

TEST(SceneFile, ErrorsNameTheKeyOnOneLine) {
  EXPECT_EQ(errorOf(R"({"yaw": [-30, 30], "colour": 1})"), "scene.json: key 'colour': unknown key");
  EXPECT_EQ(errorOf(R"({"palette": {"colors": 3}})"),
            "scene.json: key 'palette.colors': unknown key");
  EXPECT_EQ(errorOf(R"({"yaw": [30, -30]})"), "scene.json: key 'yaw': empty range: 30 > -30");
  EXPECT_EQ(errorOf(R"({"pitch": [-100, 0]})"), "scene.json: key 'pitch': -100 is outside -90..90");
  EXPECT_EQ(errorOf(R"({"zoom": [0, 2]})"), "scene.json: key 'zoom': zoom must be greater than 0");
  EXPECT_EQ(errorOf(R"({"zoom": -1})"), "scene.json: key 'zoom': zoom must be greater than 0");
  // Below 16.16's smallest step a zoom is too small, not "not greater than 0"; the numbers in
  // messages are the numbers given, not %g's six digits.
  for (const char* tiny : {"1e-300", "5e-324", "0.0000152", "[1e-10, 2]"}) {
    const std::string error = errorOf(std::string(R"({"zoom": )") + tiny + "}");
    EXPECT_EQ(error.rfind("scene.json: key 'zoom': zoom ", 0), 0u) << tiny;
    EXPECT_NE(error.find(" is too small: it must be at least 1/65536"), std::string::npos) << tiny;
  }
  EXPECT_EQ(errorOf(R"({"zoom": 1e-300})"),
            "scene.json: key 'zoom': zoom 1e-300 is too small: it must be at least 1/65536");
  EXPECT_EQ(errorOf(R"({"pitch": [0, 1000000.0625]})"),
            "scene.json: key 'pitch': 1000000.0625 is outside -90..90");
  EXPECT_EQ(errorOf(R"({"yaw": [180.5, 180.5]})"),
            "scene.json: key 'yaw': 180.5 is outside -180..180");
  EXPECT_EQ(errorOf(R"({"yaw": [0.125, 0.0625]})"),
            "scene.json: key 'yaw': empty range: 0.125 > 0.0625");
  EXPECT_EQ(errorOf(R"({"depths": [0, 8]})"), "scene.json: key 'depths': 0 is outside 1..16");
  EXPECT_EQ(errorOf(R"({"depths": [8, 17]})"), "scene.json: key 'depths': 17 is outside 1..16");
  EXPECT_EQ(errorOf(R"({"depths": [8, 7]})"),
            "scene.json: key 'depths': depths must be strictly ascending");
  EXPECT_EQ(errorOf(R"({"framebuffer": [320]})"),
            "scene.json: key 'framebuffer': expected [width, height]");
  EXPECT_EQ(
      errorOf(R"({"viewpoints": [{"yaw": 0, "pitch": 0}], "yaw": [0, 1]})"),
      "scene.json: key 'viewpoints': give either viewpoints or yaw and pitch ranges, not both");
  const std::string syntax = errorOf("{\"yaw\": [-30, 30],\n \"pitch\": }");
  EXPECT_EQ(syntax.find("scene.json: not valid JSON: parse error at line 2"), 0u) << syntax;
  EXPECT_EQ(syntax.find('\n'), std::string::npos);
}

// What the hardening sweep found (docs/robustness.md, classes 2, 7 and 12): numbers out of double's
// range name the file and key, junk after a NUL byte is refused, echoed keys are cut, and a scene
// may not ask for unbounded work.
TEST(SceneFile, HostileNumbersKeysAndBytesAreRefusedNamingFileAndKey) {
  EXPECT_EQ(errorOf(R"({"zoom": [1, 1e400]})"),
            "scene.json: not valid JSON: number overflow parsing '1e400' (key 'zoom')");
  EXPECT_EQ(errorOf(R"({"palette": {"colours": 1e400}})"),
            "scene.json: not valid JSON: number overflow parsing '1e400' (key 'palette.colours')");
  EXPECT_EQ(errorOf(std::string("{\"yaw\": [0, 1]}\0junk", 20)),
            "scene.json: a NUL byte at byte 15: a scene file is JSON text");
  EXPECT_EQ(errorOf(R"({"depths": [18446744073709551615]})"),
            "scene.json: key 'depths': 18446744073709551615 is outside 1..16");
  EXPECT_EQ(errorOf("{\"" + std::string(5000, 'k') + "\": 1}"),
            "scene.json: key '" + std::string(40, 'k') + "...': unknown key");
}

// A key given twice (nlohmann would keep the last silently), nesting past what a scene needs, and
// a number out of range inside a list of objects named by its key path.
TEST(SceneFile, DuplicateKeysDeepNestingAndKeysInsideListsAreNamed) {
  EXPECT_EQ(errorOf(R"({"yaw": [-30, 30], "yaw": [0, 1]})"), "scene.json: key 'yaw': given twice");
  EXPECT_EQ(errorOf(R"({"palette": {"colours": 4, "colours": 8}})"),
            "scene.json: key 'palette.colours': given twice");
  EXPECT_EQ(errorOf(std::string(100000, '[')),
            "scene.json: objects and lists nested deeper than 8 levels");
  EXPECT_EQ(errorOf(R"({"crop": {"min": [[[[[[[[1]]]]]]]]}})"),
            "scene.json: objects and lists nested deeper than 8 levels (key 'crop.min')");
  EXPECT_EQ(errorOf(R"({"viewpoints": [{"yaw": 0, "pitch": 0}, {"yaw": 1e400, "pitch": 0}]})"),
            "scene.json: not valid JSON: number overflow parsing '1e400' (key 'viewpoints.yaw')");
  // The same key in two objects of a list is not a duplicate.
  EXPECT_NO_THROW(parseScene(R"({"viewpoints": [{"yaw": 0, "pitch": 0}, {"yaw": 1, "pitch": 0}]})",
                             "scene.json"));
}

TEST(SceneViews, ASceneAskingForUnboundedWorkIsRefusedSayingHowToShrinkIt) {
  const std::string message =
      errorOf(R"({"yaw": [-180, 180], "pitch": [-90, 90], "angle_step": 0.1})");
  EXPECT_EQ(
      message.find(
          "scene.json: the scene asks for 6485401 views (3601 yaw x 1801 pitch x 1 zoom samples) "
          "of 320x240 pixels"),
      0u)
      << message;
  EXPECT_NE(message.find("raise angle_step (now 0.1)"), std::string::npos) << message;
  EXPECT_NE(errorOf(R"({"yaw": [-180, 180], "pitch": [-90, 90], "framebuffer": [8192, 8192]})")
                .find("shrink the framebuffer"),
            std::string::npos);
  // The full sphere at the default step, and the same without pruning, are fine.
  EXPECT_EQ(
      sceneWork(parseScene(R"({"yaw": [-180, 180], "pitch": [-90, 90]})", "scene.json")).views,
      181.0 * 91);
  EXPECT_NO_THROW(
      parseScene(R"({"yaw": [-180, 180], "pitch": [-90, 90], "angle_step": 0.1, "prune": false})",
                 "scene.json"));
}

TEST(SceneViews, SampleBothEndsOfEveryRangeAtMostOneStepApart) {
  Scene scene;
  scene.yaw_deg = Range{-30, 30};
  scene.pitch_deg = Range{-20, 20};
  scene.zoom = {1, 4};
  scene.angle_step_deg = 7;  // 60 / 7 -> 9 steps (10 yaws), 40 / 7 -> 6 steps (7 pitches)
  scene.zoom_step = 2;       // 1, 2, 4
  const std::vector<Camera> cameras = sceneCameras(scene);
  ASSERT_EQ(cameras.size(), 10u * 7u * 3u);
  EXPECT_EQ(cameras.front().yaw.turns16(), Angle::fromDegrees(-30).turns16());
  EXPECT_EQ(cameras.front().pitch.turns16(), Angle::fromDegrees(-20).turns16());
  EXPECT_EQ(cameras.front().zoom.raw(), Q16::kOneRaw);
  EXPECT_EQ(cameras.back().yaw.turns16(), Angle::fromDegrees(30).turns16());
  EXPECT_EQ(cameras.back().pitch.turns16(), Angle::fromDegrees(20).turns16());
  EXPECT_EQ(cameras.back().zoom.raw(), 4 * Q16::kOneRaw);
  EXPECT_EQ(cameras[70].zoom.raw(), 2 * Q16::kOneRaw);
}

TEST(SceneViews, ExplicitViewpointsAreTakenAsTheyAreAtEverySampledZoom) {
  const Scene scene =
      parseScene(R"({"viewpoints": [{"yaw": 10, "pitch": -5}, {"yaw": -20, "pitch": 0, "roll": 90}],
                                     "zoom": [1, 2], "zoom_step": 2})",
                 "scene.json");
  const std::vector<Camera> cameras = sceneCameras(scene);
  ASSERT_EQ(cameras.size(), 4u);  // 2 viewpoints x zoom 1 and 2
  EXPECT_EQ(cameras[0].yaw.turns16(), Angle::fromDegrees(10).turns16());
  EXPECT_EQ(cameras[0].pitch.turns16(), Angle::fromDegrees(-5).turns16());
  EXPECT_EQ(cameras[1].roll.turns16(), Angle::fromDegrees(90).turns16());
  EXPECT_EQ(cameras[3].yaw.turns16(), Angle::fromDegrees(-20).turns16());
  EXPECT_EQ(cameras[3].zoom.raw(), 2 * Q16::kOneRaw);
}

TEST(SceneViews, AutoDepthsSpanWhatTheViewsNeedByProjectedSizeAndOneCoarser) {
  Scene scene;
  scene.width = 320;
  scene.height = 240;
  scene.yaw_deg = Range{0, 0};
  scene.pitch_deg = Range{0, 0};
  scene.zoom = {1, 1};  // head-on the cube spans 240 px: depth 8 (0.94 px per voxel) is needed
  EXPECT_EQ(chooseDepths(scene).depths, (std::vector<int>{7, 8}));
  scene.zoom = {1, 2};  // 480 px -> depth 9
  EXPECT_EQ(chooseDepths(scene).depths, (std::vector<int>{7, 8, 9}));
  scene.zoom = {1, 256.0 / 240};  // exactly 256 px: still depth 8
  EXPECT_EQ(chooseDepths(scene).depths, (std::vector<int>{7, 8}));
  scene.zoom = {0.25, 1};  // 60 px: depth 6, one coarser for moving views
  EXPECT_EQ(chooseDepths(scene).depths, (std::vector<int>{5, 6, 7, 8}));
  scene.yaw_deg = Range{0, 30};  // turned, the voxel's edge is the same (its splat is wider)
  scene.pitch_deg = Range{0, 35};
  scene.zoom = {1, 1};
  EXPECT_EQ(chooseDepths(scene).depths, (std::vector<int>{7, 8}));
  scene.pitch_deg = Range{0, 0};
  scene.yaw_deg = Range{0, 0};
  scene.zoom = {0.001, 0.001};  // under one pixel: depth 1 alone
  EXPECT_EQ(chooseDepths(scene).depths, (std::vector<int>{1}));
  scene.zoom = {0.001, 32767};  // at most format::kMaxLevels depths, the finest kept
  EXPECT_EQ(chooseDepths(scene).depths, (std::vector<int>{9, 10, 11, 12, 13, 14, 15, 16}));
}

TEST(DepthRange, DenseDepthsStopWhereTheVoxelCountGrowsLessThanThreefold) {
  const std::vector<std::size_t> tabletop = {5433, 19747, 62502, 141209, 160244};  // depths 6..10
  EXPECT_EQ(denseDepthCount(tabletop), 3u);  // 62502 -> 141209 is 2.26x: depth 9 is sparse
  EXPECT_EQ(denseDepthCount(std::vector<std::size_t>{10, 30, 90}), 3u);  // exactly 3x is dense
  EXPECT_EQ(denseDepthCount(std::vector<std::size_t>{10, 29, 90}), 1u);
  EXPECT_EQ(denseDepthCount(std::vector<std::size_t>{7}), 1u);
  EXPECT_EQ(defaultDepths(), (std::vector<int>{6, 7, 8, 9, 10}));
}

TEST(OutlierRemoval, DropsFarAwayJunkAndKeepsTheSurface) {
  Scan scan = testing::colouredSphere(20000);
  const std::size_t surface = scan.positions.size();
  for (float x : {40.0f, -55.0f, 70.0f}) {  // junk far away, as real Kinect scans have
    scan.positions.push_back({x, 3, -20});
    scan.colours.push_back({1, 2, 3});
  }
  const Scan kept = removeOutliers(scan, OutlierRemoval{8, 2.0}, "junk.pcd");
  for (const auto& p : kept.positions) ASSERT_LE(std::abs(p[0]), 1.01f);  // no junk point survives
  EXPECT_GT(kept.positions.size(), surface * 95 / 100);  // and the sphere nearly whole
  EXPECT_EQ(kept.colours.size(), kept.positions.size());
}

TEST(OutlierRemoval, RefusesAScanWithTooFewPoints) {
  Scan scan = testing::colouredSphere(5);
  EXPECT_THROW(removeOutliers(scan, OutlierRemoval{8, 2.0}, "tiny.pcd"), PrepareError);
}

TEST(ScenePalette, GreyscaleModeMakesEveryPaletteColourGrey) {
  PrepareOptions options;
  options.name = "grey";
  options.depths = {5};
  options.greyscale = true;
  const PreparedModel model = prepareModel(testing::colouredSphere(5000), "sphere.pcd", options);
  ASSERT_GT(model.palette.size(), 2u);  // the sphere's 8 colours give several greys
  for (const Rgb8& colour : model.palette) {
    EXPECT_EQ(colour[0], colour[1]);
    EXPECT_EQ(colour[1], colour[2]);
  }
}

}  // namespace
}  // namespace octopoint::prepare
