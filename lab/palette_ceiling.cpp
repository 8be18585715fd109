#include "lab/palette_ceiling.h"

#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "lab/image_quality.h"

namespace octopoint::tradeoff {

std::vector<cv::Vec3b> frameColours(const ModelView& model, Rgb background) {
  std::vector<cv::Vec3b> colours;
  for (int i = 0; i < model.paletteCount(); ++i) {
    const Rgb colour = model.paletteColour(i);
    colours.emplace_back(colour.b, colour.g, colour.r);
  }
  colours.emplace_back(background.b, background.g, background.r);
  return colours;
}

cv::Mat nearestColours(const cv::Mat& image, const std::vector<cv::Vec3b>& colours) {
  if (image.type() != CV_8UC3 || colours.empty())
    throw std::invalid_argument("nearestColours: needs an 8-bit BGR image and a colour");
  // A reference has far fewer distinct colours than pixels (the background fills most of it):
  // each is searched once.
  std::unordered_map<std::uint32_t, std::size_t> nearest_of;
  cv::Mat out(image.size(), CV_8UC3);
  for (int y = 0; y < image.rows; ++y) {
    const cv::Vec3b* in = image.ptr<cv::Vec3b>(y);
    cv::Vec3b* to = out.ptr<cv::Vec3b>(y);
    for (int x = 0; x < image.cols; ++x) {
      const cv::Vec3b p = in[x];
      const std::uint32_t key = p[0] | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16);
      auto [at, inserted] = nearest_of.try_emplace(key, 0);
      if (inserted) {
        int best = -1;
        for (std::size_t i = 0; i < colours.size(); ++i) {
          int sum = 0;
          for (int c = 0; c < 3; ++c) {
            const int d = int{p[c]} - int{colours[i][c]};
            sum += d * d;
          }
          if (best < 0 || sum < best) best = sum, at->second = i;
        }
      }
      to[x] = colours[at->second];
    }
  }
  return out;
}

double paletteCeilingPsnr(const cv::Mat& reference, const std::vector<cv::Vec3b>& colours) {
  return psnr(reference, nearestColours(reference, colours));
}

}  // namespace octopoint::tradeoff
