#pragma once
// Progress of long preparer steps on stderr: shown only when stderr is a terminal and only once a
// step has taken more than a second, so scripts, tests and quick runs see nothing.

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace octopoint::prepare {

class Progress {
 public:
  Progress(std::string label, std::size_t total)
      : label_(std::move(label)), total_(total), start_(std::chrono::steady_clock::now()),
        enabled_(isatty(STDERR_FILENO) != 0) {}

  ~Progress() {
    if (shown_) std::fprintf(stderr, "\r%s: done%20s\n", label_.c_str(), "");
  }

  // Call from one thread only.
  void update(std::size_t done) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    shown_ = true;
    std::fprintf(stderr, "\r%s: %zu/%zu (%zu%%)", label_.c_str(), done, total_, total_ ? 100 * done / total_ : 100);
    std::fflush(stderr);
  }

 private:
  std::string label_;
  std::size_t total_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_{};
  bool enabled_;
  bool shown_ = false;
};

}  // namespace octopoint::prepare
