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

// checkInputFile, then the whole file. The file is opened without blocking (a FIFO put in its
// place after the check cannot hang the read) and read at most to the limit, also if it grows.
std::string readInputFile(const std::filesystem::path& path, const InputKind& input);
// The same, as bytes.
std::vector<std::uint8_t> readInputBytes(const std::filesystem::path& path, const InputKind& input);

// "1 GiB", "512 MiB", "1 MiB", "4096 bytes": a limit as --help and messages state it.
std::string describeBytes(std::uint64_t bytes);

}  // namespace octopoint::cli
