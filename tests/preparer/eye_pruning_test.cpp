// Pruning for a scene's eyes (codegen/scene_pruning.h) against the real perspective renderer: a
// model pruned for its eyes draws each eye's frame as the unpruned model does, bit for bit, also
// where the eyes alone would leave the renderer's densely sampled depths (denseDepthCount) with
// too few voxels and so change which depths detail by distance chooses among.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "octopoint/framebuffer.h"
#include "renderer/level_of_detail.h"
#include "renderer/perspective_renderer.h"
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

Framebuffer eyeFrame(const ModelView& model, const prepare::SceneEye& eye) {
  const PerspectiveView view =
      scanEyeView(*scanCube(model.cubePlacement()), eye.eye, eye.look, eye.fov,
                  modelNearPlane(model, std::nullopt, "test"), kEyeWidth, kEyeHeight, "test");
  Framebuffer frame(kEyeWidth, kEyeHeight);
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

}  // namespace
}  // namespace octopoint
