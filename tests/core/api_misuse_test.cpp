// Library users get refusals, not crashes: every public drawing entry point
// checks in O(1), in release builds too, that its arguments fit together, and draws nothing
// otherwise. And the one-call path (RgbRenderer) draws what the detailed API draws.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/rgb_renderer.h"

namespace octopoint {
namespace {

class ApiMisuse : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelIssue issue;
    model_ = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    ASSERT_TRUE(model_.has_value()) << describe(issue.error);
    level_ = &model_->finestLevel();
    ASSERT_EQ(buildFrameSetup(Camera{}, level_->depth, kDefaultFractionBits, &setup_),
              CameraError::kNone);
  }

  // Every variant refuses: false, and the frame keeps the marker it was filled with.
  void expectRefusedByEveryVariant(const FrameSetup& setup, Framebuffer& frame,
                                   const LevelView& level, RenderError why) {
    EXPECT_EQ(checkRender(level, setup, frame), why);
    for (const VariantInfo& info : allVariants()) {
      std::fill(frame.pixelData(), frame.pixelData() + frame.pixels().size(), kMarker);
      EXPECT_FALSE(renderLevel(info.variant, level, setup, frame)) << info.name;
      EXPECT_TRUE(std::all_of(frame.pixels().begin(), frame.pixels().end(),
                              [](std::uint32_t word) { return word == kMarker; }))
          << info.name << " drew although refused";
    }
  }

  static constexpr std::uint32_t kMarker = 0x12345678;
  std::optional<ModelView> model_;
  const LevelView* level_ = nullptr;
  FrameSetup setup_;
};

// fixed_fast and fixed_simd wrote past a smaller framebuffer in release builds (a segfault).
TEST_F(ApiMisuse, AFramebufferOfAnotherSizeIsRefused) {
  Framebuffer smaller(160, 120);
  expectRefusedByEveryVariant(setup_, smaller, *level_, RenderError::kFrameSizeMismatch);
  Framebuffer wider(640, 240);
  expectRefusedByEveryVariant(setup_, wider, *level_, RenderError::kFrameSizeMismatch);
  Framebuffer made_from_setup(setup_);
  EXPECT_EQ(made_from_setup.width(), 320);
  EXPECT_EQ(made_from_setup.height(), 240);
  EXPECT_TRUE(renderLevel(defaultVariant(), *level_, setup_, made_from_setup));
}

// A level of another depth drew garbage silently.
TEST_F(ApiMisuse, ALevelOfAnotherDepthIsRefused) {
  Framebuffer frame(setup_);
  expectRefusedByEveryVariant(setup_, frame, model_->level(0), RenderError::kDepthMismatch);
  LevelView impossible = *level_;
  impossible.leaves = impossible.leaves.first(1);  // fewer leaves than any tree of its node bytes
  expectRefusedByEveryVariant(setup_, frame, impossible, RenderError::kImplausibleLevel);
}

TEST_F(ApiMisuse, ASetUpBuildFrameSetupWouldNotMakeIsRefused) {
  Framebuffer frame(setup_);
  expectRefusedByEveryVariant(FrameSetup{}, frame, *level_, RenderError::kBadSetup);  // never built
  FrameSetup overflowing = setup_;
  overflowing.root.x = std::numeric_limits<std::int32_t>::max() - 10;  // the walk would wrap
  expectRefusedByEveryVariant(overflowing, frame, *level_, RenderError::kBadSetup);
  FrameSetup wrong_bits = setup_;
  wrong_bits.fraction_bits = 0;
  expectRefusedByEveryVariant(wrong_bits, frame, *level_, RenderError::kBadSetup);
  FrameSetup wrong_splat = setup_;
  wrong_splat.splat.columns = 50;
  wrong_splat.splat.span_x =
      std::numeric_limits<std::int32_t>::max() - 5;  // p + offset + span would wrap
  expectRefusedByEveryVariant(wrong_splat, frame, *level_, RenderError::kBadSetup);
  wrong_splat.splat.span_x = -1;
  expectRefusedByEveryVariant(wrong_splat, frame, *level_, RenderError::kBadSetup);
}

// Bands (a frame drawn in horizontal strips) use the full frame's set-up with a smaller height and
// a shifted root: the checks must let them through, and a reset splat too.
TEST_F(ApiMisuse, BandsAndAResetSplatStayPossible) {
  FrameSetup band = setup_;
  band.height = 60;
  band.root.y -= 120 << band.fraction_bits;
  Framebuffer band_frame(band);
  EXPECT_EQ(checkRender(*level_, band, band_frame), RenderError::kNone);
  EXPECT_TRUE(renderLevel(defaultVariant(), *level_, band, band_frame));
  FrameSetup one_pixel = setup_;
  one_pixel.splat = SplatFootprint{};
  Framebuffer frame(one_pixel);
  EXPECT_TRUE(renderLevel(defaultVariant(), *level_, one_pixel, frame));
}

TEST_F(ApiMisuse, BuffersOfTheWrongSizeAreRefusedNotOverrun) {
  EXPECT_EQ(Framebuffer(0, 240).width(), 0);
  EXPECT_EQ(Framebuffer(-5, 240).pixels().size(), 0u);
  EXPECT_EQ(Framebuffer(kMaxViewportSide + 1, 1).height(), 0);

  Framebuffer frame(setup_);
  ASSERT_TRUE(renderLevel(defaultVariant(), *level_, setup_, frame));
  const std::vector<std::uint32_t> drawn(frame.pixels().begin(), frame.pixels().end());
  HoleFiller narrower(200);
  EXPECT_TRUE(narrower.fill(frame, bridgeDepthLimit(setup_)).refused);
  EXPECT_TRUE(std::equal(drawn.begin(), drawn.end(), frame.pixels().begin()));
  EXPECT_FALSE(HoleFiller(frame).fill(frame, bridgeDepthLimit(setup_)).refused);
  EXPECT_EQ(bridgeDepthLimit(FrameSetup{}), 0u);

  std::vector<std::uint8_t> rgb(320 * 240 * 3 - 1, 7);
  EXPECT_FALSE(resolveToRgb(frame, *model_, {}, rgb));
  EXPECT_TRUE(std::all_of(rgb.begin(), rgb.end(), [](std::uint8_t byte) { return byte == 7; }));
  EXPECT_EQ(countEnclosedEmptyPixels(frame, Framebuffer(10, 10), 4), -1);
}

TEST(ZoomRatio, APlainRatioBecomesTheNearestQ16Zoom) {
  EXPECT_EQ(zoomRatio(3, 2)->raw(), 3 * 32768);
  EXPECT_EQ(zoomRatio(1, 3)->raw(), 21845);  // 65536 / 3 = 21845.33
  EXPECT_EQ(zoomRatio(32767, 1)->raw(), 32767 * 65536);
  EXPECT_FALSE(zoomRatio(0, 1));
  EXPECT_FALSE(zoomRatio(-1, 2));
  EXPECT_FALSE(zoomRatio(1, 0));
  EXPECT_FALSE(zoomRatio(1, 1 << 20));  // rounds to 0
  EXPECT_FALSE(zoomRatio(40000, 1));    // past Q16.16
}

// The one-call path draws exactly what the detailed API draws, and refuses what it cannot do.
TEST_F(ApiMisuse, RgbRendererDrawsWhatTheDetailedApiDraws) {
  Camera camera;
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = *zoomRatio(3, 2);
  for (const bool fill : {false, true}) {
    const LevelView& level = model_->finestLevel();
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup),
              CameraError::kNone);
    Framebuffer frame(setup);
    ASSERT_TRUE(renderLevel(defaultVariant(), level, setup, frame));
    if (fill) {
      ASSERT_FALSE(HoleFiller(frame).fill(frame, bridgeDepthLimit(setup)).refused);
    }
    std::vector<std::uint8_t> expected(320 * 240 * 3);
    ASSERT_TRUE(resolveToRgb(frame, *model_, {1, 2, 3}, expected));

    RgbRenderer renderer;
    std::vector<std::uint8_t> rgb(320 * 240 * 3);
    DrawOptions options;
    options.depth = level.depth;
    options.fill_holes = fill;
    options.background = {1, 2, 3};
    ASSERT_EQ(renderer.draw(*model_, camera, rgb, options), DrawError::kNone);
    EXPECT_EQ(rgb, expected) << "fill " << fill;
    EXPECT_EQ(renderer.drawnDepth(), level.depth);
  }
}

TEST_F(ApiMisuse, RgbRendererRefusesWhatItCannotDraw) {
  RgbRenderer renderer;
  Camera camera;
  std::vector<std::uint8_t> rgb(320 * 240 * 3, 9);
  EXPECT_EQ(renderer.draw(*model_, camera, std::span(rgb).first(100)), DrawError::kRgbTooSmall);
  DrawOptions options;
  options.depth = 3;
  EXPECT_EQ(renderer.draw(*model_, camera, rgb, options), DrawError::kNoSuchDepth);
  Camera huge = camera;
  huge.width = 0;
  EXPECT_EQ(renderer.draw(*model_, huge, rgb), DrawError::kNoSuchDepth);  // no depth suits it
  options.depth = level_->depth;
  EXPECT_EQ(renderer.draw(*model_, huge, rgb, options), DrawError::kBadCamera);
  EXPECT_EQ(renderer.cameraError(), CameraError::kBadViewport);
  EXPECT_TRUE(std::all_of(rgb.begin(), rgb.end(), [](std::uint8_t byte) { return byte == 9; }));
  EXPECT_EQ(renderer.draw(*model_, camera, rgb), DrawError::kNone);  // depth auto
  EXPECT_GT(renderer.drawnDepth(), 0);
}

}  // namespace
}  // namespace octopoint
