// PSNR and SSIM of lab/image_quality.h against closed forms: SSIM per channel as Wang et al. 2004
// define it, the colour figure the mean of the three channels' own figures.
#include "lab/image_quality.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace octopoint::tradeoff {
namespace {

constexpr double kC1 = (0.01 * 255) * (0.01 * 255);
constexpr double kC2 = (0.03 * 255) * (0.03 * 255);

// A textured BGR image: a different pattern in each channel, noise from a fixed seed.
cv::Mat texture(int seed) {
  cv::Mat image(48, 64, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, cv::Scalar::all(0), cv::Scalar::all(256));
  return image;
}

TEST(ImageQuality, SsimOfAnImageWithItselfIsOne) {
  const cv::Mat image = texture(1);
  EXPECT_NEAR(ssim(image, image), 1.0, 1e-6);
}

// Flat images: no variance, so the structure term is C2 / C2 = 1 and each channel's SSIM is the
// luminance term (2 mu_a mu_b + C1) / (mu_a^2 + mu_b^2 + C1). Without C1 and C2 in a channel that
// term is 0 / 0 there.
TEST(ImageQuality, SsimOfFlatImagesIsTheLuminanceTermInEveryChannel) {
  const std::array<double, 3> a{40, 100, 0}, b{60, 90, 0};
  const cv::Mat image_a(32, 32, CV_8UC3, cv::Scalar(a[0], a[1], a[2]));
  const cv::Mat image_b(32, 32, CV_8UC3, cv::Scalar(b[0], b[1], b[2]));
  double expected = 0;
  for (int channel = 0; channel < 3; ++channel) {
    const double mu_a = a[channel], mu_b = b[channel];
    expected += (2 * mu_a * mu_b + kC1) / (mu_a * mu_a + mu_b * mu_b + kC1) / 3;
  }
  const double measured = ssim(image_a, image_b);
  ASSERT_FALSE(std::isnan(measured));
  EXPECT_NEAR(measured, expected, 1e-4);
}

TEST(ImageQuality, ColourSsimIsTheMeanOfTheChannelsOwnSsim) {
  const cv::Mat image_a = texture(2);
  cv::Mat image_b;
  cv::add(image_a, texture(3) / 4, image_b);  // the same picture with noise added
  std::vector<cv::Mat> channels_a, channels_b;
  cv::split(image_a, channels_a);
  cv::split(image_b, channels_b);
  double expected = 0;
  for (int channel = 0; channel < 3; ++channel)
    expected += ssim(channels_a[channel], channels_b[channel]) / 3;
  EXPECT_LT(expected, 0.99);  // the pair differs: the test compares something
  EXPECT_NEAR(ssim(image_a, image_b), expected, 1e-6);
}

TEST(ImageQuality, PsnrOfAKnownDifference) {
  const cv::Mat image_a(16, 16, CV_8UC3, cv::Scalar(10, 20, 30));
  const cv::Mat image_b(16, 16, CV_8UC3,
                        cv::Scalar(14, 20, 30));  // squared error 16 in one channel of 3
  EXPECT_NEAR(psnr(image_a, image_b), 10 * std::log10(255.0 * 255.0 / (16.0 / 3)), 1e-9);
}

}  // namespace
}  // namespace octopoint::tradeoff
