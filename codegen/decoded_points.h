#pragma once
// Pass 1's decoded points, kept for pass 2. A LAZ chunk decodes only by running its arithmetic code
// from the start (1.7 M points a second a core), while its decoded points are 24 to 34 bytes each:
// writing them to a temporary file in pass 1 and reading them back in pass 2 costs a fraction of
// decoding every chunk a second time. The points come back exactly as the source served them
// (the same doubles, colours and intensities), so the model is the same byte for byte.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "codegen/file_io.h"
#include "codegen/point_source.h"

namespace octopoint::prepare {

class DecodedPoints {
 public:
  // For the `pieces` pieces of a source whose chunks carry colour and/or intensity as `info` says.
  DecodedPoints(const std::filesystem::path& temp_dir, std::size_t pieces);

  // Bytes of temporary file `points` points of a source like `info` need (for the disk check
  // before pass 1).
  static std::uint64_t bytesFor(const SourceInfo& info, std::uint64_t points);

  // Keeps piece `piece` as read (before anything changes it). Thread-safe for distinct pieces.
  void keep(std::size_t piece, const PointChunk& chunk);
  // Piece `piece` as kept, into `chunk` (resized). Thread-safe.
  void read(std::size_t piece, PointChunk& chunk) const;

  std::uint64_t bytesWritten() const { return file_.bytesWritten(); }

 private:
  struct Piece {
    std::uint64_t offset = 0;
    std::size_t count = 0;
    bool rgb = false;
    bool intensity = false;
  };

  TempFile file_;
  std::vector<Piece> pieces_;
};

}  // namespace octopoint::prepare
