// Pruning for a scene's eyes (codegen/scene_pruning.h) against the real perspective renderer: a
// model pruned for its eyes draws each eye's frame as the unpruned model does, bit for bit, also
// where the eyes alone would leave the renderer's densely sampled depths (denseDepthCount) with
// too few voxels and so change which depths detail by distance chooses among, and where the scan
// samples more coarsely than the kept depths' voxels, so that the renderer widens their splats by
// the stored sample reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <vector>

#include "codegen/depth_range.h"
#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "octopoint/framebuffer.h"
#include "renderer/level_of_detail.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/airborne_scans.h"
#include "tests/support/synthetic_scans.h"
#include "tools/scan_eye.h"

namespace octopoint {
namespace {

constexpr int kEyeWidth = 160;
constexpr int kEyeHeight = 120;

// The unit sphere's scan (radius 1 about the origin) at depths 4 to 7, all densely sampled.
prepare::PrepareOptions sphereOptions() {
  prepare::PrepareOptions options;
  options.name = "eye_pruning_test";
  options.depths = {4, 5, 6, 7};
  options.eye_width = kEyeWidth;
  options.eye_height = kEyeHeight;
  return options;
}

std::vector<std::uint64_t> voxelsPerDepth(const ModelView& model) {
  std::vector<std::uint64_t> voxels;
  for (int i = 0; i < model.levelCount(); ++i) voxels.push_back(model.level(i).leaves.size());
  return voxels;
}

Framebuffer eyeFrame(const ModelView& model, const prepare::SceneEye& eye, int width = kEyeWidth,
                     int height = kEyeHeight) {
  const PerspectiveView view =
      scanEyeView(*scanCube(model.cubePlacement()), eye.eye, eye.look, eye.fov,
                  modelNearPlane(model, std::nullopt, "test"), width, height, "test");
  Framebuffer frame(width, height);
  frame.clear();
  PerspectiveRenderer renderer(model);
  EXPECT_TRUE(renderer.draw(view, {}, frame));
  return frame;
}

std::size_t coveredPixels(const Framebuffer& frame) {
  std::size_t covered = 0;
  for (const std::uint32_t pixel : frame.pixels()) covered += pixel != Framebuffer::kEmpty;
  return covered;
}

TEST(EyePruning, KeepsTheDenseDepthsSoThatEveryEyesFrameIsTheUnprunedModels) {
  const prepare::Scan sphere = testing::colouredSphere(400'000);
  prepare::PrepareOptions options = sphereOptions();
  const std::vector<std::uint8_t> unpruned_image =
      prepare::serializeModel(prepare::prepareModel(sphere, "sphere.pcd", options));
  // Looking along +z: close to the sphere (every voxel it sees is coarser than a pixel, so only
  // the finest depth is drawn and depths 4 to 6 would keep no voxel of their own), and far from
  // it (detail by distance mixes depths).
  const std::vector<prepare::SceneEye> eyes = {
      {.eye = {0.1, 0.0, -1.3}, .look = {}, .fov = Angle::fromDegrees(60)},
      {.eye = {0.0, 0.2, -6.0}, .look = {}, .fov = Angle::fromDegrees(30)}};
  options.visibility_eyes = eyes;
  const std::vector<std::uint8_t> pruned_image =
      prepare::serializeModel(prepare::prepareModel(sphere, "sphere.pcd", options));
  const ModelView unpruned = *ModelView::fromBytes(unpruned_image, nullptr);
  const ModelView pruned = *ModelView::fromBytes(pruned_image, nullptr);

  const std::vector<std::uint64_t> before = voxelsPerDepth(unpruned);
  const std::vector<std::uint64_t> after = voxelsPerDepth(pruned);
  ASSERT_EQ(denseDepthCount(before), 4u)
      << before[0] << " " << before[1] << " " << before[2] << " " << before[3];
  EXPECT_EQ(denseDepthCount(after), 4u)
      << after[0] << " " << after[1] << " " << after[2] << " " << after[3];
  EXPECT_LT(after.back(), before.back() / 2) << "the eyes see less than half of the sphere";

  for (const prepare::SceneEye& eye : eyes) {
    const Framebuffer expected = eyeFrame(unpruned, eye);
    const Framebuffer actual = eyeFrame(pruned, eye);
    EXPECT_GT(coveredPixels(expected), static_cast<std::size_t>(kEyeWidth * kEyeHeight / 10));
    EXPECT_TRUE(
        expected.pixels().size() == actual.pixels().size() &&
        std::equal(expected.pixels().begin(), expected.pixels().end(), actual.pixels().begin()))
        << "eye at z " << eye.eye[2] << ": the pruned model draws another frame";
  }
}

// The airborne test scans (1 m samples, roofs of 4 to 12 m) prepared with the default depth cut
// keep depths finer than their samples (the grid 6 to 9, reaches 1, 1, 2 and 3 footprints; the
// irregular samples 6 to 8, reaches 1, 2 and 3), which the renderer draws with splats widened by
// the stored reach. Eyes (scan metres; the ground is z = 0, heights toward -z, so look 0,0 is
// straight down): above the middle, across the roofs from beyond the ground's far side, low over
// its near side, and far off it (where detail by distance draws depth 8 as well). Pruned for them,
// each eye's frame is the unpruned model's, bit for bit. A pruning that judged one-footprint
// splats dropped leaves the wider splats show and kept leaves they hide: up to 2,618 pixels of
// these frames differed, and the pruned grid kept 76% of its bytes (45% now).
constexpr int kAirborneWidth = 320;
constexpr int kAirborneHeight = 240;

const std::vector<prepare::SceneEye>& airborneEyes() {
  // Pitched from straight down toward -y (positive) or +y (negative).
  const auto eye = [](double x, double y, double z, int pitch, int fov) {
    return prepare::SceneEye{.eye = {x, y, z},
                             .look = {Angle{}, Angle::fromDegrees(pitch), Angle{}},
                             .fov = Angle::fromDegrees(fov)};
  };
  static const std::vector<prepare::SceneEye> eyes = {
      eye(112.0, 50.0, -60.0, 0, 60), eye(75.0, 112.0, -30.0, 40, 60),
      eye(150.0, -6.0, -15.0, -55, 70), eye(112.0, -120.0, -80.0, -65, 70)};
  return eyes;
}

void expectEyeFramesUnchanged(testing::AirborneSampling sampling, const char* name) {
  prepare::PrepareOptions options;
  options.name = "airborne";
  options.depths = prepare::defaultDepths();
  options.stop_at_sparse_depth = true;
  options.eye_width = kAirborneWidth;
  options.eye_height = kAirborneHeight;
  const prepare::Scan scan = testing::airborneScan(sampling, 1.0, 7);
  const std::vector<std::uint8_t> unpruned_image =
      prepare::serializeModel(prepare::prepareModel(scan, "airborne.ply", options));
  options.visibility_eyes = airborneEyes();
  const std::vector<std::uint8_t> pruned_image =
      prepare::serializeModel(prepare::prepareModel(scan, "airborne.ply", options));
  const ModelView unpruned = *ModelView::fromBytes(unpruned_image, nullptr);
  const ModelView pruned = *ModelView::fromBytes(pruned_image, nullptr);

  ASSERT_EQ(pruned.levelCount(), unpruned.levelCount());
  bool reached = false;
  for (int i = 0; i < unpruned.levelCount(); ++i) {
    EXPECT_EQ(pruned.sampleReach(i), unpruned.sampleReach(i)) << name << " level " << i;
    reached = reached || unpruned.sampleReach(i) > kOneSampleReach;
    std::printf("%s depth %d (reach %d/16): %zu -> %zu voxels\n", name, unpruned.level(i).depth,
                unpruned.sampleReach(i), unpruned.level(i).leaves.size(),
                pruned.level(i).leaves.size());
  }
  ASSERT_TRUE(reached) << name << ": no depth is sampled more coarsely than its voxels";
  std::printf("%s: %zu -> %zu bytes\n", name, unpruned_image.size(), pruned_image.size());
  EXPECT_LT(pruned_image.size(), unpruned_image.size() * 3 / 4) << name;

  for (std::size_t e = 0; e < airborneEyes().size(); ++e) {
    const Framebuffer expected =
        eyeFrame(unpruned, airborneEyes()[e], kAirborneWidth, kAirborneHeight);
    const Framebuffer actual = eyeFrame(pruned, airborneEyes()[e], kAirborneWidth, kAirborneHeight);
    EXPECT_GT(coveredPixels(expected),
              static_cast<std::size_t>(kAirborneWidth * kAirborneHeight / 10))
        << name << " eye " << e;
    std::size_t differ = 0;
    for (std::size_t i = 0; i < expected.pixels().size(); ++i)
      differ += expected.pixels()[i] != actual.pixels()[i];
    std::printf("%s eye %zu: %zu of %zu pixels differ\n", name, e, differ,
                expected.pixels().size());
    EXPECT_EQ(differ, 0u) << name << " eye " << e << ": the pruned model draws another frame";
  }
}

TEST(EyePruning, AGridScanCoarserThanItsVoxelsDrawsEveryEyesFrameAsUnpruned) {
  expectEyeFramesUnchanged(testing::AirborneSampling::kGrid, "grid");
}

TEST(EyePruning, IrregularSamplesCoarserThanTheVoxelsDrawEveryEyesFrameAsUnpruned) {
  expectEyeFramesUnchanged(testing::AirborneSampling::kIrregular, "irregular");
}

}  // namespace
}  // namespace octopoint
