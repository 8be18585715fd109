// The exact voxel cover (lab/voxel_cover.h): sampling at pixel centres, and a frame whose leaves
// splat along x drawn at five times its size and sampled back is (nearly) that frame: its
// footprint is already the exact cover along x, and along y, where a voxel spans under a pixel,
// the one pixel holding a leaf's centre is the cover's pixel wherever the cube holds that centre.
#include "lab/voxel_cover.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "lab/image_quality.h"
#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint::tradeoff {
namespace {

TEST(VoxelCover, SamplesTheCentreOfEachPixel) {
  cv::Mat big(10, 15, CV_8UC1);
  for (int y = 0; y < big.rows; ++y)
    for (int x = 0; x < big.cols; ++x)
      big.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(x + 16 * y);
  const cv::Mat small = sampleAtPixelCentres(big, 5);
  ASSERT_EQ(small.cols, 3);
  ASSERT_EQ(small.rows, 2);
  EXPECT_EQ(small.at<std::uint8_t>(0, 0), 2 + 16 * 2);
  EXPECT_EQ(small.at<std::uint8_t>(1, 2), 12 + 16 * 7);
  EXPECT_THROW(sampleAtPixelCentres(big, 2), std::invalid_argument);
  EXPECT_THROW(sampleAtPixelCentres(big, 3), std::invalid_argument);  // 3 does not divide 10
  EXPECT_EQ(voxelCoverFactor(1280, 960), 5);
  EXPECT_EQ(voxelCoverFactor(1920, 1080), 3);
  EXPECT_EQ(voxelCoverFactor(4096, 2), 1);
}

cv::Mat drawn(const ModelView& model, Camera camera, int factor) {
  camera.width *= factor;
  camera.height *= factor;
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, model.finestLevel().depth, kDefaultFractionBits, &setup),
            CameraError::kNone);
  Framebuffer frame(camera.width, camera.height);
  EXPECT_TRUE(renderLevel(defaultVariant(), model.finestLevel(), setup, frame));
  cv::Mat rgb(camera.height, camera.width, CV_8UC3);
  EXPECT_TRUE(resolveToRgb(frame, model, Rgb{236, 236, 240}, {rgb.data, rgb.total() * 3}));
  return rgb;
}

double differingShare(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat difference, grey;
  cv::absdiff(a, b, difference);
  cv::cvtColor(difference, grey, cv::COLOR_RGB2GRAY);
  return static_cast<double>(cv::countNonZero(grey)) / static_cast<double>(grey.total());
}

TEST(VoxelCover, AFrameThatSplatsAlongXIsNearlyItsOwnCover) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model) << describe(issue.error);
  Camera camera;
  camera.width = 320;
  camera.height = 240;
  camera.yaw = Angle::fromDegrees(30);  // depth 8 voxels of 0.94 pixel: 2x1 splats
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, model->finestLevel().depth, kDefaultFractionBits, &setup),
            CameraError::kNone);
  ASSERT_EQ(setup.splat.columns, 2);
  ASSERT_EQ(setup.splat.rows, 1);
  const cv::Mat frame = drawn(*model, camera, 1);
  const cv::Mat big = drawn(*model, camera, 5);
  const double share = differingShare(frame, sampleAtPixelCentres(big, 5));
  EXPECT_LT(share, 0.001);  // 0.004% measured
  // Sampled a fifth of a pixel off the centres, it is no longer the frame.
  const cv::Mat shifted = big(cv::Rect(1, 1, big.cols - 1, big.rows - 1));
  cv::Mat padded;
  cv::copyMakeBorder(shifted, padded, 0, 1, 0, 1, cv::BORDER_REPLICATE);
  EXPECT_GT(differingShare(frame, sampleAtPixelCentres(padded, 5)), 0.05);  // 10.5% measured
}

}  // namespace
}  // namespace octopoint::tradeoff
