#include "codegen/point_bins.h"

#include <cassert>
#include <cstring>
#include <utility>

namespace octopoint::prepare {

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

std::vector<std::uint64_t> partitionByBin(std::span<BinnedPoint> points, int bin_shift,
                                          std::size_t bin_count) {
  assert((bin_count & (bin_count - 1)) == 0);
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
