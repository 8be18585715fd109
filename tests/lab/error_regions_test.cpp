// The regions of lab/error_regions.h on a square silhouette with known answers, and a one-pixel
// error landing in the region of its pixel.
#include "lab/error_regions.h"

#include <gtest/gtest.h>

namespace octopoint::tradeoff {
namespace {

// A 13 x 13 frame with a 7 x 7 square of silhouette at rows and columns 2..8: its interior (a
// 5 x 5 square of silhouette around the pixel) is 4..6, the inner band the rest of the square,
// the outer band the pixels within 2 (Chebyshev) of it, 0..10, and the rest is beyond.
cv::Mat squareSilhouette() {
  cv::Mat silhouette(13, 13, CV_8U, cv::Scalar(0));
  silhouette(cv::Rect(2, 2, 7, 7)).setTo(255);
  return silhouette;
}

Region regionAt(const cv::Mat& regions, int x, int y) {
  return static_cast<Region>(regions.at<std::uint8_t>(y, x));
}

TEST(ErrorRegions, RegionsOfASquare) {
  const cv::Mat regions = silhouetteRegions(squareSilhouette());
  EXPECT_EQ(regionAt(regions, 5, 5), Region::kInterior);
  EXPECT_EQ(regionAt(regions, 4, 6), Region::kInterior);
  EXPECT_EQ(regionAt(regions, 3, 5), Region::kInnerBand);
  EXPECT_EQ(regionAt(regions, 2, 2), Region::kInnerBand);
  EXPECT_EQ(regionAt(regions, 1, 5), Region::kOuterBand);
  EXPECT_EQ(regionAt(regions, 0, 0), Region::kOuterBand);  // 2 diagonal steps from (2, 2)
  EXPECT_EQ(regionAt(regions, 11, 5), Region::kRest);
  EXPECT_EQ(regionAt(regions, 12, 0), Region::kRest);
  const RegionError counts = splitSquaredError(cv::Mat(13, 13, CV_8UC3, cv::Scalar(0)),
                                               cv::Mat(13, 13, CV_8UC3, cv::Scalar(0)), regions);
  EXPECT_EQ(counts.pixels[0], 3 * 3);
  EXPECT_EQ(counts.pixels[1], 7 * 7 - 3 * 3);
  EXPECT_EQ(counts.pixels[2], 11 * 11 - 7 * 7);
  EXPECT_EQ(counts.pixels[3], 13 * 13 - 11 * 11);
  EXPECT_EQ(counts.total(), 0);
  EXPECT_EQ(counts.share(Region::kRest), 0);
}

// The silhouette reaching the frame's border: outside the frame counts as outside it.
TEST(ErrorRegions, TheFramesBorderIsAnOutline) {
  const cv::Mat regions = silhouetteRegions(cv::Mat(9, 9, CV_8U, cv::Scalar(255)));
  EXPECT_EQ(regionAt(regions, 1, 4), Region::kInnerBand);
  EXPECT_EQ(regionAt(regions, 4, 4), Region::kInterior);
}

TEST(ErrorRegions, AOnePixelErrorLandsInItsRegion) {
  const cv::Mat regions = silhouetteRegions(squareSilhouette());
  const cv::Mat reference(13, 13, CV_8UC3, cv::Scalar(50, 60, 70));
  const struct {
    int x, y;
    Region region;
  } cases[] = {{5, 5, Region::kInterior},
               {8, 3, Region::kInnerBand},
               {10, 10, Region::kOuterBand},
               {5, 12, Region::kRest}};
  for (const auto& c : cases) {
    cv::Mat image = reference.clone();
    image.at<cv::Vec3b>(c.y, c.x) = {53, 56, 70};  // squared error 9 + 16
    const RegionError error = splitSquaredError(reference, image, regions);
    for (int r = 0; r < kRegionCount; ++r) {
      const bool here = Region(r) == c.region;
      EXPECT_EQ(error.sse[r], here ? 25 : 0) << c.x << "," << c.y << " " << regionName(Region(r));
      EXPECT_EQ(error.share(Region(r)), here ? 1 : 0);
    }
  }
}

}  // namespace
}  // namespace octopoint::tradeoff
