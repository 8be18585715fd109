#pragma once
// The time source of the interactive renderer (docs/design.md section 5), injectable so that
// scripted tests run on a clock they set themselves. Time is an integer count of microseconds.

#include <chrono>
#include <cstdint>
#include <mutex>

namespace octopoint {

class Clock {
 public:
  virtual ~Clock() = default;
  virtual std::int64_t nowMicroseconds() const = 0;
};

// Real time, monotonic.
class SteadyClock final : public Clock {
 public:
  std::int64_t nowMicroseconds() const override {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
};

// A clock that only moves when told to (scripted timelines, tests). A mutex rather than a 64-bit
// atomic: ARMv5 has no lock-free 64-bit atomics.
class ManualClock final : public Clock {
 public:
  std::int64_t nowMicroseconds() const override {
    const std::lock_guard lock(mutex_);
    return now_us_;
  }
  void set(std::int64_t now_us) {
    const std::lock_guard lock(mutex_);
    now_us_ = now_us;
  }

 private:
  mutable std::mutex mutex_;
  std::int64_t now_us_ = 0;
};

}  // namespace octopoint
