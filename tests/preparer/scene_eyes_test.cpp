// A scene file's perspective views (docs/scene.md, "eyes" and "paths"): the keys, the camera path
// files they share with octopoint-render --path, the hostile values refused naming file and key,
// and the depths the eyes ask for.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "codegen/prepare_error.h"
#include "codegen/scene.h"
#include "codegen/scene_views.h"
#include "tools/camera_path.h"

namespace octopoint::prepare {
namespace {

// A folder of its own per test, holding the scene's path files.
class SceneEyesFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("octopoint_scene_eyes_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  void write(const std::string& name, const std::string& text) const {
    std::ofstream(folder_ / name, std::ios::binary) << text;
  }
  std::string scenePath() const { return (folder_ / "scene.json").string(); }
  Scene parse(const std::string& text) const { return parseScene(text, scenePath()); }
  std::string errorOf(const std::string& text) const {
    try {
      parse(text);
    } catch (const PrepareError& error) {
      return error.what();
    }
    return "no error";
  }

  std::filesystem::path folder_;
};

constexpr const char* kWalkPath = R"({"fov": 70, "keys": [
  {"time": 0, "eye": [0.05, 0.1, -0.45], "look": [-5, -20]},
  {"time": 2, "eye": [-0.12, 0.06, -0.62], "look": [15, -20]}]})";

TEST_F(SceneEyesFolder, EyesAndPathFramesInTheScansUnitsAsRenderTakesThem) {
  write("walk.json", kWalkPath);
  const Scene scene = parse(R"({"eyes": [{"eye": [0.1, -0.2, 0.3], "look": [10, -5, 2], "fov": 45},
                                         {"eye": [0, 0, -1]}],
                                "paths": ["walk.json"], "path_frames": 5})");
  ASSERT_EQ(scene.eyes.size(), 2u + 5u);
  EXPECT_EQ(scene.eyes[0].eye, (ScanPoint{0.1, -0.2, 0.3}));
  EXPECT_EQ(scene.eyes[0].look.yaw.turns16(), Angle::fromMilliDegrees(10000).turns16());
  EXPECT_EQ(scene.eyes[0].look.pitch.turns16(), Angle::fromMilliDegrees(-5000).turns16());
  EXPECT_EQ(scene.eyes[0].look.roll.turns16(), Angle::fromMilliDegrees(2000).turns16());
  EXPECT_EQ(scene.eyes[0].fov.turns16(), Angle::fromDegrees(45).turns16());
  EXPECT_EQ(scene.eyes[1].fov.turns16(), Angle::fromDegrees(60).turns16());  // --fov's default
  EXPECT_EQ(scene.eyes[1].look.yaw.turns16(), 0);
  // The path's frames are what octopoint-render --path walk.json --frames 5 draws: the one parser
  // and sampler, relative to the scene file's folder, with the path's field of view.
  const std::vector<PathPose> poses =
      samplePath(parseCameraPath(kWalkPath, "walk.json"), scene.path_frames);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(scene.eyes[2 + i].eye, poses[i].eye);
    EXPECT_EQ(scene.eyes[2 + i].look.yaw.turns16(), poses[i].look.yaw.turns16());
    EXPECT_EQ(scene.eyes[2 + i].fov.turns16(), Angle::fromDegrees(70).turns16());
  }
  // Eyes alone are the scene's only views; with an orthographic key both kinds are.
  EXPECT_FALSE(scene.orthographic_views);
  EXPECT_TRUE(parse(R"({"eyes": [{"eye": [0, 0, 0]}], "yaw": [0, 10]})").orthographic_views);
  EXPECT_TRUE(parse(R"({"zoom": 2})").orthographic_views);
  EXPECT_EQ(parse(R"({"paths": ["walk.json"]})").eyes.size(), 64u);  // path_frames' default
}

TEST_F(SceneEyesFolder, HostileEyesAndPathsAreRefusedOnOneLineNamingFileAndKey) {
  write("walk.json", kWalkPath);
  write("broken.json", R"({"keys": [{"eye": [0, 0)");
  write("nan.json", R"({"keys": [{"eye": [0, 0, 1e400]}]})");
  const std::string file = std::filesystem::path(scenePath()).string();
  const struct {
    const char* text;
    std::string expected;  // after "PATH: "
  } cases[] = {
      {R"({"eyes": []})", "key 'eyes': expected a list of 1 to 20000"},
      {R"({"eyes": {"eye": [0, 0, 0]}})", "key 'eyes': expected a list of 1 to 20000"},
      {R"({"eyes": [{"look": [0, 0]}]})", "key 'eyes[0]': has no \"eye\""},
      {R"({"eyes": [{"eye": [0, 0]}]})", "key 'eyes[0].eye': expected [x, y, z]"},
      {R"({"eyes": [{"eye": [0, 0, "1"]}]})", "key 'eyes[0].eye': expected a number"},
      {R"({"eyes": [{"eye": [0, 0, 1e14]}]})",
       "key 'eyes[0].eye': 100000000000000 is outside -10000000000000..10000000000000"},
      {R"({"eyes": [{"eye": [0, 0, 1e400]}]})",
       "not valid JSON: number overflow parsing '1e400' (key 'eyes.eye')"},
      {R"({"eyes": [{"eye": [0, 0, 0], "look": [1, 2, 3, 4]}]})",
       "key 'eyes[0].look': expected [yaw, pitch] or [yaw, pitch, roll] in degrees"},
      {R"({"eyes": [{"eye": [0, 0, 0], "look": [1e7, 0]}]})",
       "key 'eyes[0].look': 10000000 is outside -1000000..1000000"},
      {R"({"eyes": [{"eye": [0, 0, 0], "fov": 5}]})", "key 'eyes[0].fov': 5 is outside 10..120"},
      {R"({"eyes": [{"eye": [0, 0, 0], "fov": 121}]})",
       "key 'eyes[0].fov': 121 is outside 10..120"},
      {R"({"eyes": [{"eye": [0, 0, 0], "at": 1}]})", "key 'eyes[0].at': unknown key"},
      {R"({"eyes": [{"eye": [0, 0, 0], "eye": [1, 1, 1]}]})", "key 'eyes.eye': given twice"},
      {R"({"paths": "walk.json"})", "key 'paths': expected a non-empty list of camera path files"},
      {R"({"paths": [7]})", "key 'paths[0]': expected the name of a camera path file"},
      {R"({"paths": [""]})", "key 'paths[0]': expected the name of a camera path file"},
      {R"({"paths": ["missing.json"]})", "key 'paths[0]': " + (folder_ / "missing.json").string()},
      {R"({"paths": ["broken.json"]})",
       "key 'paths[0]': " + (folder_ / "broken.json").string() + ": not valid JSON"},
      {R"({"paths": ["nan.json"]})",
       "key 'paths[0]': " + (folder_ / "nan.json").string() + ": not valid JSON: number overflow"},
      {R"({"paths": ["walk.json"], "path_frames": 0})", "key 'path_frames': 0 is outside 1..3600"},
      {R"({"paths": ["walk.json"], "path_frames": 1e9})",
       "key 'path_frames': expected a whole number"},
      {R"({"path_frames": 8})", "key 'path_frames': needs \"paths\""},
      {R"({"paths": ["walk.json", "walk.json", "walk.json", "walk.json", "walk.json", "walk.json"],
           "path_frames": 3600})",
       "key 'paths': the eyes and path frames come to more than 20000 views: lower path_frames"},
  };
  std::string many_eyes;
  for (int i = 0; i < 300; ++i) many_eyes += std::string(i ? "," : "") + R"({"eye": [0, 0, 0]})";
  EXPECT_EQ(errorOf(R"({"framebuffer": [8192, 8192], "eyes": [)" + many_eyes + "]}"),
            file +
                ": key 'eyes': 300 eyes and path frames of 8192x8192 pixels are 2.01e+10 view "
                "pixels; pruning draws at most 1.72e+10: fewer eyes or path_frames, or shrink "
                "the framebuffer");
  EXPECT_NO_THROW(
      parse(R"({"framebuffer": [8192, 8192], "prune": false, "eyes": [)" + many_eyes + "]}"));
  for (const auto& c : cases) {
    const std::string error = errorOf(c.text);
    EXPECT_EQ(error.rfind(file + ": " + c.expected, 0), 0u) << c.text << "\n  gave: " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

TEST_F(SceneEyesFolder, EyesAskForDepthsFromAPixelTwoCubeEdgesAwayToAsFineAsTheScanSamples) {
  // 240 rows at 60 degrees: f = 207.8 pixels; a depth-7 voxel spans 207.8 / 128 / 2 = 0.81 pixel
  // two edges away, depth 6 1.6: from 7, eight depths.
  const Scene eyes = parse(R"({"eyes": [{"eye": [0, 0, 0]}], "depths": "auto"})");
  EXPECT_EQ(eyeDepths(eyes), (std::vector<int>{7, 8, 9, 10, 11, 12, 13, 14}));
  EXPECT_EQ(chooseDepths(eyes).depths, eyeDepths(eyes));
  // The widest field of view decides: 120 degrees, f = 69.3: depth 5 spans 1.08 pixels, 6 0.54.
  const Scene wide = parse(R"({"eyes": [{"eye": [0, 0, 0]}, {"eye": [0, 0, 0], "fov": 120}]})");
  EXPECT_EQ(eyeDepths(wide).front(), 6);
  // With orthographic views too: one range over both, its finest eight.
  const Scene both = parse(R"({"eyes": [{"eye": [0, 0, 0]}], "zoom": [1, 64]})");
  const std::vector<int> depths = chooseDepths(both).depths;
  EXPECT_EQ(depths.size(), 8u);
  EXPECT_EQ(depths.back(), 14);  // zoom 64 on 240 rows: 2^14 voxels span the frame
  EXPECT_TRUE(eyeDepths(parse(R"({"yaw": [0, 10]})")).empty());
}

}  // namespace
}  // namespace octopoint::prepare
