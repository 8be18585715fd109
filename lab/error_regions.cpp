#include "lab/error_regions.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace octopoint::tradeoff {

const char* regionName(Region region) {
  switch (region) {
    case Region::kInterior:
      return "interior";
    case Region::kInnerBand:
      return "inner_band";
    case Region::kOuterBand:
      return "outer_band";
    case Region::kRest:
      return "rest";
  }
  return "?";
}

cv::Mat silhouetteRegions(const cv::Mat& silhouette) {
  const cv::Mat square =
      cv::getStructuringElement(cv::MORPH_RECT, {2 * kBandWidth + 1, 2 * kBandWidth + 1});
  cv::Mat interior, near;
  cv::erode(silhouette, interior, square, {-1, -1}, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::dilate(silhouette, near, square, {-1, -1}, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat regions(silhouette.size(), CV_8U);
  for (int y = 0; y < silhouette.rows; ++y) {
    const std::uint8_t* inside = silhouette.ptr<std::uint8_t>(y);
    const std::uint8_t* deep = interior.ptr<std::uint8_t>(y);
    const std::uint8_t* close = near.ptr<std::uint8_t>(y);
    std::uint8_t* out = regions.ptr<std::uint8_t>(y);
    for (int x = 0; x < silhouette.cols; ++x) {
      const Region region = deep[x] != 0     ? Region::kInterior
                            : inside[x] != 0 ? Region::kInnerBand
                            : close[x] != 0  ? Region::kOuterBand
                                             : Region::kRest;
      out[x] = static_cast<std::uint8_t>(region);
    }
  }
  return regions;
}

double RegionError::share(Region region) const {
  const double sum = total();
  return sum == 0 ? 0.0 : sse[static_cast<int>(region)] / sum;
}

double RegionError::mse(Region region) const {
  const auto r = static_cast<std::size_t>(region);
  return pixels[r] == 0 ? 0.0 : sse[r] / (static_cast<double>(pixels[r]) * channels);
}

RegionError splitSquaredError(const cv::Mat& reference, const cv::Mat& image,
                              const cv::Mat& regions) {
  if (reference.size() != image.size() || reference.type() != image.type() ||
      regions.size() != reference.size() || reference.depth() != CV_8U)
    throw std::invalid_argument("splitSquaredError: images of different sizes or types");
  const int channels = reference.channels();
  RegionError error;
  error.channels = channels;
  for (int y = 0; y < reference.rows; ++y) {
    const std::uint8_t* a = reference.ptr<std::uint8_t>(y);
    const std::uint8_t* b = image.ptr<std::uint8_t>(y);
    const std::uint8_t* region = regions.ptr<std::uint8_t>(y);
    for (int x = 0; x < reference.cols; ++x) {
      std::int64_t sum = 0;
      for (int c = 0; c < channels; ++c) {
        const int d = int{a[x * channels + c]} - int{b[x * channels + c]};
        sum += d * d;
      }
      error.sse[region[x]] += static_cast<double>(sum);
      ++error.pixels[region[x]];
    }
  }
  return error;
}

}  // namespace octopoint::tradeoff
