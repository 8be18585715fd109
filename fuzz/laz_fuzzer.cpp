// libFuzzer harness for the LAZ reader (codegen/laz_reader.h): each input is written to an
// in-memory file and opened as LAS/LAZ. LASzip's VLR, the chunk table and every chunk's arithmetic
// code are untrusted: a lie or a corruption must end in one PrepareError line, never a crash, a
// sanitizer report, a hang or an allocation past the fuzzer's -malloc_limit_mb. What the reader
// accepts is decoded chunk by chunk, as the preparer's passes read it (the preparing itself is
// las_fuzzer's), twice: every field, then only the preparer's (codegen/record_fields.h), whose
// decoded points must be the full decoding's (a left-out layer is never read, so a corrupt one may
// pass unseen, but no field asked for may change). At most 2^20 points, so that a tiny input
// declaring a billion cheap points does not spend the run's time.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "codegen/las_reader.h"
#include "codegen/prepare_error.h"
#include "tests/support/memory_file.h"

namespace {

using namespace octopoint::prepare;

constexpr std::uint64_t kMaxDecodedPoints = 1 << 20;

// Bit for bit (a NaN equals itself here).
template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static octopoint::fuzzing::MemoryFile file;
  const auto& path = file.write(data, size);
  try {
    const auto source = openLasSource(path, RecordFields::all());
    if (source->info().points > kMaxDecodedPoints) return 0;
    // the same file opened again: its header and chunk table were accepted just now
    const auto selective = openLasSource(path, RecordFields::pointChunk());
    PointChunk chunk, selective_chunk;
    std::uint64_t next = 0;
    for (std::size_t i = 0; i < source->pieceCount(); ++i) {
      const PointRange piece = source->piece(i);
      if (piece.first != next || piece.count == 0) std::abort();  // pieces cover the points once
      next += piece.count;
      source->read(piece.first, piece.count, chunk);
      if (chunk.xyz.size() != piece.count) std::abort();
      // Leaving layers out checks less, never more: what decodes whole decodes selectively, to
      // the same points.
      try {
        selective->read(piece.first, piece.count, selective_chunk);
      } catch (const PrepareError&) {
        std::abort();
      }
      if (!sameBits(selective_chunk.xyz, chunk.xyz) || !sameBits(selective_chunk.rgb, chunk.rgb) ||
          !sameBits(selective_chunk.intensity, chunk.intensity)) {
        std::abort();
      }
    }
    if (next != source->info().points) std::abort();
  } catch (const PrepareError& error) {
    if (std::string(error.what()).find('\n') != std::string::npos) std::abort();
  }
  return 0;
}
