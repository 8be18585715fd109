#include "lab/voxel_cover.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "octopoint/camera.h"

namespace octopoint::tradeoff {

int voxelCoverFactor(int width, int height) {
  for (const int factor : {5, 3}) {
    if (std::int64_t{factor} * width <= kMaxViewportSide &&
        std::int64_t{factor} * height <= kMaxViewportSide)
      return factor;
  }
  return 1;
}

cv::Mat sampleAtPixelCentres(const cv::Mat& big, int factor) {
  if (factor < 1 || factor % 2 == 0 || big.cols % factor != 0 || big.rows % factor != 0)
    throw std::invalid_argument("sampleAtPixelCentres: an odd factor that divides the size");
  cv::Mat small(big.rows / factor, big.cols / factor, big.type());
  const std::size_t pixel = big.elemSize();
  for (int y = 0; y < small.rows; ++y) {
    const std::uint8_t* row = big.ptr<std::uint8_t>(factor * y + factor / 2);
    std::uint8_t* out = small.ptr<std::uint8_t>(y);
    for (int x = 0; x < small.cols; ++x) {
      const std::uint8_t* from = row + (static_cast<std::size_t>(factor) * x + factor / 2) * pixel;
      std::copy(from, from + pixel, out + static_cast<std::size_t>(x) * pixel);
    }
  }
  return small;
}

}  // namespace octopoint::tradeoff
