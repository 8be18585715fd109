#include "codegen/point_tally.h"

#include <algorithm>
#include <sstream>

#include "cli/text.h"
#include "codegen/prepare_error.h"

namespace octopoint::prepare {
namespace {

[[noreturn]] void failAbsurd(const std::string& path, const std::array<double, 3>& p,
                             std::size_t axis, double limit, std::uint64_t index) {
  std::ostringstream what;
  what << "absurd coordinate "
       << "xyz"[axis] << " = " << cli::realText(p[axis]) << ", beyond +-" << cli::realText(limit);
  throw PrepareError(path + ": " + what.str() + " (point " + std::to_string(index) + ")");
}

}  // namespace

PointFilter::PointFilter(const std::optional<CropBox>& crop, ScanAxes axes, bool float_coordinates)
    : crop_(crop.has_value()), axes_(axes) {
  if (!crop) return;
  for (std::size_t axis = 0; axis < 3; ++axis) {  // float scans see the box as cropScan does
    low_[axis] = float_coordinates ? static_cast<float>(crop->low[axis]) : crop->low[axis];
    high_[axis] = float_coordinates ? static_cast<float>(crop->high[axis]) : crop->high[axis];
  }
}

void ExactIntensity::merge(const ExactIntensity& other) {
  if (!other.started()) return;
  if (!started()) start();
  for (std::size_t v = 0; v < counts_.size(); ++v) counts_[v] += other.counts_[v];
}

IntensityRange ExactIntensity::range() const {
  std::uint64_t total = 0;
  for (std::uint64_t count : counts_) total += count;
  if (total == 0) return {};
  float found[2] = {};
  const std::uint64_t ranks[2] = {quantileRank(total, kLowIntensityQuantile),
                                  quantileRank(total, kHighIntensityQuantile)};
  for (std::size_t t = 0; t < 2; ++t) {  // the value at that rank: the first whose counts pass it
    std::uint64_t below = 0;
    std::size_t v = 0;
    while (below + counts_[v] <= ranks[t]) below += counts_[v++];
    found[t] = static_cast<float>(v);
  }
  return {found[0], found[1]};
}

std::uint16_t PointTally::add(const PointChunk& chunk, std::uint64_t first, const SourceInfo& info,
                              const PointFilter& filter, bool coarse_intensity,
                              const std::string& path) {
  const bool exact = exact_intensity.started();
  std::uint16_t brightest = 0;
  for (std::size_t i = 0; i < chunk.xyz.size(); ++i) {
    std::array<double, 3> p = chunk.xyz[i];
    if (!isFinite(p)) continue;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      if (std::fabs(p[axis]) > info.coordinate_limit) {
        failAbsurd(path, p, axis, info.coordinate_limit, first + i);
      }
    }
    ++finite;
    if (coarse_intensity) intensity.addCoarse(chunk.intensity[i]);
    if (exact) exact_intensity.add(chunk.intensity[i]);
    if (info.colour_bits_detected) {
      for (std::uint16_t channel : chunk.rgb[i]) brightest = std::max(brightest, channel);
    }
    if (filter.keep(p)) bounds.add(p);
  }
  brightest_channel = std::max(brightest_channel, brightest);
  return brightest;
}

void PointTally::merge(const PointTally& other) {
  bounds.merge(other.bounds);
  intensity.merge(other.intensity);
  exact_intensity.merge(other.exact_intensity);
  brightest_channel = std::max(brightest_channel, other.brightest_channel);
  finite += other.finite;
}

}  // namespace octopoint::prepare
