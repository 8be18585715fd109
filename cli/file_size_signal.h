#pragma once
// Under a file size limit (RLIMIT_FSIZE, `ulimit -f`) a write past it raises SIGXFSZ, which kills
// the process before it can clean up. Ignored, the write fails with EFBIG instead and the writer
// reports it like a full disk. The previous disposition comes back at the end of the scope.

#include <csignal>

namespace octopoint::cli {

class FileSizeSignalIgnored {
 public:
  FileSizeSignalIgnored() : previous_(std::signal(SIGXFSZ, SIG_IGN)) {}
  ~FileSizeSignalIgnored() { std::signal(SIGXFSZ, previous_); }
  FileSizeSignalIgnored(const FileSizeSignalIgnored&) = delete;
  FileSizeSignalIgnored& operator=(const FileSizeSignalIgnored&) = delete;

 private:
  void (*previous_)(int);
};

}  // namespace octopoint::cli
