#pragma once
// The one check every file a tool reads goes through before a byte of it is read: it must be a
// regular file (symbolic links followed) of at most a stated size. A directory, a FIFO (which
// would block the reader forever), a device (/dev/zero never ends), a socket, a symlink loop, a
// dangling link or an unreadable file each get their own true message, and a file past the limit
// is refused by its size, not by running out of memory.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace octopoint::cli {

inline constexpr std::uint64_t kKiB = 1024;
inline constexpr std::uint64_t kMiB = 1024 * kKiB;
inline constexpr std::uint64_t kGiB = 1024 * kMiB;

// What a tool reads and the most it reads of it. `kind` names it in messages ("scan", "scene
// file"); `max_bytes` is stated in the tool's --help and docs.
struct InputKind {
  std::string_view kind;
  std::uint64_t max_bytes;
};

// Returns the file's size, or throws cli::Error with one line "PATH: what", e.g.
//   "data/x.pcd: no such file", "out: is a directory, not a scan",
//   "/tmp/f: is a FIFO (named pipe), not a regular file: a scan must be a file",
//   "/dev/zero: is a character device, not a regular file: ...",
//   "loop.oct: too many levels of symbolic links (a symlink loop?)",
//   "big.pcd: 2147483648 bytes, more than the 1 GiB a scan may have".
std::uint64_t checkInputFile(const std::filesystem::path& path, const InputKind& input);

// A file read in parts, front to back, for readers that check what its first bytes declare
// before they read the rest: checked as checkInputFile does, then opened without blocking (a FIFO
// put in its place after the check cannot hang a read) and checked again as opened.
class InputFile {
 public:
  InputFile(const std::filesystem::path& path, const InputKind& input);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  std::uint64_t size() const { return size_; }  // as opened
  // Appends the next `count` bytes to `bytes`: fewer where the file ends.
  void readUpTo(std::vector<std::uint8_t>& bytes, std::size_t count);
  // Appends the rest: up to the size the file had when opened, in one piece, and whatever it has
  // grown by since, to the limit (past it: cli::Error).
  void readRest(std::vector<std::uint8_t>& bytes);
  void readRest(std::string& bytes);

 private:
  template <typename Bytes>
  void readRestInto(Bytes& bytes);
  // Reads into [at, at + count) until it is full or the file ends; returns the bytes read.
  std::size_t readInto(char* at, std::size_t count);

  std::filesystem::path path_;
  InputKind input_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

// checkInputFile, then the whole file (InputFile::readRest): read at most to the limit, also if
// it grows.
std::string readInputFile(const std::filesystem::path& path, const InputKind& input);
// The same, as bytes.
std::vector<std::uint8_t> readInputBytes(const std::filesystem::path& path, const InputKind& input);

// "1 GiB", "512 MiB", "1 MiB", "4096 bytes": a limit as --help and messages state it.
std::string describeBytes(std::uint64_t bytes);

}  // namespace octopoint::cli
