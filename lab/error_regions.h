#pragma once
// Where a frame's squared error lies (docs/tradeoff.md, "The measures"): every pixel falls in one
// region of the reference's silhouette, by its distance from the outline, and the squared error
// PSNR sums is split over the regions.

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>

namespace octopoint::tradeoff {

// The width of the bands on either side of the silhouette's outline, in pixels.
inline constexpr int kBandWidth = 2;

enum class Region : std::uint8_t {
  kInterior,   // silhouette pixels with a (2 kBandWidth + 1)^2 square of silhouette around them
  kInnerBand,  // the other silhouette pixels: within kBandWidth pixels inside the outline
  kOuterBand,  // not silhouette, but within kBandWidth pixels (that square) of a silhouette pixel
  kRest,       // everything farther out
};
inline constexpr int kRegionCount = 4;
const char* regionName(Region region);

// Each pixel's Region (CV_8U) for a silhouette (CV_8U, non-zero = object). Outside the frame
// counts as outside the silhouette: a silhouette pixel on the frame's border is never interior.
cv::Mat silhouetteRegions(const cv::Mat& silhouette);

// The squared error of `image` against `reference` (8-bit, same size and channels), summed over
// the channels of each region's pixels: the sum of the four is what PSNR's mean is made of.
struct RegionError {
  std::array<double, kRegionCount> sse{};
  std::array<std::int64_t, kRegionCount> pixels{};
  int channels = 0;
  double total() const { return sse[0] + sse[1] + sse[2] + sse[3]; }
  // The region's part of the total squared error (0 when there is none).
  double share(Region region) const;
  // The mean squared error over the region's pixels and channels, as PSNR's (0 when empty).
  double mse(Region region) const;
};
RegionError splitSquaredError(const cv::Mat& reference, const cv::Mat& image,
                              const cv::Mat& regions);

}  // namespace octopoint::tradeoff
