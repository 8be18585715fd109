#pragma once
// Writing LAS files for tests and scale runs (tests/support/make_large_scan.cpp): any version 1.0
// to 1.4, any point format 0 to 10, with VLRs, EVLRs, extra bytes per record and 8- or 16-bit
// colour, streamed point by point, as LAS or LAZ. The header's counts and bounds are patched in by
// finish().

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "tests/support/landscape.h"
#include "tests/support/laz_encoder.h"

namespace octopoint::testing {

struct LasLayout {
  int format = 2;
  int version_minor = -1;  // -1: the first version with the format (1.2; 1.3 for 4-5; 1.4 for 6-10)
  int extra_bytes = 0;     // user bytes after each record's fields
  int vlrs = 1;            // VLRs between the header and the points
  int evlrs = 0;           // EVLRs after the points (1.4 only)
  bool colour_16bit =
      true;  // channels scaled to 16 bits (v * 257), else the 8-bit values as they are
  std::array<double, 3> scale{0.001, 0.001, 0.001};
  std::array<double, 3> offset{500000, 4100000,
                               0};  // a UTM-like origin, far beyond float precision
  // LAZ (formats 0 to 3, 6 to 8): the records compressed as LASzip does
  // (tests/support/laz_encoder.h), in chunks of laz_chunk_points, or of varying sizes listed in the
  // chunk table.
  bool laz = false;
  // Every field varied (returns, classes, scan angles, user data, sources, GPS times in two
  // interleaved flight lines with jumps), so that a LAZ coder meets each of its cases; else the
  // fields a landscape has (position, intensity, colour) and constant others.
  bool varied_fields = false;
  std::uint32_t laz_chunk_points = 50000;
  bool laz_variable_chunks = false;
  // The records in the order of a COPC octree (tests/support/copc_octree.h) of nodes of at most
  // laz_chunk_points points; with laz, a COPC file: LAS 1.4 of formats 6 to 8, the COPC info VLR
  // first, each node one chunk, the hierarchy pages in an EVLR after the chunk table. The records
  // are held in memory until finish().
  bool copc = false;

  int minor() const {
    return version_minor >= 0 ? version_minor : format <= 3 ? 2 : format <= 5 ? 3 : 4;
  }
};

// Byte offsets in the public header block (LAS 1.4 R15).
namespace las_offsets {
inline constexpr std::size_t kHeaderSize = 94, kPointOffset = 96, kVlrCount = 100, kFormat = 104,
                             kRecordLength = 105, kLegacyCount = 107, kScale = 131, kOffset = 155,
                             kEvlrStart = 235, kEvlrCount = 243, kCount = 247;
}

class LasWriter {
 public:
  LasWriter(const std::filesystem::path& path, const LasLayout& layout);
  void add(const LandscapePoint&
               point);  // the landscape's metres, stored relative to the layout's origin
  // The landscape's points 0 to count - 1.
  void addLandscape(const Landscape& landscape, std::uint64_t count) {
    for (std::uint64_t i = 0; i < count; ++i) add(landscape.point(i));
  }
  void finish();  // EVLRs, then the header's counts and bounds

  static std::uint16_t recordLength(const LasLayout& layout);
  std::uint64_t pointOffset() const { return point_offset_; }
  // LAZ: each chunk's points and bytes, as the chunk table lists them.
  const std::vector<std::uint64_t>& lazChunkPoints() const { return chunk_points_; }
  const std::vector<std::uint64_t>& lazChunkBytes() const { return chunk_bytes_; }

 private:
  void flush();
  void varyFields(std::uint8_t* record) const;
  std::uint64_t nextChunkPoints() const;
  void finishLazChunk();
  void finishLaz();
  void finishCopc();
  std::uint32_t evlrCount() const;

  LasLayout layout_;
  std::unique_ptr<LazChunkEncoder> laz_;
  std::vector<std::uint64_t> chunk_points_, chunk_bytes_;
  std::uint64_t evlr_start_ = 0;
  std::ofstream out_;
  std::uint64_t point_offset_ = 0;
  std::uint64_t count_ = 0;
  std::array<double, 3> low_{}, high_{};
  std::vector<std::uint8_t> buffer_;
  std::vector<std::uint8_t> copc_records_;  // every record, until finish() orders them
  std::uint64_t copc_info_at_ = 0;          // the COPC info VLR's payload, patched in finish()
  std::vector<std::uint8_t> copc_pages_;    // the hierarchy pages, the first EVLR's payload
};

// The landscape's points 0 to count - 1 written to `path` as `layout` says; returns `path`.
inline std::filesystem::path writeLandscapeScan(const std::filesystem::path& path,
                                                const LasLayout& layout, const Landscape& landscape,
                                                std::uint64_t count) {
  LasWriter writer(path, layout);
  writer.addLandscape(landscape, count);
  writer.finish();
  return path;
}

}  // namespace octopoint::testing
