#include "codegen/intensity_grey.h"

#include <cassert>

namespace octopoint::prepare {

void IntensityPercentiles::finishCoarse() {
  finite_count_ = 0;
  for (std::uint64_t count : coarse_) finite_count_ += count;
  if (finite_count_ == 0) return;
  const std::uint64_t ranks[2] = {quantileRank(finite_count_, kLowIntensityQuantile),
                                  quantileRank(finite_count_, kHighIntensityQuantile)};
  for (std::size_t i = 0; i < 2; ++i) {
    std::uint64_t below = 0;
    std::uint32_t bucket = 0;
    while (below + coarse_[bucket] <= ranks[i]) below += coarse_[bucket++];
    targets_[i] = {bucket, ranks[i] - below};
  }
}

IntensityPercentiles IntensityPercentiles::forFinePass() const {
  IntensityPercentiles fine;
  fine.coarse_.clear();
  fine.finite_count_ = finite_count_;
  fine.targets_ = targets_;
  for (auto& counts : fine.fine_) counts.assign(kBuckets, 0);
  return fine;
}

void IntensityPercentiles::merge(const IntensityPercentiles& other) {
  for (std::size_t i = 0; i < other.coarse_.size() && i < coarse_.size(); ++i)
    coarse_[i] += other.coarse_[i];
  for (std::size_t t = 0; t < 2; ++t) {
    if (fine_[t].empty()) fine_[t].assign(other.fine_[t].size(), 0);
    for (std::size_t i = 0; i < other.fine_[t].size(); ++i) fine_[t][i] += other.fine_[t][i];
  }
}

IntensityRange IntensityPercentiles::range() const {
  if (finite_count_ == 0) return {};
  float found[2] = {};
  for (std::size_t t = 0; t < 2; ++t) {
    assert(fine_[t].size() == kBuckets);
    std::uint64_t below = 0;
    std::uint32_t low_bits = 0;
    while (below + fine_[t][low_bits] <= targets_[t].rank) below += fine_[t][low_bits++];
    found[t] = value(targets_[t].bucket << 16 | low_bits);
  }
  return {found[0], found[1]};
}

}  // namespace octopoint::prepare
