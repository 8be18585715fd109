#include "cli/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "cli/error.h"
#include "cli/text.h"

namespace octopoint::cli {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw Error(displayPath(path) + ": " + what);
}

// "a scan", "an octopoint model".
std::string withArticle(std::string_view kind) {
  const bool vowel =
      !kind.empty() && std::string_view("aeiouAEIOU").find(kind[0]) != std::string_view::npos;
  return (vowel ? "an " : "a ") + std::string(kind);
}

// Why stat() failed, in words that point at the cause.
std::string statFailure(const std::filesystem::path& path, int error) {
  switch (error) {
    case ENOENT: {
      struct stat link {};
      if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
        return "is a dangling symbolic link (what it points to does not exist)";
      }
      return "no such file";
    }
    case ELOOP:
      return "too many levels of symbolic links (a symlink loop?)";
    case EACCES:
      return "permission denied";
    case ENOTDIR:
      return "a part of the path is not a directory";
    case ENAMETOOLONG:
      return "file name too long";
    default:
      return std::string("cannot look at it: ") + std::strerror(error);
  }
}

std::string notRegular(mode_t mode, std::string_view kind) {
  const std::string tail = ", not a regular file: " + withArticle(kind) + " must be a file";
  if (S_ISDIR(mode)) return "is a directory, not " + withArticle(kind);
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe)" + tail;
  if (S_ISCHR(mode)) return "is a character device" + tail;
  if (S_ISBLK(mode)) return "is a block device" + tail;
  if (S_ISSOCK(mode)) return "is a socket" + tail;
  return "is not a regular file: " + withArticle(kind) + " must be a file";
}

void checkStatus(const std::filesystem::path& path, const struct stat& status,
                 const InputKind& input) {
  if (!S_ISREG(status.st_mode)) fail(path, notRegular(status.st_mode, input.kind));
  const auto size = static_cast<std::uint64_t>(status.st_size);
  if (size > input.max_bytes) {
    fail(path, std::to_string(size) + " bytes, more than the " + describeBytes(input.max_bytes) +
                   " " + withArticle(input.kind) + " may have");
  }
}

}  // namespace

std::string describeBytes(std::uint64_t bytes) {
  if (bytes >= kGiB && bytes % kGiB == 0) return std::to_string(bytes / kGiB) + " GiB";
  if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  if (bytes >= kKiB && bytes % kKiB == 0) return std::to_string(bytes / kKiB) + " KiB";
  return std::to_string(bytes) + " bytes";
}

std::uint64_t checkInputFile(const std::filesystem::path& path, const InputKind& input) {
  if (path.empty()) throw Error("an empty file name was given for " + withArticle(input.kind));
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) fail(path, statFailure(path, errno));
  checkStatus(path, status, input);
  if (::access(path.c_str(), R_OK) != 0) fail(path, statFailure(path, errno));
  return static_cast<std::uint64_t>(status.st_size);
}

InputFile::InputFile(const std::filesystem::path& path, const InputKind& input)
    : path_(path), input_(input) {
  checkInputFile(path, input);
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) fail(path, statFailure(path, errno));
  struct stat status {};
  if (::fstat(fd_, &status) != 0) {
    const int error = errno;
    ::close(fd_);
    fail(path, statFailure(path, error));
  }
  try {
    checkStatus(path, status, input);  // what was opened, in case the name changed hands
  } catch (...) {
    ::close(fd_);
    throw;
  }
  size_ = static_cast<std::uint64_t>(status.st_size);
}

InputFile::~InputFile() { ::close(fd_); }

std::size_t InputFile::readInto(char* at, std::size_t count) {
  std::size_t have = 0;
  while (have < count) {
    const ssize_t got = ::read(fd_, at + have, count - have);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail(path_, std::string("read failed: ") + std::strerror(errno));
    if (got == 0) break;
    have += static_cast<std::size_t>(got);
  }
  return have;
}

void InputFile::readUpTo(std::vector<std::uint8_t>& bytes, std::size_t count) {
  const std::size_t old_size = bytes.size();
  bytes.resize(old_size + count);
  bytes.resize(old_size + readInto(reinterpret_cast<char*>(bytes.data()) + old_size, count));
}

template <typename Bytes>
void InputFile::readRestInto(Bytes& bytes) {
  // The size as opened in one buffer, never grown: growing it would copy the whole file.
  const std::size_t expected = static_cast<std::size_t>(size_);
  std::size_t have = bytes.size();
  if (have < expected) {
    bytes.resize(expected);
    have += readInto(reinterpret_cast<char*>(bytes.data()) + have, expected - have);
    bytes.resize(have);
  }
  // Whatever the file grew by meanwhile, in small reads, to one byte past the limit.
  char more[4096];
  for (;;) {
    const std::size_t room = static_cast<std::size_t>(std::min<std::uint64_t>(
        sizeof more, input_.max_bytes + 1 - std::min<std::uint64_t>(have, input_.max_bytes)));
    const std::size_t got = readInto(more, room);
    if (got == 0) break;
    bytes.insert(bytes.end(), more, more + got);
    have += got;
    if (have > input_.max_bytes) {
      fail(path_, "grew past the " + describeBytes(input_.max_bytes) + " " +
                      withArticle(input_.kind) + " may have while being read");
    }
  }
}

void InputFile::readRest(std::vector<std::uint8_t>& bytes) { readRestInto(bytes); }
void InputFile::readRest(std::string& bytes) { readRestInto(bytes); }

namespace {

template <typename Bytes>
Bytes readWhole(const std::filesystem::path& path, const InputKind& input) {
  InputFile file(path, input);
  Bytes bytes;
  file.readRest(bytes);
  return bytes;
}

}  // namespace

std::string readInputFile(const std::filesystem::path& path, const InputKind& input) {
  return readWhole<std::string>(path, input);
}

std::vector<std::uint8_t> readInputBytes(const std::filesystem::path& path,
                                         const InputKind& input) {
  return readWhole<std::vector<std::uint8_t>>(path, input);
}

}  // namespace octopoint::cli
