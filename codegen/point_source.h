#pragma once
// Where the streamed preparer's points come from: a file read in chunks of records, any chunk at
// any time from any thread, so that several threads decode one file at once and no pass ever holds
// the whole scan. LAS files (codegen/las_reader.h) and binary PCD/PLY files of a plain layout
// (codegen/binary_scan_source.cpp) are read this way; everything else is loaded whole through PCL
// (codegen/scan_loader.h) and then served from memory by the same interface.
//
// No PCL in this header or in the streamed sources.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/input_file.h"
#include "codegen/scan_loader.h"

namespace octopoint::prepare {

// What a source's points carry besides their position.
enum class PointPayload {
  kRgb,        // a colour per point (8-bit, or 16-bit for LAS: see colour_bits_detected)
  kIntensity,  // an intensity per point, shown as grey (codegen/intensity_grey.h)
  kNone,       // nothing: the voxels get a depth shade
};

// The box a file's header says its points fill (LAS: min and max x, y, z), in scan units.
struct HeaderBox {
  std::array<double, 3> low{};
  std::array<double, 3> high{};
};

struct SourceInfo {
  std::uint64_t points = 0;             // records served, the non-finite ones included
  std::uint64_t dropped_by_loader = 0;  // non-finite points a loader dropped before serving them
  PointPayload payload = PointPayload::kNone;
  // What the colours mean, for the summary: a loaded scan's intensity arrives as grey kRgb.
  ScanShading shading = ScanShading::kNone;
  // LAS stores 16-bit colour channels, yet many writers put 8-bit values in them: the preparer
  // decides from the whole file (all channels <= 255: 8-bit) and falls back to the intensity when
  // every channel of every point is 0.
  bool colour_bits_detected = false;
  bool has_intensity = false;  // besides the colour (LAS): the fallback for all-zero colours
  // A finite |coordinate| above this is refused as absurd (codegen/scan_loader.h); LAS coordinates
  // are bounded by their header's scale and offset instead, so it is infinite there.
  double coordinate_limit = std::numeric_limits<double>::infinity();
  bool float_coordinates = true;  // PCD, PLY and scans in memory; LAS coordinates are doubles
  bool organized = false;         // height > 1 (PCD/PLY)
  bool streamed = true;           // false when the whole scan was loaded through PCL first
  // LAZ: a chunk decodes only by running its arithmetic code again, so the preparer keeps pass 1's
  // decoded points for pass 2 (codegen/decoded_points.h) rather than decode every chunk twice.
  bool compressed = false;
  // LAS and LAZ: the header's box, snapped to the records' coordinate grid (nullopt when it is no
  // box). The preparer bins in its first pass on the cube this box gives and checks it against
  // the points' own bounds at the end (codegen/streamed_prepare.h); it is never taken on trust.
  std::optional<HeaderBox> header_box;
  bool intensity_16bit = false;  // every intensity an integer 0..65535 (LAS): counted exactly
  std::string format;            // for the summary line, e.g. "LAS 1.4, point format 7"
};

// One chunk of consecutive records, decoded. Positions are in scan units; a non-finite one marks a
// point to drop (PCD/PLY store NaN for "no return"). rgb is filled for kRgb sources, intensity for
// kIntensity ones and for has_intensity.
struct PointChunk {
  std::vector<std::array<double, 3>> xyz;
  std::vector<std::array<std::uint16_t, 3>> rgb;
  std::vector<float> intensity;
  std::vector<std::uint8_t> raw;  // the records as read, for the sources that decode them

  void resize(std::size_t count, const SourceInfo& info) {
    xyz.resize(count);
    rgb.resize(info.payload == PointPayload::kRgb ? count : 0);
    intensity.resize(info.payload == PointPayload::kIntensity || info.has_intensity ? count : 0);
  }
};

// A run of consecutive records.
struct PointRange {
  std::uint64_t first = 0;
  std::size_t count = 0;
};

// Records a pass reads at once, unless the source has pieces of its own.
inline constexpr std::size_t kPiecePoints = 1 << 16;

class PointSource {
 public:
  virtual ~PointSource() = default;
  virtual const SourceInfo& info() const = 0;
  // Decodes records [first, first + count) into `chunk` (resized to count). Safe to call from
  // several threads at once. Throws PrepareError on a read error.
  virtual void read(std::uint64_t first, std::size_t count, PointChunk& chunk) const = 0;
  // The pieces a pass reads, in order, each record in one: runs of kPiecePoints, or a compressed
  // file's chunks (LAZ), which decode only from their start and so are read whole, each by one
  // thread.
  virtual std::size_t pieceCount() const {
    return static_cast<std::size_t>((info().points + kPiecePoints - 1) / kPiecePoints);
  }
  virtual PointRange piece(std::size_t index) const {
    const std::uint64_t first = std::uint64_t{index} * kPiecePoints;
    const std::uint64_t left = info().points - first;
    return {first, static_cast<std::size_t>(left < kPiecePoints ? left : kPiecePoints)};
  }
  // Whether piece `index` may hold a point inside the box [low, high] (the scan's own
  // coordinates): true unless the source knows where its pieces lie (COPC's octree nodes), so that
  // a crop reads only the pieces that meet it.
  virtual bool pieceMayMeet(std::size_t /*index*/, const std::array<double, 3>& /*low*/,
                            const std::array<double, 3>& /*high*/) const {
    return true;
  }
  // The bytes read from the file so far (0 when the source does not count them): what a crop
  // saves.
  virtual std::uint64_t bytesRead() const { return 0; }
};

// Serves an in-memory scan (already cropped or not; its colours are final 8-bit colours, the
// intensity already turned grey by loadScan). The scan must outlive the source.
std::unique_ptr<PointSource> memorySource(const Scan& scan);

// The scan files streamed (LAS, binary PCD/PLY): regular files of at most 4 TiB. Streaming costs
// the same memory whatever the size; a file that is mostly hole fails on its content.
inline constexpr cli::InputKind kStreamedScanInput{"scan", 4096 * cli::kGiB};

// Opens a scan file by its extension (.las, .laz, .pcd, .ply): LAS and binary
// PCD/PLY of a plain layout are streamed, anything else is loaded whole with loadScan, which then
// stays in memory. Throws PrepareError with one line for every failure.
std::unique_ptr<PointSource> openPointSource(const std::filesystem::path& path);

// openPointSource's checks and streamed readers alone: nullptr for a file that loadScan must read
// (defined apart from openPointSource, which links PCL; codegen/whole_scan.h).
std::unique_ptr<PointSource> openStreamedSource(const std::filesystem::path& path);

// A scan PCL loaded from `path`, served from memory and owned by the source.
std::unique_ptr<PointSource> loadedScanSource(Scan scan, const std::filesystem::path& path);

}  // namespace octopoint::prepare
