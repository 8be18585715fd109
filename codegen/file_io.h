#pragma once
// Plain POSIX file access for the streamed preparer: positioned reads that several threads may do
// at once on one descriptor (pread), and anonymous temporary files for the points that do not fit
// the memory budget. Every failure is a PrepareError naming the file.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace octopoint::prepare {

class InputFile {
 public:
  explicit InputFile(const std::filesystem::path& path);  // throws PrepareError
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::uint64_t size() const { return size_; }
  // Reads exactly out.size() bytes at `offset`; throws PrepareError naming `what` when the file
  // ends first or the read fails.
  void readAt(std::uint64_t offset, std::span<std::uint8_t> out, const std::string& what) const;
  // The first byte at or after `offset` that lies in a hole of a sparse file, or size() when there
  // is none (or the file system cannot tell).
  std::uint64_t nextHole(std::uint64_t offset) const;
  // Tells the kernel the file will be read front to back (larger read-ahead).
  void adviseSequential() const;
  // The bytes readAt has read so far, from every thread.
  std::uint64_t bytesRead() const { return bytes_read_.load(std::memory_order_relaxed); }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  mutable std::atomic<std::uint64_t> bytes_read_{0};
};

// A temporary file that is unlinked as soon as it is created: it takes disk space while open and
// none once closed, whatever way the process ends.
class TempFile {
 public:
  explicit TempFile(const std::filesystem::path& directory);  // throws PrepareError
  ~TempFile();
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  // Reserves `bytes` at the end of the file (thread-safe) and returns where they begin.
  std::uint64_t reserve(std::uint64_t bytes);
  void writeAt(std::uint64_t offset, const void* data, std::size_t bytes);
  void readAt(std::uint64_t offset, void* out, std::size_t bytes) const;
  std::uint64_t bytesWritten() const;

 private:
  std::filesystem::path directory_;
  int fd_ = -1;
  std::atomic<std::uint64_t> end_{0};
};

// Free bytes for an unprivileged user on the file system holding `directory` (0 if unknown).
std::uint64_t freeDiskBytes(const std::filesystem::path& directory);

}  // namespace octopoint::prepare
