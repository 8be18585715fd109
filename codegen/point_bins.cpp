#include "codegen/point_bins.h"

#include <bit>
#include <cassert>
#include <cstring>
#include <utility>

namespace octopoint::prepare {

namespace {
constexpr int kFlagSortBits = 8;  // at most 256 groups in one pass
}  // namespace

void gatherBin(const BinContents& bin, std::span<BinnedPoint> out) {
  assert(out.size() == bin.count);
  std::size_t at = 0;
  for (const BinPiece& piece : bin.pieces) {
    if (piece.memory) {
      std::memcpy(out.data() + at, piece.memory, piece.count * sizeof(BinnedPoint));
    } else {
      piece.file->readAt(piece.offset, out.data() + at, piece.count * sizeof(BinnedPoint));
    }
    at += piece.count;
  }
}

namespace {

// One pass of partitionByBin: American flag sort into `bin_count` groups.
std::vector<std::uint64_t> flagSort(std::span<BinnedPoint> points, int bin_shift,
                                    std::size_t bin_count) {
  const auto binOf = [&](const BinnedPoint& p) {
    return static_cast<std::size_t>(p.key() >> bin_shift) & (bin_count - 1);
  };
  std::vector<std::uint64_t> starts(bin_count + 1, 0);
  for (const BinnedPoint& p : points) ++starts[binOf(p) + 1];
  for (std::size_t b = 0; b < bin_count; ++b) starts[b + 1] += starts[b];
  // next[b]: the first slot of bin b not yet holding one of its points. Each swap puts one point
  // into its bin for good, so the loop makes at most points.size() swaps.
  std::vector<std::uint64_t> next(starts.begin(), starts.end() - 1);
  for (std::size_t b = 0; b < bin_count; ++b) {
    while (next[b] < starts[b + 1]) {
      BinnedPoint& slot = points[next[b]];
      const std::size_t home = binOf(slot);
      if (home == b) {
        ++next[b];
      } else {
        std::swap(slot, points[next[home]++]);
      }
    }
  }
  return starts;
}

}  // namespace

std::vector<std::uint64_t> partitionByBin(std::span<BinnedPoint> points, int bin_shift,
                                          std::size_t bin_count) {
  assert((bin_count & (bin_count - 1)) == 0);
  // Thousands of bins at once send each swap to a far place in a buffer of tens of megabytes; a
  // pass into 2^high groups by the upper digits, then one per group into 2^low bins, keeps each
  // pass's write positions few enough to stay in the cache. (A bin's points may come out in
  // another order within it: the voxelizer sorts them by key and sums colours as integers.)
  const int bits = std::countr_zero(bin_count);
  if (bits <= kFlagSortBits) return flagSort(points, bin_shift, bin_count);
  const int low = bits / 2;
  const std::size_t low_count = std::size_t{1} << low;
  const std::vector<std::uint64_t> groups = flagSort(points, bin_shift + low, bin_count >> low);
  std::vector<std::uint64_t> starts(bin_count + 1, 0);
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    const std::vector<std::uint64_t> within =
        flagSort(points.subspan(groups[g], groups[g + 1] - groups[g]), bin_shift, low_count);
    for (std::size_t b = 0; b < low_count; ++b) starts[g * low_count + b] = groups[g] + within[b];
  }
  starts[bin_count] = points.size();
  return starts;
}

TempFile& SpillFile::get() {
  std::call_once(once_, [&] { file_ = std::make_unique<TempFile>(directory_); });
  return *file_;
}

std::uint64_t SpillFile::bytesWritten() const { return file_ ? file_->bytesWritten() : 0; }

BinSpiller::BinSpiller(int bin_shift, std::size_t bin_count, std::size_t capacity, SpillFile& spill)
    : bin_shift_(bin_shift),
      bin_count_(bin_count),
      capacity_(std::max<std::size_t>(capacity, 1)),
      owned_(std::make_unique_for_overwrite<BinnedPoint[]>(capacity_)),
      buffer_(owned_.get()),
      spill_(spill) {
  adviseHugePages(buffer_, capacity_ * sizeof(BinnedPoint));
}

BinSpiller::BinSpiller(int bin_shift, std::size_t bin_count, std::span<BinnedPoint> buffer,
                       SpillFile& spill)
    : bin_shift_(bin_shift),
      bin_count_(bin_count),
      capacity_(buffer.size()),
      buffer_(buffer.data()),
      spill_(spill) {
  assert(!buffer.empty());
}

void BinSpiller::writeRun() {
  if (size_ == 0) return;
  const std::span<BinnedPoint> points(buffer_, size_);
  Run run{0, partitionByBin(points, bin_shift_, bin_count_)};
  TempFile& file = spill_.get();
  run.offset = file.reserve(size_ * sizeof(BinnedPoint));
  file.writeAt(run.offset, points.data(), points.size_bytes());
  runs_.push_back(std::move(run));
  size_ = 0;
}

void BinSpiller::finish(bool keep_tail, std::vector<BinContents>& bins) {
  assert(bins.size() == bin_count_);
  if (!keep_tail) writeRun();
  const TempFile* file = runs_.empty() ? nullptr : &spill_.get();
  for (const Run& run : runs_) {
    for (std::size_t b = 0; b < bin_count_; ++b) {
      const std::uint64_t count = run.starts[b + 1] - run.starts[b];
      if (count)
        bins[b].add({nullptr, file, run.offset + run.starts[b] * sizeof(BinnedPoint), count});
    }
  }
  runs_.clear();
  if (size_ == 0) return;
  groupTail();
  for (std::size_t b = 0; b < bin_count_; ++b) {
    const std::uint64_t count = tail_starts_[b + 1] - tail_starts_[b];
    if (count) bins[b].add({buffer_ + tail_starts_[b], nullptr, 0, count});
  }
}

void BinSpiller::groupTail() {
  if (tail_starts_.empty()) tail_starts_ = partitionByBin({buffer_, size_}, bin_shift_, bin_count_);
}

}  // namespace octopoint::prepare
