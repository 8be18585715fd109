#include "codegen/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "codegen/prepare_error.h"
#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

std::string errnoText() { return std::strerror(errno); }

}  // namespace

InputFile::InputFile(const std::filesystem::path& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) fail(path, "cannot open the file for reading: " + errnoText(), "opening the scan");
  struct stat status {};
  if (::fstat(fd_, &status) != 0) {
    const std::string why = errnoText();
    ::close(fd_);
    fail(path, "cannot read the file size: " + why, "opening the scan");
  }
  size_ = static_cast<std::uint64_t>(status.st_size);
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

void InputFile::readAt(std::uint64_t offset, std::span<std::uint8_t> out,
                       const std::string& what) const {
  std::size_t done = 0;
  while (done < out.size()) {
    const ssize_t got =
        ::pread(fd_, out.data() + done, out.size() - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0)
      fail(path_, "read failed: " + errnoText(), what + ", byte " + std::to_string(offset + done));
    if (got == 0) {
      fail(path_, "truncated: the file ends at byte " + std::to_string(offset + done), what);
    }
    done += static_cast<std::size_t>(got);
  }
  bytes_read_.fetch_add(out.size(), std::memory_order_relaxed);
}

std::uint64_t InputFile::nextHole(std::uint64_t offset) const {
  if (offset >= size_) return size_;
  const off_t hole = ::lseek(fd_, static_cast<off_t>(offset), SEEK_HOLE);
  return hole < 0 ? size_ : static_cast<std::uint64_t>(hole);
}

void InputFile::adviseSequential() const { ::posix_fadvise(fd_, 0, 0, POSIX_FADV_SEQUENTIAL); }

TempFile::TempFile(const std::filesystem::path& directory) : directory_(directory) {
  std::string name = (directory / "octopoint-prepare-XXXXXX").string();
  std::vector<char> buffer(name.begin(), name.end());
  buffer.push_back('\0');
  fd_ = ::mkstemp(buffer.data());
  if (fd_ < 0) {
    fail(directory, "cannot create a temporary file: " + errnoText(),
         "temporary directory (--temp-dir)");
  }
  ::unlink(buffer.data());  // gone from the directory now; the space is freed on close
}

TempFile::~TempFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::uint64_t TempFile::reserve(std::uint64_t bytes) { return end_.fetch_add(bytes); }

std::uint64_t TempFile::bytesWritten() const { return end_.load(); }

void TempFile::writeAt(std::uint64_t offset, const void* data, std::size_t bytes) {
  const auto* from = static_cast<const char*>(data);
  std::size_t done = 0;
  while (done < bytes) {
    const ssize_t wrote =
        ::pwrite(fd_, from + done, bytes - done, static_cast<off_t>(offset + done));
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) {
      fail(directory_,
           "writing a temporary file failed: " + errnoText() + " (disk full? use --temp-dir)",
           "spilling points beyond --memory");
    }
    done += static_cast<std::size_t>(wrote);
  }
}

void TempFile::readAt(std::uint64_t offset, void* out, std::size_t bytes) const {
  auto* to = static_cast<char*>(out);
  std::size_t done = 0;
  while (done < bytes) {
    const ssize_t got = ::pread(fd_, to + done, bytes - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0)
      fail(directory_, "reading a temporary file back failed: " + errnoText(), "spilled points");
    done += static_cast<std::size_t>(got);
  }
}

std::uint64_t freeDiskBytes(const std::filesystem::path& directory) {
  struct statvfs stats {};
  if (::statvfs(directory.c_str(), &stats) != 0) return 0;
  return static_cast<std::uint64_t>(stats.f_bavail) * stats.f_frsize;
}

}  // namespace octopoint::prepare
