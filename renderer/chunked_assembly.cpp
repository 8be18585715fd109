#include "renderer/chunked_assembly.h"

#include <span>

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
  for (std::size_t i = 0; i < assembled->nodes.size(); ++i) {
    assembled->levels.push_back(
        {static_cast<std::uint8_t>(head.levels[i].depth), assembled->nodes[i].data(),
         static_cast<std::uint32_t>(assembled->nodes[i].size()), assembled->leaves[i].data(),
         static_cast<std::uint32_t>(assembled->leaves[i].size())});
  }
  const bool placed = head.format_version == chunked::kVersion5;
  assembled->embedded =
      EmbeddedModel{"chunked model",
                    placed ? format::kVersion4 : format::kVersion2,
                    static_cast<std::uint8_t>(head.flags & chunked::kFlagSyntheticColour),
                    head.cube_edge_pm,
                    static_cast<std::uint16_t>(head.palette_count),
                    head.palette_rgb.data(),
                    0,
                    nullptr,
                    static_cast<std::uint8_t>(assembled->levels.size()),
                    assembled->levels.data(),
                    placed ? head.cube : CubePlacement{}};
  ModelIssue issue;
  assembled->view = ModelView::fromEmbedded(assembled->embedded, &issue);
  if (!assembled->view) return nullptr;
  return assembled;
}

}  // namespace octopoint
