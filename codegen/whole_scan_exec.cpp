// prepareWholeScan in octopoint-prepare, which links no PCL: hands the run over to
// octopoint-prepare-pcl (codegen/whole_scan.h). Nothing has been written yet at that point, and
// the program that takes over reads the same arguments, so the run is the same as if it had been
// started in the first place: same output, messages and exit status.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "codegen/prepare_error.h"
#include "codegen/whole_scan.h"

namespace octopoint::prepare {

PreparedModel prepareWholeScan(const std::string& scan_path, const PrepareOptions&,
                               const StreamOptions&, PrepareSummary&, char** argv) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path helper = self.parent_path() / kWholeScanProgram;
  std::fflush(nullptr);
  ::execv(helper.c_str(), argv);
  throw PrepareError(scan_path + ": this scan is read whole through PCL, by " + helper.string() +
                     ", which cannot be run (" + std::strerror(errno) + ")");
}

}  // namespace octopoint::prepare
