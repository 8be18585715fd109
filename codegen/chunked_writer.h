#pragma once
// Writing a prepared model as a chunked file (format version 5, octopoint/progressive.h,
// docs/format.md): `octopoint-prepare --chunked`. No PCL here, so tools and tests without the
// scan loader can write chunked files too.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "codegen/prepared_model.h"

namespace octopoint::prepare {

// Measured in docs/streaming.md ("Choosing the chunk size"): each level is cut at the finest
// region level whose chunks hold at least this many bytes on average, so chunks are about the
// same size at every depth: larger ones cost a zoomed view bytes it does not need, smaller ones
// cost directory bytes (20 per chunk) and requests.
inline constexpr std::size_t kDefaultTargetChunkBytes = 2048;
// The head (everything before the first picture) is kept within this many bytes: the base is the
// finest depth that fits. 4 KiB take under a second on a 5 kB/s link.
inline constexpr std::size_t kDefaultHeadBudget = 4096;

struct ChunkedOptions {
  std::size_t target_chunk_bytes = kDefaultTargetChunkBytes;
  std::size_t head_budget = kDefaultHeadBudget;
};

// What the writer chose, for the preparer's report and the measurements.
struct ChunkedLayout {
  int base_depth = 0;
  bool base_added = false;               // the base is a coarser depth than any of the model's own
  std::vector<int> depths;               // of the chunked levels
  std::vector<int> region_levels;        // of the chunked levels
  std::vector<std::size_t> chunks;       // per chunked level
  std::vector<std::size_t> chunk_bytes;  // per chunked level
  std::size_t target_chunk_bytes = 0;    // larger than asked when needed to stay within version 1
  std::size_t head_bytes = 0;
  std::size_t table_bytes = 0;
  std::size_t file_bytes = 0;
};

// The chunked image of `model`, whose levels must be nested (codegen/level_voxels.h, nestLevels;
// throws PrepareError otherwise). No larger than the version-1 file of the same levels: when the
// asked chunk size would make it larger, chunks are made larger (down to one per level); only a
// model whose every level fits in one chunk can still be larger (a single depth, whose base is
// extra). Throws PrepareError when the coarsest depth is 1 (no coarser base is possible).
std::vector<std::uint8_t> serializeChunkedModel(const PreparedModel& model,
                                                const ChunkedOptions& options = {},
                                                ChunkedLayout* layout = nullptr);

}  // namespace octopoint::prepare
