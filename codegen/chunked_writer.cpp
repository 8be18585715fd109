#include "codegen/chunked_writer.h"

#include <algorithm>
#include <cassert>
#include <string>

#include "codegen/byte_output.h"
#include "codegen/level_voxels.h"
#include "codegen/octree_encoder.h"
#include "codegen/prepare_error.h"
#include "octopoint/model.h"
#include "octopoint/progressive.h"
#include "renderer/crc32.h"

namespace octopoint::prepare {
namespace {

struct Chunk {
  std::uint32_t region = 0;
  std::uint32_t points = 0;
  std::uint32_t coarse_points = 0;
  std::vector<std::uint8_t> bytes;  // masks, then palette indices
};

struct Level {
  int depth = 0;
  int region_level = 0;
  std::vector<Chunk> chunks;
};

std::size_t headBytes(std::size_t palette_count, std::size_t levels, const PreparedLevel& base) {
  return chunked::kFixedHeaderBytes + 3 * palette_count + chunked::kLevelRowBytes * levels +
         base.nodes.size() + base.leaves.size() + format::kCubePlacementBytes +
         chunked::kHeadCrcBytes;
}

// What each coarse voxel becomes at the finer depth: its refinement's mask bytes (a single 0 when
// nothing) and how many finer voxels it has. Fine voxels below each coarse one are contiguous.
struct Refinement {
  std::vector<std::uint8_t> masks;
  std::uint32_t points = 0;
};

std::vector<Refinement> refinements(const LevelVoxels& coarse, const LevelVoxels& fine) {
  const int gap = fine.depth - coarse.depth;
  const std::uint64_t suffix_mask = (std::uint64_t{1} << (3 * gap)) - 1;
  const auto orphan = [&](std::uint64_t key) {
    return PrepareError("chunked model: a voxel of depth " + std::to_string(fine.depth) + " (key " +
                        std::to_string(key) + ") has no parent at depth " +
                        std::to_string(coarse.depth) + ": the levels are not nested");
  };
  std::vector<Refinement> result(coarse.keys.size());
  std::vector<std::uint64_t> suffixes;
  std::size_t f = 0;
  for (std::size_t c = 0; c < coarse.keys.size(); ++c) {
    if (f < fine.keys.size() && fine.keys[f] >> (3 * gap) < coarse.keys[c])
      throw orphan(fine.keys[f]);
    suffixes.clear();
    for (; f < fine.keys.size() && fine.keys[f] >> (3 * gap) == coarse.keys[c]; ++f) {
      suffixes.push_back(fine.keys[f] & suffix_mask);
    }
    result[c].masks = suffixes.empty() ? std::vector<std::uint8_t>{0} : encodeOctree(suffixes, gap);
    result[c].points = static_cast<std::uint32_t>(suffixes.size());
  }
  if (f != fine.keys.size()) throw orphan(fine.keys[f]);
  return result;
}

// The finest region level in [lowest, highest] whose chunks hold at least `target` bytes on
// average (the coarsest, `lowest`, when none does): a level's bytes do not depend on how it is cut.
int chooseRegionLevel(const LevelVoxels& coarse, std::size_t level_bytes, int lowest, int highest,
                      std::size_t target) {
  for (int level = highest; level > lowest; --level) {
    const int shift = 3 * (coarse.depth - level);
    std::size_t regions = 0;
    for (std::size_t c = 0; c < coarse.keys.size(); ++c) {
      regions += c == 0 || coarse.keys[c] >> shift != coarse.keys[c - 1] >> shift;
    }
    if (level_bytes >= target * regions) return level;
  }
  return lowest;
}

// Level `fine` as chunks refining `coarse`, regions at the chosen level (at least `lowest`).
std::vector<Chunk> makeChunks(const LevelVoxels& coarse, const LevelVoxels& fine, int lowest,
                              std::size_t target, int* region_level) {
  const std::vector<Refinement> parts = refinements(coarse, fine);
  std::size_t level_bytes = fine.keys.size();
  for (const Refinement& part : parts) level_bytes += part.masks.size();
  *region_level = chooseRegionLevel(coarse, level_bytes, lowest,
                                    std::min(coarse.depth - 1, chunked::kMaxRegionLevel), target);
  const int shift = 3 * (coarse.depth - *region_level);
  std::vector<Chunk> chunks;
  for (std::size_t c = 0; c < coarse.keys.size(); ++c) {
    const auto region = static_cast<std::uint32_t>(coarse.keys[c] >> shift);
    if (chunks.empty() || chunks.back().region != region) chunks.push_back(Chunk{region, 0, 0, {}});
    Chunk& chunk = chunks.back();
    ++chunk.coarse_points;
    chunk.points += parts[c].points;
    chunk.bytes.insert(chunk.bytes.end(), parts[c].masks.begin(), parts[c].masks.end());
  }
  // Masks are in place; the palette indices follow them, in the same order.
  std::size_t next_colour = 0;
  for (Chunk& chunk : chunks) {
    chunk.bytes.insert(
        chunk.bytes.end(), fine.colours.begin() + static_cast<std::ptrdiff_t>(next_colour),
        fine.colours.begin() + static_cast<std::ptrdiff_t>(next_colour + chunk.points));
    next_colour += chunk.points;
  }
  return chunks;
}

// The base: the coarsest depth itself when its head fits the budget and finer depths remain,
// else the finest coarser depth that fits (depth 1 at worst: at most 8 voxels). Returns the index
// of the first depth of `voxels` to chunk (0 when the base is added, 1 when it is the coarsest).
std::size_t chooseBase(const PreparedModel& model, const std::vector<LevelVoxels>& voxels,
                       const ChunkedOptions& options, LevelVoxels& base) {
  if (model.levels.size() >= 2 && headBytes(model.palette.size(), model.levels.size(),
                                            model.levels.front()) <= options.head_budget) {
    base = voxels.front();
    return 1;
  }
  for (int depth = model.levels.front().depth - 1; depth >= 1; --depth) {
    base = coarsen(voxels.front(), depth, model.palette);
    if (depth == 1 || headBytes(model.palette.size(), model.levels.size() + 1, encodeLevel(base)) <=
                          options.head_budget) {
      break;
    }
  }
  return 0;
}

// Each depth from `first_chunked` on as chunks refining the one before it (the base first); a
// depth's regions are never coarser than the one before it's.
std::vector<Level> chunkLevels(const LevelVoxels& base, const std::vector<LevelVoxels>& voxels,
                               std::size_t first_chunked, std::size_t target_chunk_bytes) {
  std::vector<Level> levels;
  const LevelVoxels* coarser = &base;
  int region_level = 0;
  for (std::size_t i = first_chunked; i < voxels.size(); ++i) {
    std::vector<Chunk> chunks =
        makeChunks(*coarser, voxels[i], region_level, target_chunk_bytes, &region_level);
    levels.push_back(Level{voxels[i].depth, region_level, std::move(chunks)});
    coarser = &voxels[i];
  }
  return levels;
}

// Each level's record table (a 20-byte record per chunk) and where its chunks start, after the
// head and all the tables.
struct RecordTables {
  std::vector<std::vector<std::uint8_t>> tables;
  std::vector<std::uint64_t> level_offsets;
  std::uint64_t file_bytes = 0;
};

RecordTables recordTables(const std::vector<Level>& levels, std::size_t head_bytes,
                          std::uint64_t chunk_count) {
  RecordTables records;
  std::uint64_t offset = head_bytes + chunked::kRecordBytes * chunk_count;
  for (const Level& level : levels) {
    records.level_offsets.push_back(offset);
    std::vector<std::uint8_t>& table = records.tables.emplace_back();
    for (const Chunk& chunk : level.chunks) {
      putU32(table, chunk.region);
      putU32(table, static_cast<std::uint32_t>(chunk.bytes.size()));
      putU32(table, chunk.points);
      putU32(table, chunk.coarse_points);
      putU32(table, crc32(chunk.bytes));
      offset += chunk.bytes.size();
    }
  }
  records.file_bytes = offset;
  return records;
}

ChunkedLayout describeLayout(const std::vector<Level>& levels, int base_depth, bool base_added,
                             std::size_t head_bytes, std::uint64_t chunk_count,
                             std::size_t file_bytes) {
  ChunkedLayout layout;
  layout.base_depth = base_depth;
  layout.base_added = base_added;
  for (const Level& level : levels) {
    layout.depths.push_back(level.depth);
    layout.region_levels.push_back(level.region_level);
    layout.chunks.push_back(level.chunks.size());
    std::size_t bytes = 0;
    for (const Chunk& chunk : level.chunks) bytes += chunk.bytes.size();
    layout.chunk_bytes.push_back(bytes);
  }
  layout.head_bytes = head_bytes;
  layout.table_bytes = chunked::kRecordBytes * chunk_count;
  layout.file_bytes = file_bytes;
  return layout;
}

// The chunked image with chunks of `options.target_chunk_bytes`; fills `layout`.
std::vector<std::uint8_t> serializeLevels(const PreparedModel& model,
                                          const std::vector<LevelVoxels>& voxels,
                                          const ChunkedOptions& options, ChunkedLayout* layout) {
  LevelVoxels base;
  const std::size_t first_chunked = chooseBase(model, voxels, options, base);
  const PreparedLevel base_level = encodeLevel(base);
  const std::vector<Level> levels =
      chunkLevels(base, voxels, first_chunked, options.target_chunk_bytes);

  // Layout: head, record tables, chunks.
  const std::size_t level_count = levels.size() + 1;
  const std::size_t head_bytes = headBytes(model.palette.size(), level_count, base_level);
  std::uint64_t chunk_count = 0;
  for (const Level& level : levels) chunk_count += level.chunks.size();
  const RecordTables records = recordTables(levels, head_bytes, chunk_count);

  std::vector<std::uint8_t> out(format::kMagic, format::kMagic + sizeof format::kMagic);
  putU16(out, chunked::kFormatVersion);
  out.push_back(static_cast<std::uint8_t>(level_count));
  out.push_back(0);                 // flags
  putU64(out, model.cube_edge_pm);  // picometres, as format version 2
  putU16(out, static_cast<std::uint32_t>(model.palette.size()));
  putU16(out, 0);  // no normals
  putU32(out, static_cast<std::uint32_t>(head_bytes));
  putU64(out, records.file_bytes);
  putU32(out, static_cast<std::uint32_t>(base_level.nodes.size()));
  putU32(out, static_cast<std::uint32_t>(base_level.leaves.size()));
  for (const Rgb8& colour : model.palette) out.insert(out.end(), colour.begin(), colour.end());
  // Level table: the base row, then one per chunked level.
  // Each row carries its level's sample reach: the base's is one footprint (the coarsest depth,
  // or a coarser one made of it), a chunked level's the one the preparer measured for its depth.
  out.push_back(static_cast<std::uint8_t>(base.depth));
  out.push_back(0);  // region level
  out.push_back(format::kOneSampleReachQ4);
  out.insert(out.end(), 17, std::uint8_t{0});
  for (std::size_t j = 0; j < levels.size(); ++j) {
    out.push_back(static_cast<std::uint8_t>(levels[j].depth));
    out.push_back(static_cast<std::uint8_t>(levels[j].region_level));
    out.push_back(model.levels[first_chunked + j].sample_reach);
    out.push_back(0);
    putU32(out, static_cast<std::uint32_t>(levels[j].chunks.size()));
    putU32(out, crc32(records.tables[j]));
    putU64(out, records.level_offsets[j]);
  }
  out.insert(out.end(), base_level.nodes.begin(), base_level.nodes.end());
  out.insert(out.end(), base_level.leaves.begin(), base_level.leaves.end());
  putCubePlacement(out, model.cube);
  putU32(out, crc32(out));
  assert(out.size() == head_bytes);
  for (const std::vector<std::uint8_t>& table : records.tables)
    out.insert(out.end(), table.begin(), table.end());
  for (const Level& level : levels) {
    for (const Chunk& chunk : level.chunks)
      out.insert(out.end(), chunk.bytes.begin(), chunk.bytes.end());
  }
  assert(out.size() == records.file_bytes);
  *layout =
      describeLayout(levels, base.depth, first_chunked == 0, head_bytes, chunk_count, out.size());
  return out;
}

}  // namespace

std::vector<std::uint8_t> serializeChunkedModel(const PreparedModel& model,
                                                const ChunkedOptions& options,
                                                ChunkedLayout* layout) {
  assert(!model.levels.empty() && model.levels.size() <= format::kMaxLevels);
  if (model.levels.front().depth < 2) {
    throw PrepareError(
        "--chunked: the coarsest depth must be at least 2 (a chunked model needs a coarser base)");
  }
  std::vector<LevelVoxels> voxels;
  for (const PreparedLevel& level : model.levels) voxels.push_back(decodeLevel(level));
  std::size_t version1 = format::v1::kHeaderBytes + format::kLevelRowBytes * model.levels.size();
  for (const PreparedLevel& level : model.levels)
    version1 += level.nodes.size() + level.leaves.size();

  ChunkedLayout chosen;
  ChunkedOptions tried = options;
  std::vector<std::uint8_t> image = serializeLevels(model, voxels, tried, &chosen);
  // Each chunk costs a 20-byte record; refining instead of repeating the coarser levels saves their
  // node bytes. When the records win (few depths, small coarse levels), fewer and larger chunks,
  // down to one per level, keep the file no larger than version 1 where that is possible at all.
  const auto chunk_count = [](const ChunkedLayout& l) {
    std::size_t count = 0;
    for (std::size_t c : l.chunks) count += c;
    return count;
  };
  while (image.size() > version1 && chunk_count(chosen) > chosen.chunks.size()) {
    tried.target_chunk_bytes *= 2;
    image = serializeLevels(model, voxels, tried, &chosen);
  }
  chosen.target_chunk_bytes = tried.target_chunk_bytes;
  if (layout != nullptr) *layout = chosen;
  return image;
}

}  // namespace octopoint::prepare
