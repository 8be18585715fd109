#include "codegen/prepare.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "cli/real_numbers.h"
#include "cli/text.h"
#include "codegen/outlier_filter.h"
#include "codegen/point_source.h"
#include "codegen/prepare_error.h"
#include "codegen/streamed_prepare.h"

namespace octopoint::prepare {

Scan cropScan(const Scan& scan, const CropBox& box, const std::string& scan_path) {
  std::vector<std::uint8_t> inside(scan.positions.size());
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    const auto& p = scan.positions[i];
    bool in = true;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      in = in && p[axis] >= static_cast<float>(box.low[axis]) &&
           p[axis] <= static_cast<float>(box.high[axis]);
    }
    inside[i] = in;
  }
  Scan cropped = keepPoints(scan, inside);
  if (cropped.positions.empty()) {
    throw PrepareError(scan_path + ": no point of the " + std::to_string(scan.positions.size()) +
                       " points lies inside the crop box");
  }
  return cropped;
}

CropBox parseCropBox(const std::string& flag, const std::string& text) {
  std::array<double, 6> v{};
  std::size_t at = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::size_t comma = i + 1 < v.size() ? text.find(',', at) : text.size();
    if (comma == std::string::npos || (i + 1 == v.size() && text.find(',', at) != std::string::npos)) {
      throw PrepareError(flag + ": " + cli::inQuotes(text) + " is not six comma-separated numbers X0,Y0,Z0,X1,Y1,Z1");
    }
    v[i] = cli::parseReal(flag, std::string_view(text).substr(at, comma - at), -kMaxCropCoordinate,
                          kMaxCropCoordinate);
    at = comma + 1;
  }
  const CropBox box{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (!(box.low[axis] < box.high[axis])) {
      throw PrepareError(flag + ": " + cli::inQuotes(text) + " is empty: each lower bound must be below its upper bound");
    }
  }
  return box;
}

Scan modelPoints(const Scan& full_scan, const std::string& scan_path, const PrepareOptions& options) {
  if (full_scan.positions.empty()) throw PrepareError(scan_path + ": the scan has no usable points");
  Scan scan = options.crop ? cropScan(full_scan, *options.crop, scan_path) : full_scan;
  if (options.outliers) scan = removeOutliers(scan, *options.outliers, scan_path);
  if (options.axes == ScanAxes::kYUp) {
    for (auto& p : scan.positions) p = {p[0], -p[1], -p[2]};  // a rotation: no mirror image
  }
  return scan;
}

PreparedModel prepareModel(const Scan& full_scan, const std::string& scan_path,
                           const PrepareOptions& options, unsigned threads) {
  const Scan scan = modelPoints(full_scan, scan_path, options);
  PrepareOptions streamed = options;  // the points are cropped, cleaned and turned already
  streamed.crop.reset();
  streamed.outliers.reset();
  streamed.axes = ScanAxes::kYDown;
  StreamOptions stream;
  stream.threads = threads;
  stream.memory_bytes = std::max<std::uint64_t>(kDefaultMemoryBytes, 64 * scan.positions.size());
  return prepareFromSource(*memorySource(scan), scan_path, streamed, stream);
}

}  // namespace octopoint::prepare
