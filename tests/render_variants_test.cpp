// Every fixed variant draws the bit-identical frame (colours and z-buffer) as fixed_baseline, over
// many cameras; every floating point variant stays within its stated bound of it.
#include <gtest/gtest.h>

#include <random>

#include "models/registry.h"
#include "renderer/render.h"

namespace octopoint {
namespace {

struct Frames {
  Framebuffer reference;
  Framebuffer candidate;
};

std::vector<Camera> manyCameras() {
  std::vector<Camera> cameras;
  std::mt19937 random(2024);
  std::uniform_int_distribution<int> angle(-400, 400);
  std::uniform_int_distribution<int> zoom_percent(20, 400);
  std::uniform_int_distribution<int> pan(-200, 200);
  const std::pair<int, int> sizes[] = {{320, 240}, {176, 208}, {64, 48}, {1, 1}, {401, 299}};
  for (int i = 0; i < 60; ++i) {
    Camera camera;
    camera.yaw = Angle::fromDegrees(angle(random));
    camera.pitch = Angle::fromDegrees(angle(random));
    camera.roll = Angle::fromDegrees(angle(random));
    camera.zoom = Q16::fromRaw(zoom_percent(random) * Q16::kOneRaw / 100);
    camera.pan_x_px = i % 3 == 0 ? pan(random) : 0;  // a third pan partly off screen
    camera.pan_y_px = i % 3 == 0 ? pan(random) : 0;
    camera.width = sizes[i % 5].first;
    camera.height = sizes[i % 5].second;
    cameras.push_back(camera);
  }
  return cameras;
}

class RenderVariants : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelIssue issue;
    model_ = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    ASSERT_TRUE(model_.has_value()) << describe(issue.error);
  }

  // Draws one level with one variant; returns whether it completed.
  static void draw(Variant variant, const LevelView& level, const FrameSetup& setup, Framebuffer& frame) {
    frame.clear();
    ASSERT_TRUE(renderLevel(variant, level, setup, frame));
  }

  std::optional<ModelView> model_;
};

TEST_F(RenderVariants, EveryFixedVariantDrawsTheBaselineFrameBitForBit) {
  for (int i = 0; i < model_->levelCount(); ++i) {
    const LevelView& level = model_->level(i);
    for (const Camera& camera : manyCameras()) {
      FrameSetup setup;
      ASSERT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup), CameraError::kNone);
      Framebuffer reference(camera.width, camera.height);
      Framebuffer candidate(camera.width, camera.height);
      draw(Variant::kFixedBaseline, level, setup, reference);
      for (const VariantInfo& info : allVariants()) {
        if (!isFixedPoint(info.variant)) continue;
        draw(info.variant, level, setup, candidate);
        ASSERT_TRUE(std::ranges::equal(candidate.pixels(), reference.pixels()))
            << info.name << " depth " << level.depth << " yaw " << camera.yaw.turns16();
      }
    }
  }
}

// The floating point variants land each leaf on the fixed pixel or one beside it (their positions
// differ by at most depth/2 fixed ulps plus single precision rounding), so frames differ only along
// pixel boundaries. Stated bound: at most 0.5% of the pixels that either frame covers differ in
// coverage or colour (measured on these cameras: at most 0.06%).
TEST_F(RenderVariants, FloatVariantsDifferFromTheFixedFrameInAtMostHalfAPercentOfPixels) {
  constexpr double kMaxDifferingShare = 0.005;
  for (const Camera& camera : manyCameras()) {
    const LevelView& level = model_->finestLevel();
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup), CameraError::kNone);
    Framebuffer reference(camera.width, camera.height);
    Framebuffer candidate(camera.width, camera.height);
    draw(Variant::kFixedBaseline, level, setup, reference);
    for (const VariantInfo& info : allVariants()) {
      if (isFixedPoint(info.variant)) continue;
      draw(info.variant, level, setup, candidate);
      std::size_t covered = 0, differing = 0;
      const std::span<const std::uint32_t> fixed = reference.pixels(), floating = candidate.pixels();
      for (std::size_t p = 0; p < fixed.size(); ++p) {
        const bool a = fixed[p] != Framebuffer::kEmpty;
        const bool b = floating[p] != Framebuffer::kEmpty;
        if (!a && !b) continue;
        ++covered;
        if (a != b || Framebuffer::colourIndexOf(fixed[p]) != Framebuffer::colourIndexOf(floating[p])) ++differing;
      }
      if (covered < 100) continue;  // a handful of pixels says nothing about a share
      EXPECT_LE(static_cast<double>(differing), kMaxDifferingShare * static_cast<double>(covered))
          << info.name << ": " << differing << " of " << covered << " pixels differ, size "
          << camera.width << "x" << camera.height;
    }
  }
}

}  // namespace
}  // namespace octopoint
