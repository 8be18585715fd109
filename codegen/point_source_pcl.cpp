// openPointSource: the streamed readers, else PCL (codegen/scan_loader.h). Apart from
// point_source.cpp so that a program that never loads a scan through PCL links none of it
// (codegen/whole_scan.h).
#include "codegen/point_source.h"
#include "codegen/scan_loader.h"

namespace octopoint::prepare {

std::unique_ptr<PointSource> openPointSource(const std::filesystem::path& path) {
  if (std::unique_ptr<PointSource> streamed = openStreamedSource(path)) return streamed;
  return loadedScanSource(loadScan(path), path);
}

}  // namespace octopoint::prepare
