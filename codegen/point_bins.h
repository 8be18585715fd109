#pragma once
// Points binned by the top digits of their Morton key, in memory up to a budget and in temporary
// files beyond it. A bin is a contiguous range of keys, so bins processed one by one and put side
// by side are already in the octree's depth-first order; and what lands in a bin does not depend on
// how the input was split between threads or where the buffers happened to fill up.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "codegen/file_io.h"
#include "codegen/huge_pages.h"

namespace octopoint::prepare {

// One point as the bins store it: its Morton key at the model's finest depth and its payload
// (0xRRGGBB, or the bits of a float intensity). 12 bytes, so 10^8 points take 1.2 GB.
struct BinnedPoint {
  std::uint32_t key_low;
  std::uint32_t key_high;
  std::uint32_t payload;

  static BinnedPoint make(std::uint64_t key, std::uint32_t payload) {
    return {static_cast<std::uint32_t>(key), static_cast<std::uint32_t>(key >> 32), payload};
  }
  std::uint64_t key() const { return std::uint64_t{key_high} << 32 | key_low; }
};
static_assert(sizeof(BinnedPoint) == 12);

// A buffer of points whose slots are not zeroed when it grows: every slot is written before it is
// read, and zeroing gigabytes would cost as much as using them.
class PointBuffer {
 public:
  // The first `count` slots; earlier contents are kept only while the buffer does not grow.
  std::span<BinnedPoint> resize(std::size_t count) {
    if (count > capacity_) {
      data_ = std::make_unique_for_overwrite<BinnedPoint[]>(count);
      capacity_ = count;
      adviseHugePages(data_.get(), count * sizeof(BinnedPoint));
    }
    size_ = count;
    return span();
  }
  std::span<BinnedPoint> span() const { return {data_.get(), size_}; }

 private:
  std::unique_ptr<BinnedPoint[]> data_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

// Some of a bin's points: `count` of them in memory at `memory`, or in `file` at byte `offset`.
struct BinPiece {
  const BinnedPoint* memory = nullptr;
  const TempFile* file = nullptr;
  std::uint64_t offset = 0;
  std::uint64_t count = 0;
};

struct BinContents {
  std::vector<BinPiece> pieces;
  std::uint64_t count = 0;
  void add(const BinPiece& piece) {
    pieces.push_back(piece);
    count += piece.count;
  }
};

// Copies every point of `bin` to `out` (which holds bin.count points).
void gatherBin(const BinContents& bin, std::span<BinnedPoint> out);

// Calls visit(span of const points) on the points of `bin` in blocks of at most buffer.size(), read
// into `buffer` (file pieces) or straight from memory.
template <typename Visit>
void forEachBlock(const BinContents& bin, std::span<BinnedPoint> buffer, Visit visit);

// Reorders `points` so that they are grouped by bin ((key >> bin_shift) & (bin_count - 1), where
// bin_count is a power of 2), in bin order, in place (American flag sort: one counting pass, then
// cycles of swaps). Returns the start of each group, bin_count + 1 entries.
std::vector<std::uint64_t> partitionByBin(std::span<BinnedPoint> points, int bin_shift,
                                          std::size_t bin_count);

// A temporary file made on first use, shared by several spillers.
class SpillFile {
 public:
  explicit SpillFile(std::filesystem::path directory) : directory_(std::move(directory)) {}
  TempFile& get();
  std::uint64_t bytesWritten() const;

 private:
  std::filesystem::path directory_;
  std::once_flag once_;
  std::unique_ptr<TempFile> file_;
};

// Gathers points in a buffer of at most `capacity` points; a full buffer is grouped by bin and
// written to the spill file as one run. One spiller per thread.
class BinSpiller {
 public:
  // A buffer of its own of `capacity` points (allocated, not zeroed: pages are taken as filled).
  BinSpiller(int bin_shift, std::size_t bin_count, std::size_t capacity, SpillFile& spill);
  // The caller's buffer.
  BinSpiller(int bin_shift, std::size_t bin_count, std::span<BinnedPoint> buffer, SpillFile& spill);

  void add(const BinnedPoint& point) {
    if (size_ == capacity_) writeRun();
    buffer_[size_++] = point;
  }
  // Hands every point gathered over to `bins` (bin_count entries): the runs written and, if
  // keep_tail, the points still buffered (then grouped in place; the spiller must outlive their
  // use), else those written as one more run.
  void finish(bool keep_tail, std::vector<BinContents>& bins);
  // Groups the points still buffered by bin, which finish(true, ...) does if not done before:
  // callable on several spillers at once, from different threads.
  void groupTail();

 private:
  void writeRun();

  int bin_shift_;
  std::size_t bin_count_;
  std::size_t capacity_;
  std::unique_ptr<BinnedPoint[]> owned_;
  BinnedPoint* buffer_ = nullptr;
  std::size_t size_ = 0;
  SpillFile& spill_;
  struct Run {
    std::uint64_t offset;
    std::vector<std::uint64_t> starts;  // per bin, in points from the run's start
  };
  std::vector<Run> runs_;
  std::vector<std::uint64_t> tail_starts_;  // once grouped
};

template <typename Visit>
void forEachBlock(const BinContents& bin, std::span<BinnedPoint> buffer, Visit visit) {
  for (const BinPiece& piece : bin.pieces) {
    if (piece.memory) {
      visit(std::span<const BinnedPoint>(piece.memory, piece.count));
      continue;
    }
    for (std::uint64_t done = 0; done < piece.count;) {
      const std::uint64_t n = std::min<std::uint64_t>(buffer.size(), piece.count - done);
      piece.file->readAt(piece.offset + done * sizeof(BinnedPoint), buffer.data(),
                         n * sizeof(BinnedPoint));
      visit(std::span<const BinnedPoint>(buffer.first(n)));
      done += n;
    }
  }
}

}  // namespace octopoint::prepare
