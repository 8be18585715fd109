#pragma once
// Progress of long preparer steps on stderr: shown only once a step has taken more than a second,
// and by default only when stderr is a terminal, so scripts, tests and quick runs see nothing.
// `octopoint-prepare --progress` shows it anyway; then, when stderr is not a terminal, each update
// is a line of its own (once a second) instead of a line redrawn in place.
//
//   binning: 41.2 of 100.0 M points (41%), 5.3 M points/s, 11 s left

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace octopoint::prepare {

class Progress {
 public:
  // `unit` names what is counted ("points"); large counts are then shown in millions with a rate.
  Progress(std::string label, std::size_t total, std::string unit = "")
      : label_(std::move(label)),
        unit_(std::move(unit)),
        total_(total),
        start_(std::chrono::steady_clock::now()),
        terminal_(isatty(STDERR_FILENO) != 0),
        enabled_(terminal_ || forced()) {}

  ~Progress() {
    if (shown_ && terminal_) std::fprintf(stderr, "\r%s: done%50s\n", label_.c_str(), "");
  }

  static void force(bool on) { forcedFlag().store(on); }

  // Call from one thread only.
  void update(std::size_t done) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    const auto every = terminal_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(1000);
    if (now - start_ < std::chrono::seconds(1) || now - last_ < every) return;
    last_ = now;
    shown_ = true;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const unsigned percent =
        total_
            ? static_cast<unsigned>(100.0 * static_cast<double>(done) / static_cast<double>(total_))
            : 100;
    char text[160];
    if (unit_.empty()) {
      std::snprintf(text, sizeof text, "%s: %zu/%zu (%u%%)", label_.c_str(), done, total_, percent);
    } else {
      const double rate = static_cast<double>(done) / seconds;
      const double left =
          rate > 0 ? static_cast<double>(total_ - std::min(done, total_)) / rate : 0;
      std::snprintf(text, sizeof text, "%s: %.1f of %.1f M %s (%u%%), %.1f M %s/s, %.0f s left",
                    label_.c_str(), static_cast<double>(done) / 1e6,
                    static_cast<double>(total_) / 1e6, unit_.c_str(), percent, rate / 1e6,
                    unit_.c_str(), left);
    }
    if (terminal_) {
      std::fprintf(stderr, "\r%-78s", text);
    } else {
      std::fprintf(stderr, "%s\n", text);
    }
    std::fflush(stderr);
  }

 private:
  static std::atomic<bool>& forcedFlag() {
    static std::atomic<bool> flag{false};
    return flag;
  }
  static bool forced() { return forcedFlag().load(); }

  std::string label_;
  std::string unit_;
  std::size_t total_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_{};
  bool terminal_;
  bool enabled_;
  bool shown_ = false;
};

}  // namespace octopoint::prepare
