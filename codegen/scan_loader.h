#pragma once
// Loading a range scan (.pcd or .ply) into plain arrays: the first step of the preparer.
//
// The header deliberately includes no PCL header: PCL compiles slowly and its flags must not leak
// into the code that uses the loader. PCL is an implementation detail of scan_loader.cpp.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "cli/input_file.h"

namespace octopoint::prepare {

// What the per-point colours come from.
enum class ScanShading { kColour, kIntensity, kNone };

struct Scan {
  std::vector<std::array<float, 3>> positions;  // finite points only, in the scan's own units
  std::vector<std::array<uint8_t, 3>> colours;  // RGB per position; empty when shading == kNone
  // Unit surface normals per position, oriented toward the sensor, NaN where none could be
  // estimated; empty unless estimated (codegen/normal_estimation.h).
  std::vector<std::array<float, 3>> normals;
  ScanShading shading = ScanShading::kNone;
  std::size_t points_in_file = 0;  // including the dropped ones
  std::size_t dropped_non_finite = 0;
  bool organized = false;  // height > 1 in the file
  // An organized scan's sensor grid (grid_width x grid_height points, row-major) and, per kept
  // position, its index in that grid: what integral-image normal estimation walks. Empty and 0
  // for an unorganized scan.
  std::uint32_t grid_width = 0;
  std::uint32_t grid_height = 0;
  std::vector<std::uint32_t> grid_index;
  std::array<float, 3> sensor_origin{};  // where the sensor stood (PCD VIEWPOINT), in scan units
};

// The points of `scan` with keep[i] != 0, in order, with their colours, normals and grid indices;
// the file's counts, the grid's size and the sensor origin are kept. `keep` has one entry per
// position.
Scan keepPoints(const Scan& scan, const std::vector<std::uint8_t>& keep);

// A finite coordinate with a larger magnitude is refused as absurd: no range scanner measures a
// million units in any unit, and such values would wreck the later fit into the cube.
inline constexpr float kMaxAbsCoordinate = 1.0e6f;

// The scan files loadScan reads: regular files of at most 1 GiB (cli/input_file.h). PCL holds a
// whole scan in memory several times over while reading it, so the limit keeps a sparse or
// padded file from costing gigabytes before it fails.
inline constexpr cli::InputKind kScanInput{"scan", cli::kGiB};

// Loads a .pcd or .ply scan (chosen by extension, case-insensitive).
// Accepts float32 x/y/z plus optionally a colour field (packed float "rgb", or uint32 "rgb"/"rgba";
// R is bits 16..23, G 8..15, B 0..7) or else a float32 "intensity" field. PLY
// red/green/blue(/alpha) properties arrive through PCL as such a colour field. Drops points with
// any non-finite coordinate (NaN or infinity) and counts them. Intensity becomes grey: the
// 1st..99th percentile of intensity over the kept points maps linearly to 0..255, clamped, so that
// a few hot returns do not turn everything else black. Throws PrepareError with one line "PATH:
// what (where)" for every failure: a path that is not a regular file of at most
// kScanInput.max_bytes (cli::Error, from cli::checkInputFile), unknown extension, garbage or
// truncated file, a header declaring more data than the file holds (checked before anything is
// allocated), missing or wrongly typed x/y/z, no points, no finite points, or a finite |coordinate|
// > kMaxAbsCoordinate (naming point index and value). Identical points are not an error here (the
// fitting step deals with them).
Scan loadScan(const std::filesystem::path& path);

}  // namespace octopoint::prepare
