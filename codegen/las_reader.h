#pragma once
// LAS 1.0 to 1.4 (ASPRS), read by hand: Debian ships no LAS library. Point formats 0 to 10, the
// coordinates as int32 * scale + offset in double, intensity, RGB where the format has it, the
// 64-bit point count of 1.4, VLRs and EVLRs (walked and checked, their contents skipped), records
// longer than their format (user "extra bytes", skipped). LAZ, the same file with its points
// compressed by LASzip, is read by codegen/laz_reader.h from the header read here.
//
// Every count, offset and length in the header is checked against the file size before anything is
// read or allocated, so a header that lies costs nothing: readLasHeader throws one PrepareError
// line "PATH: what (where)".

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "codegen/file_io.h"
#include "codegen/point_source.h"
#include "codegen/record_fields.h"

namespace octopoint::prepare {

// The bytes of one point record that each format defines (LAS 1.4 R15, "Point Data Records").
inline constexpr std::array<std::uint16_t, 11> kLasFormatBytes = {20, 28, 26, 34, 57, 63,
                                                                  30, 36, 38, 59, 67};

// Sane bounds for scale and offset: with them every int32 coordinate maps to a finite double of at
// most ~3e12 units, far beyond any survey, so no point can overflow the cube fit. A scale of 0, a
// negative one, 1e300 or NaN is refused.
inline constexpr double kMinLasScale = 1e-9;
inline constexpr double kMaxLasScale = 1e3;
inline constexpr double kMaxLasOffset = 1e12;

struct LasHeader {
  int version_minor = 0;  // major is always 1
  int point_format = 0;
  std::uint16_t record_length = 0;
  std::uint64_t point_count = 0;
  std::uint64_t point_offset = 0;  // the first point record
  std::array<double, 3> scale{};
  std::array<double, 3> offset{};
  // The header's "max and min X, Y, Z": the extent of the points' coordinates, as written (the
  // LAS specification says actual; a writer may leave them 0 or loose).
  std::array<double, 3> stated_low{};
  std::array<double, 3> stated_high{};
  std::uint32_t vlr_count = 0;
  std::uint32_t evlr_count = 0;
  std::uint16_t rgb_offset = 0;  // byte of red in the record; 0 when the format has no colour
  // LAZ: the point format byte has LASzip's compression bits and LASzip's VLR describes the items.
  bool compressed = false;
  std::uint64_t laszip_vlr_offset = 0;  // the VLR's payload
  std::uint16_t laszip_vlr_bytes = 0;
  // COPC (a LAZ 1.4 file ordered as an octree): its info VLR ("copc", record 1), 0 if none.
  std::uint64_t copc_vlr_offset = 0;  // the VLR's payload
  std::uint16_t copc_vlr_bytes = 0;
  std::uint64_t points_end = 0;  // where the point data ends: the EVLRs' start, else the file's end
};

// Reads and checks the header, every VLR and every EVLR of `file`. For LAZ the compressed point
// data is checked by its reader, not here.
LasHeader readLasHeader(const InputFile& file);

// What a LAS (or LAZ) file's points carry: payload kRgb with colour_bits_detected (and the
// intensity beside it) for formats with colour, else kIntensity.
SourceInfo lasSourceInfo(const LasHeader& header);

// A record's coordinate: its int32 times the scale plus the offset, in double. The one expression
// for points and for the header's box (lasSourceInfo), so that a box snapped to the records' grid
// is exactly the coordinates its corners' points decode to.
inline double lasCoordinate(std::int32_t raw, double scale, double offset) {
  return static_cast<double>(raw) * scale + offset;
}

// Decodes `chunk.xyz.size()` LAS records from `records` into `chunk` (already resized).
void decodeLasRecords(const LasHeader& header, const std::uint8_t* records, PointChunk& chunk);

// A LAS or LAZ file as a point source (lasSourceInfo). LAZ of point formats 6 to 10 decodes only
// `fields` of each record (openLazSource): by default what PointChunk carries, which is all the
// preparer reads; RecordFields::all() for the records exactly as the file holds them.
std::unique_ptr<PointSource> openLasSource(const std::filesystem::path& path,
                                           RecordFields fields = RecordFields::pointChunk());

}  // namespace octopoint::prepare
