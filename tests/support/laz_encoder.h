#pragma once
// A LAZ encoder for tests and scale runs (tests/support/las_writer.h writes the file around it):
// LAS point formats 0 to 3 and 6 to 8 with extra bytes, as LASzip writes them today: the
// point-wise items version 2 (POINT10, GPSTIME11, RGB12, BYTE) for formats 0 to 3, the layered
// items version 3 (POINT14, RGB14, RGBNIR14, BYTE14; LASzip's compressor 3) for 6 to 8, chunked,
// with a chunk table. It is the exact inverse of the decoders in codegen/laz_pointwise.cpp and
// codegen/laz_layered.cpp, built on the same arithmetic coder (codegen/laz_arithmetic.h); an
// independent decoder (laz-perf) checks both in the tests.

#include <cstdint>
#include <memory>
#include <vector>

namespace octopoint::testing {

class LazChunkEncoder {
 public:
  // Records of point format `format` (0 to 3, 6 to 8) followed by `extra_bytes` bytes.
  LazChunkEncoder(int format, int extra_bytes);
  ~LazChunkEncoder();
  LazChunkEncoder(const LazChunkEncoder&) = delete;
  LazChunkEncoder& operator=(const LazChunkEncoder&) = delete;

  // Adds a record to the chunk being written (the first is stored raw).
  void add(const std::uint8_t* record);
  std::uint64_t points() const;
  // The chunk's bytes; the next add() starts a new chunk.
  std::vector<std::uint8_t> finishChunk();

  // LASzip's VLR payload for these records (compressor 2 or 3, chunks of `chunk_size` points, or
  // variable ones for 0xffffffff).
  std::vector<std::uint8_t> vlrPayload(std::uint32_t chunk_size) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The chunk table: version, count and each chunk's (points and) bytes, arithmetic-coded.
std::vector<std::uint8_t> lazChunkTable(const std::vector<std::uint64_t>& chunk_points,
                                        const std::vector<std::uint64_t>& chunk_bytes,
                                        bool variable);

}  // namespace octopoint::testing
