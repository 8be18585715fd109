#include "renderer/chunked_assembly.h"

#include <algorithm>
#include <span>

#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

struct HeldRegion {
  std::uint32_t code;  // Morton code at the region level, root's child index highest
  ProgressiveModel::RegionStream stream;
};

// The stream of the node at tree level `level` whose regions (Morton codes at `region_level`,
// ascending, all below this node) are `regions`: its child mask, then its children's subtrees in
// order k = 0..7 (octopoint/model.h); at the region level, the region's own stream.
void splice(std::span<const HeldRegion> regions, int level, int region_level,
            std::vector<std::uint8_t>& nodes, std::vector<std::uint8_t>& leaves) {
  if (level == region_level) {
    const ProgressiveModel::RegionStream& stream = regions.front().stream;
    nodes.insert(nodes.end(), stream.nodes.begin(), stream.nodes.end());
    leaves.insert(leaves.end(), stream.leaves.begin(), stream.leaves.end());
    return;
  }
  const int shift = 3 * (region_level - 1 - level);
  const auto child = [shift](const HeldRegion& region) { return (region.code >> shift) & 7u; };
  std::uint8_t mask = 0;
  for (const HeldRegion& region : regions)
    mask = static_cast<std::uint8_t>(mask | 1u << child(region));
  nodes.push_back(mask);
  std::size_t begin = 0;
  while (begin < regions.size()) {  // ascending codes: each child's regions are one run
    std::size_t end = begin + 1;
    while (end < regions.size() && child(regions[end]) == child(regions[begin])) ++end;
    splice(regions.subspan(begin, end - begin), level + 1, region_level, nodes, leaves);
    begin = end;
  }
}

// Points the levels, the embedded model and its view at the streams made.
bool finish(AssembledModel& assembled, const ChunkedHead& head) {
  // Version 7's reaches go with the levels (an embedded model of version 6); older heads' levels
  // are one footprint (versions 4 and 2, which end before the reach).
  const bool reached = head.format_version == chunked::kVersion7;
  for (std::size_t i = 0; i < assembled.nodes.size(); ++i) {
    assembled.levels.push_back(
        {static_cast<std::uint8_t>(head.levels[i].depth), assembled.nodes[i].data(),
         static_cast<std::uint32_t>(assembled.nodes[i].size()), assembled.leaves[i].data(),
         static_cast<std::uint32_t>(assembled.leaves[i].size()), nullptr,
         static_cast<std::uint8_t>(reached ? head.levels[i].sample_reach : 0)});
  }
  const bool placed = head.format_version != chunked::kVersion3;
  assembled.embedded =
      EmbeddedModel{"chunked model",
                    reached  ? format::kVersion6
                    : placed ? format::kVersion4
                             : format::kVersion2,
                    static_cast<std::uint8_t>(head.flags & chunked::kFlagSyntheticColour),
                    head.cube_edge_pm,
                    static_cast<std::uint16_t>(head.palette_count),
                    head.palette_rgb.data(),
                    0,
                    nullptr,
                    static_cast<std::uint8_t>(assembled.levels.size()),
                    assembled.levels.data(),
                    placed ? head.cube : CubePlacement{}};
  ModelIssue issue;
  assembled.view = ModelView::fromEmbedded(assembled.embedded, &issue);
  return assembled.view.has_value();
}

}  // namespace

std::unique_ptr<AssembledModel> assembleChunked(const ProgressiveModel& model) {
  auto assembled = std::make_unique<AssembledModel>();
  const ChunkedHead& head = model.head();
  assembled->chunked_levels = model.levelCount();
  // Level 0, the base: the whole cube already.
  const ProgressiveModel::RegionStream base = model.regionStream(0, 0);
  assembled->nodes.emplace_back(base.nodes.begin(), base.nodes.end());
  assembled->leaves.emplace_back(base.leaves.begin(), base.leaves.end());
  for (int level = 1; level < model.levelCount(); ++level) {
    const std::uint32_t count = model.chunkCount(level);
    std::vector<HeldRegion> regions;
    bool complete = count > 0;
    for (std::uint32_t i = 0; i < count && complete; ++i) {
      complete = model.chunkState(level, i) == ChunkState::kHeld;
      // A region whose voxels all refine to nothing has no stream: no node of the whole holds it.
      if (complete && !model.regionStream(level, i).nodes.empty())
        regions.push_back({model.record(level, i).region, model.regionStream(level, i)});
    }
    // A finer level is drawn only over a complete coarser one: the first gap ends the model.
    if (!complete || regions.empty()) break;
    std::vector<std::uint8_t> nodes, leaves;
    splice(regions, 0, head.levels[static_cast<std::size_t>(level)].region_level, nodes, leaves);
    assembled->nodes.push_back(std::move(nodes));
    assembled->leaves.push_back(std::move(leaves));
  }
  if (!finish(*assembled, head)) return nullptr;
  return assembled;
}

namespace {

// The whole-cube stream of `level` made of the held chunks `chunks` (ascending indices, so
// ascending region codes), those whose stream is empty left out.
bool spliceChunks(const ProgressiveModel& model, int level, std::span<const std::uint32_t> chunks,
                  AssembledModel& part) {
  std::vector<HeldRegion> regions;
  for (const std::uint32_t i : chunks) {
    const ProgressiveModel::RegionStream stream = model.regionStream(level, i);
    if (!stream.nodes.empty()) regions.push_back({model.record(level, i).region, stream});
  }
  if (regions.empty()) return false;
  std::vector<std::uint8_t> nodes, leaves;
  splice(regions, 0, model.head().levels[static_cast<std::size_t>(level)].region_level, nodes,
         leaves);
  part.nodes.push_back(std::move(nodes));  // finest first until heldPart reverses them
  part.leaves.push_back(std::move(leaves));
  return true;
}

bool held(const ProgressiveModel& model, int level, std::uint32_t index) {
  return level == 0 || model.chunkState(level, index) == ChunkState::kHeld;
}

// The part whose finest level is `level`: where level + 1 is listed (`finer_known`), the pieces of
// the held chunks of `level` whose region at the next level's region level is not held there; else
// the held chunks of `level` whole. Below it, the chunks of the coarser levels that hold them.
std::unique_ptr<AssembledModel> heldPart(const ProgressiveModel& model, int level,
                                         bool finer_known) {
  const ChunkedHead& head = model.head();
  auto part = std::make_unique<AssembledModel>();
  part->chunked_levels = model.levelCount();
  const std::uint32_t count = level == 0 ? 1 : model.chunkCount(level);
  std::vector<std::uint32_t> owners;  // the chunks of `level` the part draws from
  std::vector<HeldRegion> pieces;
  if (finer_known) {
    // A held chunk's finer chunks are listed in region order, each with its parent's index.
    const std::uint32_t finer_count = model.chunkCount(level + 1);
    const int finer_region_level = head.levels[static_cast<std::size_t>(level + 1)].region_level;
    const int region_level = head.levels[static_cast<std::size_t>(level)].region_level;
    const int below = finer_region_level - region_level;
    std::uint32_t i = 0;
    while (i < finer_count) {
      const std::uint32_t parent = model.record(level + 1, i).parent;
      std::uint32_t end = i;
      bool any_missing = false;
      while (end < finer_count && model.record(level + 1, end).parent == parent) {
        any_missing = any_missing || !held(model, level + 1, end);
        ++end;
      }
      if (held(model, level, parent) && any_missing) {
        const ProgressiveModel::RegionStream stream = model.regionStream(level, parent);
        const std::uint32_t parent_code = level == 0 ? 0 : model.record(level, parent).region;
        std::uint32_t next = i;
        // Every subregion of a held chunk is one of its finer chunks, in order (the model checked
        // it when the finer level's table arrived).
        forEachSubregion(
            stream.nodes, stream.leaves,
            head.levels[static_cast<std::size_t>(level)].depth - region_level, below,
            [&](std::uint32_t code, const StreamRange& range) {
              const std::uint32_t region = parent_code << (3 * below) | code;
              while (next < end && model.record(level + 1, next).region < region) ++next;
              if (next == end || model.record(level + 1, next).region != region ||
                  held(model, level + 1, next)) {
                return;
              }
              pieces.push_back(
                  {region,
                   {stream.nodes.subspan(range.node_begin, range.node_end - range.node_begin),
                    stream.leaves.subspan(range.leaf_begin, range.leafCount())}});
            });
        owners.push_back(parent);
      }
      i = end;
    }
    if (pieces.empty()) return nullptr;
    std::vector<std::uint8_t> nodes, leaves;
    splice(pieces, 0, finer_region_level, nodes, leaves);
    part->nodes.push_back(std::move(nodes));
    part->leaves.push_back(std::move(leaves));
  } else {
    for (std::uint32_t i = 0; i < count; ++i) {
      if (held(model, level, i)) owners.push_back(i);
    }
    if (level == 0) {
      const ProgressiveModel::RegionStream base = model.regionStream(0, 0);
      part->nodes.emplace_back(base.nodes.begin(), base.nodes.end());
      part->leaves.emplace_back(base.leaves.begin(), base.leaves.end());
    } else if (!spliceChunks(model, level, owners, *part)) {
      return nullptr;
    }
  }
  // The coarser levels: the chunks holding the owners, up to the base.
  for (int coarser = level - 1; coarser >= 0; --coarser) {
    std::vector<std::uint32_t> parents;
    for (const std::uint32_t i : owners) parents.push_back(model.record(coarser + 1, i).parent);
    parents.erase(std::unique(parents.begin(), parents.end()), parents.end());  // ascending
    owners = std::move(parents);
    if (coarser == 0) {
      const ProgressiveModel::RegionStream base = model.regionStream(0, 0);
      part->nodes.emplace_back(base.nodes.begin(), base.nodes.end());
      part->leaves.emplace_back(base.leaves.begin(), base.leaves.end());
    } else if (!spliceChunks(model, coarser, owners, *part)) {
      return nullptr;  // cannot be: a held chunk's parent is held, and holds its voxels
    }
  }
  std::reverse(part->nodes.begin(), part->nodes.end());  // coarsest first, as a model's levels
  std::reverse(part->leaves.begin(), part->leaves.end());
  if (!finish(*part, head)) return nullptr;
  return part;
}

}  // namespace

HeldParts assembleHeldParts(const ProgressiveModel& model) {
  HeldParts held_parts;
  // The levels whose record tables are known (a table is taken only after the coarser one's).
  int known = 1;
  while (known < model.levelCount() && model.hasRecordTable(known)) ++known;
  std::array<std::uint64_t, chunked::kMaxChunkedLevels> voxels{};
  voxels[0] = model.regionStream(0, 0).leaves.size();
  for (int level = 1; level < known; ++level) {
    for (std::uint32_t i = 0; i < model.chunkCount(level); ++i)
      voxels[static_cast<std::size_t>(level)] += model.record(level, i).points;
  }
  std::size_t drawable = 0;
  while (drawable < static_cast<std::size_t>(std::min(known, format::kMaxLevels)) &&
         model.levelDepth(static_cast<int>(drawable)) <= kMaxRenderDepth) {
    ++drawable;
  }
  // With the stored sample reaches (version 7; one footprint before): as a whole model's frame.
  std::array<std::int32_t, chunked::kMaxChunkedLevels> reaches{};
  for (std::size_t i = 0; i < drawable; ++i) reaches[i] = model.head().levels[i].sample_reach;
  held_parts.detail_count =
      denseDepthCount(std::span(voxels).first(drawable), std::span(reaches).first(drawable));
  for (std::size_t i = 0; i < held_parts.detail_count; ++i)
    held_parts.detail_depths[i] = model.levelDepth(static_cast<int>(i));
  // A level past the densely sampled ones is never drawn: the finest dense level's part holds
  // every region of it, whatever finer chunks are held.
  const int levels = static_cast<int>(held_parts.detail_count);
  for (int level = 0; level < levels; ++level) {
    std::unique_ptr<AssembledModel> part = heldPart(model, level, level + 1 < levels);
    if (part) held_parts.parts.push_back(std::move(part));
  }
  // Nothing drawable above the base (every held chunk empty): the base alone.
  if (held_parts.parts.empty()) {
    if (std::unique_ptr<AssembledModel> base = heldPart(model, 0, false))
      held_parts.parts.push_back(std::move(base));
  }
  return held_parts;
}

}  // namespace octopoint
