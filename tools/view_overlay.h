#pragma once
// The text the viewer prints over the picture: lines from any number of sources, asked afresh
// each time the window is drawn (the viewer redraws when the text changes, so a source may report
// something that changes without a new frame, such as bytes received), and the rate counters the
// default lines show.
//
// To add lines (bytes received, chunks pending, the light's direction): one add() call in
// tools/view_main.cpp with a function that appends them.

#include <cstdint>
#include <deque>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

namespace octopoint {

using OverlayLines = std::vector<std::string>;

class Overlay {
 public:
  using Source = std::function<void(OverlayLines& lines)>;

  void add(Source source) { sources_.push_back(std::move(source)); }
  // Every source's lines, in the order they were added.
  OverlayLines lines() const;
  // Draws `lines` at the top left of an RGB or BGR image, white on a dark outline.
  static void draw(cv::Mat& image, const OverlayLines& lines);

 private:
  std::vector<Source> sources_;
};

// Events per second from a running total: how much the total grew since the newest record that
// is at least a second old (so over one second plus at most one gap between records; the viewer
// records at least every 100 ms tick).
class RateCounter {
 public:
  // The total as of `now_us` (totals never decrease).
  void record(std::int64_t now_us, std::uint64_t total);
  // The growth described above; before the first second, the growth since the first record.
  std::uint64_t perSecond() const;

 private:
  // (time, total) samples: every one of the last second, and the newest older one as the base.
  std::deque<std::pair<std::int64_t, std::uint64_t>> samples_;
};

}  // namespace octopoint
