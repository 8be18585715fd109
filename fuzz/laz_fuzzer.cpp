// libFuzzer harness for the LAZ reader (codegen/laz_reader.h): each input is written to an
// in-memory file and opened as LAS/LAZ. LASzip's VLR, the chunk table and every chunk's arithmetic
// code are untrusted: a lie or a corruption must end in one PrepareError line, never a crash, a
// sanitizer report, a hang or an allocation past the fuzzer's -malloc_limit_mb. What the reader
// accepts is decoded whole, chunk by chunk, as the preparer's passes read it (the preparing itself
// is las_fuzzer's); at most 2^20 points, so that a tiny input declaring a billion cheap points
// does not spend the run's time.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "codegen/las_reader.h"
#include "codegen/prepare_error.h"
#include "tests/support/memory_file.h"

namespace {

using namespace octopoint::prepare;

constexpr std::uint64_t kMaxDecodedPoints = 1 << 20;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static octopoint::fuzzing::MemoryFile file;
  const auto& path = file.write(data, size);
  try {
    const auto source = openLasSource(path);
    if (source->info().points > kMaxDecodedPoints) return 0;
    PointChunk chunk;
    std::uint64_t next = 0;
    for (std::size_t i = 0; i < source->pieceCount(); ++i) {
      const PointRange piece = source->piece(i);
      if (piece.first != next || piece.count == 0) std::abort();  // pieces cover the points once
      next += piece.count;
      source->read(piece.first, piece.count, chunk);
      if (chunk.xyz.size() != piece.count) std::abort();
    }
    if (next != source->info().points) std::abort();
  } catch (const PrepareError& error) {
    if (std::string(error.what()).find('\n') != std::string::npos) std::abort();
  }
  return 0;
}
