// libFuzzer harness for the scan header checks (codegen/scan_header_check.cpp), the plain parsing
// that stands between an untrusted .pcd/.ply file and PCL's readers. The checks read a file, so
// each input is written to an in-memory file (memfd) and checked as PCD and as PLY. A malformed
// header must end in PrepareError, nothing else: no other exception, no crash, no sanitizer report.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "codegen/prepare_error.h"
#include "codegen/scan_header_check.h"
#include "tests/support/memory_file.h"

namespace {

using namespace octopoint::prepare;

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
  static octopoint::fuzzing::MemoryFile file;
  const std::filesystem::path& path = file.write(data, size);
  expectCleanOutcome([&] { return checkPcdHeader(path, size); });
  expectCleanOutcome([&] { return checkPlyHeader(path, size); });
  return 0;
}
