#include "tools/view_overlay.h"

#include <opencv2/imgproc.hpp>

namespace octopoint {
namespace {

constexpr double kFontScale = 0.55;
constexpr int kLineHeight = 20;  // pixels, for kFontScale
constexpr int kMargin = 8;
constexpr std::int64_t kRateWindowUs = 1'000'000;

}  // namespace

OverlayLines Overlay::lines() const {
  OverlayLines lines;
  for (const Source& source : sources_) source(lines);
  return lines;
}

void Overlay::draw(cv::Mat& image, const OverlayLines& lines) {
  int baseline_y = kMargin + kLineHeight - 8;
  for (const std::string& line : lines) {
    const cv::Point origin{kMargin, baseline_y};
    cv::putText(image, line, origin, cv::FONT_HERSHEY_SIMPLEX, kFontScale, {0, 0, 0}, 3,
                cv::LINE_AA);
    cv::putText(image, line, origin, cv::FONT_HERSHEY_SIMPLEX, kFontScale, {255, 255, 255}, 1,
                cv::LINE_AA);
    baseline_y += kLineHeight;
  }
}

void RateCounter::record(std::int64_t now_us, std::uint64_t total) {
  samples_.emplace_back(now_us, total);
  // Keep one sample at or before the window's start, as the base the growth is counted from.
  while (samples_.size() > 2 && samples_[1].first <= now_us - kRateWindowUs) samples_.pop_front();
}

std::uint64_t RateCounter::perSecond() const {
  if (samples_.size() < 2) return 0;
  return samples_.back().second - samples_.front().second;
}

}  // namespace octopoint
