#include "tests/support/model_images.h"

#include <cassert>
#include <cstddef>
#include <span>

#include "codegen/level_voxels.h"
#include "codegen/model_writer.h"
#include "codegen/octree_encoder.h"
#include "octopoint/model.h"
#include "renderer/crc32.h"
#include "renderer/little_endian.h"

namespace octopoint::fuzzing {
namespace {

prepare::PreparedModel preparedShell(const EmbeddedModel& model) {
  prepare::PreparedModel prepared;
  prepared.name = model.name;
  prepared.cube_edge_pm = model.cube_edge_pm;
  prepared.cube = model.cube;
  prepared.synthetic_colour = (model.flags & format::v2::kFlagSyntheticColour) != 0;
  for (int i = 0; i < model.palette_count; ++i) {
    const std::uint8_t* entry = model.palette_rgb + 3 * static_cast<std::size_t>(i);
    prepared.palette.push_back({entry[0], entry[1], entry[2]});
  }
  for (int i = 0; i < model.normal_count; ++i) {
    const std::int16_t* entry = model.normal_xyz + 3 * static_cast<std::size_t>(i);
    prepared.normal_palette.push_back({entry[0], entry[1], entry[2]});
  }
  return prepared;
}

// Lists the Morton key (the child indices from the root down, 3 bits a level) of every leaf of a
// valid stream, in stream order, which is ascending key order.
struct KeyLister {
  const EmbeddedLevel& level;
  std::size_t node_at = 0;
  std::vector<std::uint64_t> keys;

  void visit(int tree_level, std::uint64_t key) {
    if (tree_level == level.depth) {
      keys.push_back(key);
      return;
    }
    const std::uint8_t mask = level.nodes[node_at++];
    for (int k = 0; k < 8; ++k) {
      if (mask & (1u << k)) visit(tree_level + 1, key << 3 | static_cast<std::uint64_t>(k));
    }
  }
};

using Bytes = std::vector<std::uint8_t>;

void putU32(Bytes& image, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i)
    image[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(value >> (8 * i));
}

// The records' chunk CRCs and each table's CRC in the level table, as far as they lie in the file.
void resealTables(Bytes& image) {
  using le::readU16;
  using le::readU32;
  using le::readU64;
  const auto fits = [&](std::uint64_t at, std::uint64_t size) { return at + size <= image.size(); };
  const std::size_t level_count = image[6];
  const std::size_t palette_count = readU16(&image[16]);
  const std::size_t head_bytes = readU32(&image[20]);
  const std::size_t rows_at = 40 + 3 * palette_count;
  std::uint64_t table_at = head_bytes;
  for (std::size_t j = 1; j < level_count && fits(rows_at + 20 * j, 20); ++j) {
    const std::size_t row = rows_at + 20 * j;
    const std::uint64_t count = readU32(&image[row + 4]);
    std::uint64_t chunk_at = readU64(&image[row + 12]);
    if (!fits(table_at, 20 * count)) return;
    for (std::uint64_t i = 0; i < count; ++i) {
      const auto record = static_cast<std::size_t>(table_at + 20 * i);
      const std::uint32_t bytes = readU32(&image[record + 4]);
      if (fits(chunk_at, bytes)) {
        putU32(image, record + 16,
               crc32(std::span(image).subspan(static_cast<std::size_t>(chunk_at), bytes)));
      }
      chunk_at += bytes;
    }
    putU32(image, row + 8,
           crc32(std::span(image).subspan(static_cast<std::size_t>(table_at),
                                          static_cast<std::size_t>(20 * count))));
    table_at += 20 * count;
  }
}

}  // namespace

prepare::PreparedModel preparedModel(const EmbeddedModel& model, const std::vector<int>& depths) {
  prepare::PreparedModel prepared = preparedShell(model);
  for (int i = 0; i < model.level_count; ++i) {
    const EmbeddedLevel& level = model.levels[i];
    prepare::PreparedLevel copy{level.depth,
                                {level.nodes, level.nodes + level.node_bytes},
                                {level.leaves, level.leaves + level.leaf_count}};
    if (level.normals != nullptr)
      copy.normals.assign(level.normals, level.normals + level.leaf_count);
    prepared.levels.push_back(std::move(copy));
  }
  if (!depths.empty()) {
    const prepare::LevelVoxels finest = prepare::decodeLevel(prepared.levels.back());
    std::vector<prepare::PreparedLevel> levels;
    for (int depth : depths) {
      levels.push_back(depth == finest.depth ? prepared.levels.back()
                                             : prepare::encodeLevel(prepare::coarsen(
                                                   finest, depth, prepared.palette)));
    }
    prepared.levels = std::move(levels);
    // Coarsened levels have no normals: keep the set consistent (the chunked format carries none).
    prepared.normal_palette.clear();
    for (prepare::PreparedLevel& level : prepared.levels) level.normals.clear();
  }
  return prepared;
}

std::vector<std::uint8_t> octImage(const EmbeddedModel& model) {
  return prepare::serializeModel(preparedModel(model));
}

std::vector<std::uint8_t> chunkedImage(const EmbeddedModel& model, const std::vector<int>& depths,
                                       const prepare::ChunkedOptions& options) {
  return prepare::serializeChunkedModel(preparedModel(model, depths), options);
}

std::vector<std::uint8_t> coarsenedOctImage(const EmbeddedModel& model, int depth) {
  const EmbeddedLevel& finest = model.levels[model.level_count - 1];
  assert(depth >= 1 && depth <= finest.depth);
  KeyLister lister{finest, 0, {}};
  lister.visit(0, 0);
  const int shift = 3 * (finest.depth - depth);
  prepare::PreparedLevel coarse{depth, {}, {}, {}};
  std::vector<std::uint64_t> coarse_keys;
  for (std::size_t i = 0; i < lister.keys.size(); ++i) {
    const std::uint64_t key = lister.keys[i] >> shift;
    if (!coarse_keys.empty() && coarse_keys.back() == key) continue;
    coarse_keys.push_back(key);
    coarse.leaves.push_back(finest.leaves[i]);
    if (finest.normals != nullptr) coarse.normals.push_back(finest.normals[i]);
  }
  coarse.nodes = prepare::encodeOctree(coarse_keys, depth);
  prepare::PreparedModel prepared = preparedShell(model);
  prepared.levels.push_back(std::move(coarse));
  return prepare::serializeModel(prepared);
}

void resealChunked(Bytes& image) {
  using le::readU32;
  // Reads with bounds: an altered header may point anywhere; whatever lies outside is left alone.
  const auto fits = [&](std::uint64_t at, std::uint64_t size) { return at + size <= image.size(); };
  if (!fits(0, 40)) return;
  resealTables(image);
  const std::size_t head_bytes = readU32(&image[20]);
  if (head_bytes >= 4 && fits(0, head_bytes)) {
    putU32(image, head_bytes - 4, crc32(std::span(image).first(head_bytes - 4)));
  }
}

}  // namespace octopoint::fuzzing
