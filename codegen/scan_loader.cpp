// Loads a .pcd/.ply range scan with PCL, after validating its header ourselves.
//
// Why we validate before PCL: experiments with PCL 1.13 under AddressSanitizer (every truncation
// of small PCD/PLY files, huge and negative counts, garbage) showed that its readers
//   - dereference a null pointer in PCDReader::read when the PCD header has no FIELDS line (empty
//     file, garbage, a header cut short);
//   - allocate points * point_size bytes straight from the header (POINTS 4000000000 asks for 64
//   GB,
//     a huge COUNT likewise, a PLY "element vertex -5" for 64 GB) before looking at the file
//     length;
//   - allocate the uncompressed size stored in a binary_compressed body (up to 4 GB) unchecked;
//   - return success with an empty or garbled cloud for some truncated input (PCD cut after
//     FIELDS, an ascii PCD whose last line is cut short, PLY cut inside its header, PLY "element
//     vertex 0", a binary PLY missing its trailing faces);
//   - spin for seconds over "element face 4000000000" when the element has no properties.
// So every size the header declares is checked against the real file length first, and only a
// file that can hold what it declares is handed to PCL.

#include "codegen/scan_loader.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>

#include "cli/input_file.h"
#include "cli/text.h"
#include "codegen/intensity_grey.h"
#include "codegen/prepare_error.h"
#include "codegen/scan_header_check.h"
#include "codegen/scan_layout_check.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

// PCL reports through PCL_ERROR/PCL_WARN on stderr; the user should see only our one line.
void silencePcl() {
  static std::once_flag once;
  std::call_once(once, [] { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); });
}

const pcl::PCLPointField* findField(const pcl::PCLPointCloud2& cloud, std::string_view name) {
  for (const pcl::PCLPointField& field : cloud.fields) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

std::string fieldList(const pcl::PCLPointCloud2& cloud) {
  std::string names;
  for (const pcl::PCLPointField& field : cloud.fields)
    names += (names.empty() ? "" : " ") + field.name;
  return printable(names);
}

// A field is usable as a scalar of `datatype` if it is one value of that type inside the point.
bool isScalarOf(const pcl::PCLPointField& field, std::uint8_t datatype) {
  return field.datatype == datatype && field.count == 1;
}

// PCL hands back what it parsed; check its layout before fromPCLPointCloud2 indexes into it.
void checkCloudLayout(const fs::path& path, const pcl::PCLPointCloud2& cloud,
                      std::uint64_t declared_points) {
  const std::uint64_t points = std::uint64_t{cloud.width} * cloud.height;
  if (points != declared_points || cloud.data.size() != saturatingMul(points, cloud.point_step)) {
    fail(path,
         "PCL read " + std::to_string(points) + " points (" + std::to_string(cloud.data.size()) +
             " bytes) where the header declares " + std::to_string(declared_points),
         "after reading");
  }
  for (const pcl::PCLPointField& field : cloud.fields) {
    const std::uint64_t end =
        field.offset + static_cast<std::uint64_t>(pcl::getFieldSize(field.datatype)) * field.count;
    if (end > cloud.point_step) {
      fail(path, "field '" + printable(field.name) + "' lies outside the point", "after reading");
    }
  }
}

// Which colour source the cloud offers; fails on a colour field we cannot read.
ScanShading pickShading(const fs::path& path, const pcl::PCLPointCloud2& cloud) {
  using Field = pcl::PCLPointField;
  if (const Field* rgb = findField(cloud, "rgb")) {
    if (!isScalarOf(*rgb, Field::FLOAT32) && !isScalarOf(*rgb, Field::UINT32)) {
      fail(path, "field 'rgb' is not one float32 or uint32", "field list: " + fieldList(cloud));
    }
    return ScanShading::kColour;
  }
  if (const Field* rgba = findField(cloud, "rgba")) {
    if (!isScalarOf(*rgba, Field::UINT32)) {
      fail(path, "field 'rgba' is not one uint32", "field list: " + fieldList(cloud));
    }
    return ScanShading::kColour;
  }
  if (const Field* intensity = findField(cloud, "intensity")) {
    if (!isScalarOf(*intensity, Field::FLOAT32)) {
      fail(path, "field 'intensity' is not one float32", "field list: " + fieldList(cloud));
    }
    return ScanShading::kIntensity;
  }
  return ScanShading::kNone;
}

std::array<std::uint8_t, 3> unpackRgb(std::uint32_t rgba) {
  return {static_cast<std::uint8_t>(rgba >> 16), static_cast<std::uint8_t>(rgba >> 8),
          static_cast<std::uint8_t>(rgba)};
}

// Nearest-rank quantile of `values` (which it reorders), q in [0, 1].
float percentile(std::vector<float>& values, double q) {
  const auto rank = static_cast<std::size_t>(quantileRank(values.size(), q));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

// Intensity to grey (codegen/intensity_grey.h), with the percentiles found by sorting.
std::vector<std::array<std::uint8_t, 3>> intensityToGrey(const std::vector<float>& intensities) {
  std::vector<float> finite;
  finite.reserve(intensities.size());
  for (float v : intensities) {
    if (std::isfinite(v)) finite.push_back(v);
  }
  IntensityRange range;
  if (!finite.empty()) {
    range.low = percentile(finite, kLowIntensityQuantile);
    range.high = percentile(finite, kHighIntensityQuantile);
  }
  std::vector<std::array<std::uint8_t, 3>> greys;
  greys.reserve(intensities.size());
  for (float v : intensities) {
    const std::uint8_t level = intensityGrey(v, range);
    greys.push_back({level, level, level});
  }
  return greys;
}

// Keeps finite points in file order, refuses absurd ones; `keep_extra(point)` records the
// colour or intensity of each kept point.
template <typename PointT, typename KeepExtra>
void collectPoints(const fs::path& path, const pcl::PointCloud<PointT>& points, Scan& scan,
                   KeepExtra keep_extra) {
  scan.positions.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PointT& p = points[i];
    const std::array<float, 3> xyz = {p.x, p.y, p.z};
    if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
      ++scan.dropped_non_finite;
      continue;
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (std::fabs(xyz[axis]) > kMaxAbsCoordinate) {
        std::ostringstream what;
        what << "absurd coordinate "
             << "xyz"[axis] << " = " << cli::realText(xyz[axis]) << ", beyond +-"
             << cli::realText(kMaxAbsCoordinate);
        fail(path, what.str(), "point " + std::to_string(i));
      }
    }
    scan.positions.push_back(xyz);
    if (scan.organized) scan.grid_index.push_back(static_cast<std::uint32_t>(i));
    keep_extra(p);
  }
}

// Whether the scan is a .ply file (else .pcd), from its extension in any case.
bool isPlyScan(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool is_ply = extension == ".ply";
  if (!is_ply && extension != ".pcd") {
    fail(path, "unknown extension '" + printable(extension) + "', expected .pcd or .ply",
         "file name");
  }
  return is_ply;
}

// The file read by PCL, after its header was checked, and checked to hold float32 x, y and z.
pcl::PCLPointCloud2 readCloud(const fs::path& path, bool is_ply, std::uint64_t declared_points,
                              Eigen::Vector4f& origin) {
  silencePcl();
  pcl::PCLPointCloud2 cloud;
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  int result = -1;
  try {
    if (is_ply) {
      result = pcl::io::loadPLYFile(path.string(), cloud);
    } else {
      result = pcl::io::loadPCDFile(path.string(), cloud, origin, orientation);
    }
  } catch (const std::exception& e) {  // bad_alloc, or PCL's own exceptions
    fail(path, std::string("PCL's reader threw: ") + printable(e.what()), "reading the data");
  }
  if (result < 0) {
    fail(path,
         std::string("corrupt or truncated data: PCL's ") + (is_ply ? "PLY" : "PCD") +
             " reader rejected it",
         "reading the data");
  }
  checkCloudLayout(path, cloud, declared_points);

  using Field = pcl::PCLPointField;
  for (const char* axis : {"x", "y", "z"}) {
    const Field* field = findField(cloud, axis);
    if (field == nullptr || !isScalarOf(*field, Field::FLOAT32)) {
      failWithoutFloatAxis(path, axis, fieldList(cloud));
    }
  }
  return cloud;
}

// The cloud's finite points with the colour its shading takes (none, RGB or intensity as grey).
void collectShadedPoints(const fs::path& path, const pcl::PCLPointCloud2& cloud, Scan& scan) {
  if (scan.shading == ScanShading::kColour) {
    pcl::PointCloud<pcl::PointXYZRGBA> points;
    pcl::fromPCLPointCloud2(cloud, points);
    scan.colours.reserve(points.size());
    collectPoints(path, points, scan,
                  [&](const pcl::PointXYZRGBA& p) { scan.colours.push_back(unpackRgb(p.rgba)); });
  } else if (scan.shading == ScanShading::kIntensity) {
    pcl::PointCloud<pcl::PointXYZI> points;
    pcl::fromPCLPointCloud2(cloud, points);
    std::vector<float> intensities;
    intensities.reserve(points.size());
    collectPoints(path, points, scan,
                  [&](const pcl::PointXYZI& p) { intensities.push_back(p.intensity); });
    scan.colours = intensityToGrey(intensities);
  } else {
    pcl::PointCloud<pcl::PointXYZ> points;
    pcl::fromPCLPointCloud2(cloud, points);
    collectPoints(path, points, scan, [](const pcl::PointXYZ&) {});
  }
}

}  // namespace

Scan loadScan(const fs::path& path) {
  std::uint64_t file_size = 0;
  try {
    file_size = cli::checkInputFile(path, kScanInput);
  } catch (const cli::Error& error) {  // "PATH: what", in the loader's "PATH: what (where)" form
    throw PrepareError(std::string(error.what()) + " (opening the scan)");
  }
  const bool is_ply = isPlyScan(path);
  if (file_size == 0) fail(path, "empty file (0 bytes)", "opening the scan");
  const std::uint64_t declared_points =
      is_ply ? checkPlyHeader(path, file_size) : checkPcdHeader(path, file_size);
  Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  const pcl::PCLPointCloud2 cloud = readCloud(path, is_ply, declared_points, origin);

  Scan scan;
  scan.points_in_file = declared_points;
  scan.organized = cloud.height > 1;
  if (scan.organized) {
    scan.grid_width = cloud.width;
    scan.grid_height = cloud.height;
  }
  for (int axis = 0; axis < 3; ++axis) {
    scan.sensor_origin[static_cast<std::size_t>(axis)] =
        std::isfinite(origin[axis]) ? origin[axis] : 0.0f;
  }
  scan.shading = pickShading(path, cloud);
  collectShadedPoints(path, cloud, scan);
  if (scan.positions.empty()) {
    fail(path,
         "no finite points: all " + std::to_string(scan.points_in_file) +
             " points have a NaN or infinite coordinate",
         "every point");
  }
  return scan;
}

Scan keepPoints(const Scan& scan, const std::vector<std::uint8_t>& keep) {
  Scan kept;
  kept.shading = scan.shading;
  kept.points_in_file = scan.points_in_file;
  kept.dropped_non_finite = scan.dropped_non_finite;
  kept.organized = scan.organized;
  kept.grid_width = scan.grid_width;
  kept.grid_height = scan.grid_height;
  kept.sensor_origin = scan.sensor_origin;
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    if (!keep[i]) continue;
    kept.positions.push_back(scan.positions[i]);
    if (!scan.colours.empty()) kept.colours.push_back(scan.colours[i]);
    if (!scan.normals.empty()) kept.normals.push_back(scan.normals[i]);
    if (!scan.grid_index.empty()) kept.grid_index.push_back(scan.grid_index[i]);
  }
  return kept;
}

}  // namespace octopoint::prepare
