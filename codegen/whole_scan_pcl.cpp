// prepareWholeScan in octopoint-prepare-pcl: the scan loaded through PCL (codegen/whole_scan.h).
#include <cctype>
#include <filesystem>
#include <memory>

#include "codegen/point_source.h"
#include "codegen/prepare_error.h"
#include "codegen/scan_loader.h"
#include "codegen/whole_scan.h"

namespace octopoint::prepare {

PreparedModel prepareWholeScan(const std::string& scan_path, const PrepareOptions& options,
                               const StreamOptions& stream, PrepareSummary& summary, char**) {
  if (!options.outliers && !options.normals) {
    const std::unique_ptr<PointSource> source = openPointSource(scan_path);
    return prepareFromSource(*source, scan_path, options, stream, &summary);
  }
  // Outlier removal and normal estimation look at each point's neighbours, so the scan is loaded
  // whole through PCL.
  std::string extension = std::filesystem::path(scan_path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".las" || extension == ".laz") {
    const char* what = options.outliers ? "outlier removal (the scene's \"outliers\")"
                                        : "normal estimation (--normals)";
    throw PrepareError(scan_path + ": " + what +
                       " needs the whole scan in memory, which octopoint-prepare does for .pcd and "
                       ".ply only");
  }
  const Scan scan = loadScan(scan_path);
  PreparedModel model = prepareModel(scan, scan_path, options, stream.threads);
  summary.finite_points = scan.positions.size();
  summary.dropped_non_finite = scan.dropped_non_finite;
  summary.shading = scan.shading;
  return model;
}

}  // namespace octopoint::prepare
