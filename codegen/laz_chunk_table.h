#pragma once
// LAZ's chunk table: where each chunk of compressed points starts, how many bytes and points it
// holds (variable chunks) or how many its fixed size gives, each checked against the file and the
// header's point count before a chunk is read. And the bytes of a chunk, handed to a decoder a
// window at a time.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "cli/input_file.h"
#include "codegen/las_reader.h"
#include "codegen/laz_arithmetic.h"

namespace octopoint::prepare {

// LASzip's chunk size for chunks whose sizes the chunk table lists.
inline constexpr std::uint32_t kVariableChunks = 0xffffffffu;

// One chunk: its points and where its bytes lie.
struct LazChunk {
  std::uint64_t first_point = 0;
  std::uint64_t points = 0;
  std::uint64_t offset = 0;
  std::uint64_t bytes = 0;
};

// The chunk table of a LAZ file whose chunks hold `chunk_size` points (kVariableChunks: each its
// own). Throws PrepareError, one line naming the file and where, for a table that is missing,
// truncated or lies.
std::vector<LazChunk> readChunkTable(const InputFile& file, const LasHeader& header,
                                     std::uint32_t chunk_size);
// A point-wise LAZ file without chunks: one chunk of every point (refused past kMaxLazChunkPoints).
std::vector<LazChunk> wholeFileChunk(const InputFile& file, const LasHeader& header);

// The bytes of [offset, end) of a file, handed to a decoder a window at a time.
class FileInput final : public laz::ByteInput {
 public:
  FileInput(const InputFile& file, std::uint64_t offset, std::uint64_t end, std::string what)
      : file_(file), next_(offset), end_(end), what_(std::move(what)) {}

  std::span<const std::uint8_t> more() override;
  std::uint64_t handed() const { return handed_; }

 private:
  const InputFile& file_;
  std::uint64_t next_;
  std::uint64_t end_;
  std::string what_;
  std::vector<std::uint8_t> window_;
  std::uint64_t handed_ = 0;
};

}  // namespace octopoint::prepare
