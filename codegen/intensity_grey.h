#pragma once
// Intensity as grey: the 1st..99th percentile of the scan's finite intensities maps linearly to
// 0..255, clamped, so that a few hot returns do not turn everything else black. One formula for
// both loaders: the in-memory one (scan_loader.cpp) finds the percentiles by sorting, the streamed
// one (IntensityPercentiles) with two histogram passes in bounded memory; both find the same
// values.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace octopoint::prepare {

inline constexpr double kLowIntensityQuantile = 0.01;
inline constexpr double kHighIntensityQuantile = 0.99;

struct IntensityRange {
  float low = 0;
  float high = 0;
};

// The 0-based rank of the nearest-rank quantile q among n > 0 sorted values.
inline std::uint64_t quantileRank(std::uint64_t n, double q) {
  return static_cast<std::uint64_t>(q * static_cast<double>(n - 1) + 0.5);
}

// Non-finite intensities are black; a constant intensity carries no shading: mid grey.
inline std::uint8_t intensityGrey(float v, const IntensityRange& range) {
  double grey = 0.0;
  if (std::isfinite(v)) {
    grey = range.high > range.low ? (static_cast<double>(v) - range.low) /
                                        (static_cast<double>(range.high) - range.low) * 255.0
                                  : 128.0;
  }
  return static_cast<std::uint8_t>(std::lround(std::clamp(grey, 0.0, 255.0)));
}

// Exact nearest-rank 1st and 99th percentiles of a float stream read twice, in 1.5 MB whatever its
// length. Floats are mapped to unsigned keys in the same order; pass 1 counts the keys' top 16
// bits, which says in which bucket each percentile lies and at which rank inside it; pass 2 counts
// the low 16 bits of the keys in those two buckets, which pins the value down. Each worker thread
// counts into its own instance; merge() adds them up (counting is order-free, so the result does
// not depend on how the stream was split).
class IntensityPercentiles {
 public:
  IntensityPercentiles() : coarse_(kBuckets, 0) {}

  // Pass 1: every finite intensity.
  void addCoarse(float v) {
    if (std::isfinite(v)) ++coarse_[key(v) >> 16];
  }
  // After pass 1 (on the merged instance): fixes the two target buckets for pass 2.
  void finishCoarse();
  // A fresh instance for one worker's pass 2, knowing the targets.
  IntensityPercentiles forFinePass() const;
  // Pass 2: every finite intensity again.
  void addFine(float v) {
    if (!std::isfinite(v)) return;
    const std::uint32_t k = key(v);
    for (std::size_t i = 0; i < 2; ++i) {
      if (k >> 16 == targets_[i].bucket) ++fine_[i][k & 0xffffu];
    }
  }
  void merge(const IntensityPercentiles& other);
  // After pass 2 (merged): the range; {0, 0} when there was no finite intensity.
  IntensityRange range() const;

 private:
  static constexpr std::size_t kBuckets = 1 << 16;
  struct Target {
    std::uint32_t bucket = 0;
    std::uint64_t rank = 0;  // inside the bucket
  };

  static std::uint32_t key(float v) {
    const auto bits = std::bit_cast<std::uint32_t>(v);
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
  }
  static float value(std::uint32_t k) {
    return std::bit_cast<float>((k & 0x80000000u) ? k & 0x7fffffffu : ~k);
  }

  std::vector<std::uint64_t> coarse_;
  std::uint64_t finite_count_ = 0;
  std::array<Target, 2> targets_{};
  std::array<std::vector<std::uint64_t>, 2> fine_;
};

}  // namespace octopoint::prepare
