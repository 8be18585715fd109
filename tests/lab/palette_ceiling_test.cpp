// The palette ceiling of lab/palette_ceiling.h: the reference in the nearest frame colours, found
// here by brute force, scores exactly the ceiling; no frame of those colours scores more; and a
// real frame of the default model, drawn and hole-filled, holds only those colours.
#include "lab/palette_ceiling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "lab/image_quality.h"
#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint::tradeoff {
namespace {

cv::Mat randomImage(int seed, int width = 24, int height = 16) {
  cv::Mat image(height, width, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, cv::Scalar::all(0), cv::Scalar::all(256));
  return image;
}

std::vector<cv::Vec3b> randomColours(int seed, int count) {
  const cv::Mat image = randomImage(seed, count, 1);
  return {image.begin<cv::Vec3b>(), image.end<cv::Vec3b>()};
}

TEST(PaletteCeiling, KnownAnswer) {
  const std::vector<cv::Vec3b> colours{{0, 0, 0}, {100, 100, 100}};
  cv::Mat reference(1, 2, CV_8UC3);
  reference.at<cv::Vec3b>(0, 0) = {40, 40, 40};  // nearer black: 3 x 40^2 = 4800
  reference.at<cv::Vec3b>(0, 1) = {90, 90, 90};  // nearer grey: 3 x 10^2 = 300
  const double mse = (4800.0 + 300.0) / 6;
  EXPECT_NEAR(paletteCeilingPsnr(reference, colours), 10 * std::log10(255.0 * 255.0 / mse), 1e-9);
}

TEST(PaletteCeiling, TheReferenceQuantizedByBruteForceScoresExactlyTheCeiling) {
  const cv::Mat reference = randomImage(1);
  const std::vector<cv::Vec3b> colours = randomColours(2, 7);
  cv::Mat quantized(reference.size(), CV_8UC3);
  for (int y = 0; y < reference.rows; ++y) {
    for (int x = 0; x < reference.cols; ++x) {
      double best = 1e18;
      for (const cv::Vec3b& colour : colours) {
        const cv::Vec3b p = reference.at<cv::Vec3b>(y, x);
        const double d = cv::norm(cv::Vec3d(p) - cv::Vec3d(colour), cv::NORM_L2SQR);
        if (d < best) best = d, quantized.at<cv::Vec3b>(y, x) = colour;
      }
    }
  }
  EXPECT_EQ(psnr(reference, quantized), paletteCeilingPsnr(reference, colours));
}

TEST(PaletteCeiling, NoFrameOfThoseColoursScoresMore) {
  const cv::Mat reference = randomImage(3);
  const std::vector<cv::Vec3b> colours = randomColours(4, 5);
  const double ceiling = paletteCeilingPsnr(reference, colours);
  cv::RNG rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    // The quantized reference with a few pixels changed to another frame colour.
    cv::Mat frame = nearestColours(reference, colours);
    for (int k = 0; k < 1 + trial % 4; ++k) {
      frame.at<cv::Vec3b>(rng.uniform(0, frame.rows), rng.uniform(0, frame.cols)) =
          colours[rng.uniform(0, static_cast<int>(colours.size()))];
    }
    EXPECT_LE(psnr(reference, frame), ceiling);
  }
}

// The premise: a plain frame, decoded and hole-filled, holds only palette colours and the
// background, so its PSNR against any reference (here a blurred copy, whose colours are not the
// palette's) stays under the ceiling.
TEST(PaletteCeiling, ADrawnAndFilledFrameHoldsOnlyTheFrameColours) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model) << describe(issue.error);
  const Rgb background{236, 236, 240};
  Camera camera;
  camera.width = 160;
  camera.height = 120;
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = Q16::fromRaw(2 * Q16::kOneRaw);  // zoomed in: holes for the filler to fill
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, model->finestLevel().depth, kDefaultFractionBits, &setup),
            CameraError::kNone);
  setup.splat = SplatFootprint{};
  Framebuffer frame(camera.width, camera.height);
  ASSERT_TRUE(renderLevel(defaultVariant(), model->finestLevel(), setup, frame));
  HoleFiller filler(camera.width);
  ASSERT_GT(filler.fill(frame, bridgeDepthLimit(setup)).total(), 0);
  cv::Mat rgb(camera.height, camera.width, CV_8UC3), image;
  ASSERT_TRUE(resolveToRgb(frame, *model, background, {rgb.data, rgb.total() * 3}));
  cv::cvtColor(rgb, image, cv::COLOR_RGB2BGR);

  const std::vector<cv::Vec3b> colours = frameColours(*model, background);
  ASSERT_EQ(static_cast<int>(colours.size()), model->paletteCount() + 1);
  const cv::Mat quantized = nearestColours(image, colours);
  EXPECT_EQ(cv::norm(image, quantized, cv::NORM_L1), 0);  // every pixel is a frame colour
  cv::Mat reference;
  cv::GaussianBlur(image, reference, cv::Size(5, 5), 1.5);
  EXPECT_LE(psnr(reference, image), paletteCeilingPsnr(reference, colours));
  EXPECT_LT(paletteCeilingPsnr(reference, colours), 100);  // the blur left non-palette colours
}

}  // namespace
}  // namespace octopoint::tradeoff
