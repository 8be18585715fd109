// libFuzzer harness for the scan header checks (codegen/scan_header_check.cpp), the plain parsing
// that stands between an untrusted .pcd/.ply file and PCL's readers. The checks read a file, so
// each input is written to an in-memory file (memfd) and checked as PCD and as PLY. A malformed
// header must end in PrepareError, nothing else: no other exception, no crash, no sanitizer report.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "codegen/prepare_error.h"
#include "codegen/scan_header_check.h"

namespace {

using namespace octopoint::prepare;

// One memfd for the whole run, rewritten for every input; its /proc path is what the checks open.
class MemoryFile {
 public:
  MemoryFile() : fd_(::memfd_create("octopoint_scan_header_fuzz", 0)) {
    if (fd_ < 0) std::abort();
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) {
    if (::ftruncate(fd_, 0) != 0) std::abort();
    std::size_t done = 0;
    while (done < size) {
      const ssize_t wrote = ::pwrite(fd_, data + done, size - done, static_cast<off_t>(done));
      if (wrote <= 0) std::abort();
      done += static_cast<std::size_t>(wrote);
    }
    return path_;
  }

 private:
  int fd_;
  std::filesystem::path path_;
};

template <typename Check>
void expectCleanOutcome(Check check) {
  try {
    if (check() == 0) std::abort();  // an accepted header always declares points
  } catch (const PrepareError& error) {
    // The message is the CLI's one stderr line: it must be exactly one line.
    if (std::string(error.what()).find('\n') != std::string::npos) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static MemoryFile file;
  const std::filesystem::path& path = file.write(data, size);
  expectCleanOutcome([&] { return checkPcdHeader(path, size); });
  expectCleanOutcome([&] { return checkPlyHeader(path, size); });
  return 0;
}
