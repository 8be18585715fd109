#include <array>
#include <cassert>

#include "octopoint/model.h"
#include "octopoint/progressive.h"
#include "renderer/bit_scan.h"
#include "renderer/crc32.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {
namespace {

ChunkedIssue issueAt(ChunkedError error, std::uint64_t offset) { return {error, offset, 0}; }

// Copies one refinement (a subtree `gap` levels deep starting with a first mask that may be 0) from
// the chunk's masks to `out`; returns false, writing nothing, when the voxel has nothing at the
// finer depth.
class Refiner {
 public:
  Refiner(std::span<const std::uint8_t> masks, int gap, std::vector<std::uint8_t>& out)
      : masks_(masks), gap_(gap), out_(out) {}

  bool refineVoxel() {
    if (masks_[at_] == 0) {
      ++at_;
      return false;
    }
    copySubtree(0);
    return true;
  }

  // Rebuilds the coarse stream below one node at tree level `level` (of `levels`), refining each of
  // its leaves; returns false, and takes back what it wrote, when nothing is left below it.
  bool refineNode(const std::uint8_t*& coarse, int level, int levels) {
    const std::size_t mask_at = out_.size();
    out_.push_back(0);
    unsigned kept = 0;
    for (unsigned mask = *coarse++; mask != 0; mask &= mask - 1) {
      const unsigned child = static_cast<unsigned>(lowestChild(mask));
      const bool has_voxels =
          level + 1 == levels ? refineVoxel() : refineNode(coarse, level + 1, levels);
      if (has_voxels) kept |= 1u << child;
    }
    if (kept == 0) {
      out_.resize(mask_at);
      return false;
    }
    out_[mask_at] = static_cast<std::uint8_t>(kept);
    return true;
  }

 private:
  void copySubtree(int level) {
    const unsigned mask = masks_[at_++];
    out_.push_back(static_cast<std::uint8_t>(mask));
    if (level + 1 == gap_) return;
    for (int child = childCount(mask); child > 0; --child) copySubtree(level + 1);
  }

  std::span<const std::uint8_t> masks_;
  std::size_t at_ = 0;
  int gap_;
  std::vector<std::uint8_t>& out_;
};

void visitSubregions(const std::uint8_t*& node, const std::uint8_t*& leaf,
                     const std::uint8_t* node_base, const std::uint8_t* leaf_base, int level,
                     int levels, int level_below, std::uint32_t code,
                     const std::function<void(std::uint32_t, const StreamRange&)>& visit) {
  if (level == level_below) {
    StreamRange range;
    range.node_begin = static_cast<std::uint32_t>(node - node_base);
    range.leaf_begin = static_cast<std::uint32_t>(leaf - leaf_base);
    skipSubtree(node, leaf, level, levels);
    range.node_end = static_cast<std::uint32_t>(node - node_base);
    range.leaf_end = static_cast<std::uint32_t>(leaf - leaf_base);
    visit(code, range);
    return;
  }
  for (unsigned mask = *node++; mask != 0; mask &= mask - 1) {
    const auto child = static_cast<std::uint32_t>(lowestChild(mask));
    visitSubregions(node, leaf, node_base, leaf_base, level + 1, levels, level_below,
                    code << 3 | child, visit);
  }
}

}  // namespace

ChunkedIssue validateChunk(std::span<const std::uint8_t> bytes, const ChunkRecord& record, int gap,
                           int palette_count) {
  if (bytes.size() != record.bytes) return issueAt(ChunkedError::kWrongChunkLength, bytes.size());
  if (crc32(bytes) != record.crc) return issueAt(ChunkedError::kBadChunkCrc, 0);
  // A record that passed parseRecordTable has bytes >= points.
  const std::span<const std::uint8_t> masks = bytes.first(bytes.size() - record.points);
  const std::span<const std::uint8_t> colours = bytes.subspan(masks.size());
  std::size_t at = 0;
  std::uint64_t leaves = 0;
  // pending[l]: children still to visit at refinement level l; bounded by the gap (<= 15).
  std::array<int, format::kMaxDepth> pending{};
  for (std::uint32_t voxel = 0; voxel < record.coarse_points; ++voxel) {
    if (at == masks.size()) return issueAt(ChunkedError::kChunkTruncated, at);
    const unsigned first = masks[at++];
    if (first == 0) continue;  // nothing at the finer depth
    if (gap == 1) {
      leaves += static_cast<unsigned>(childCount(first));
      continue;
    }
    int top = 1;
    pending[1] = childCount(first);
    while (top >= 1) {
      if (pending[static_cast<std::size_t>(top)] == 0) {
        --top;
        continue;
      }
      --pending[static_cast<std::size_t>(top)];
      if (at == masks.size()) return issueAt(ChunkedError::kChunkTruncated, at);
      const unsigned mask = masks[at];
      if (mask == 0) return issueAt(ChunkedError::kChunkEmptyNode, at);
      ++at;
      if (top + 1 == gap) {
        leaves += static_cast<unsigned>(childCount(mask));
      } else {
        ++top;
        pending[static_cast<std::size_t>(top)] = childCount(mask);
      }
    }
  }
  if (at != masks.size()) return issueAt(ChunkedError::kChunkTrailingBytes, at);
  if (leaves != record.points) return issueAt(ChunkedError::kChunkLeafCountMismatch, masks.size());
  for (std::size_t i = 0; i < colours.size(); ++i) {
    if (colours[i] >= palette_count)
      return issueAt(ChunkedError::kChunkLeafOutsidePalette, masks.size() + i);
  }
  return {};
}

void refineRegion(std::span<const std::uint8_t> coarse_nodes, int coarse_levels,
                  std::span<const std::uint8_t> chunk, std::uint32_t points, int gap,
                  std::vector<std::uint8_t>& nodes, std::vector<std::uint8_t>& leaves) {
  assert(coarse_levels >= 1 && !coarse_nodes.empty() && chunk.size() >= points);
  Refiner refiner(chunk.first(chunk.size() - points), gap, nodes);
  const std::uint8_t* coarse = coarse_nodes.data();
  refiner.refineNode(coarse, 0, coarse_levels);
  assert(coarse == coarse_nodes.data() + coarse_nodes.size());
  const std::span<const std::uint8_t> colours = chunk.subspan(chunk.size() - points);
  leaves.insert(leaves.end(), colours.begin(), colours.end());
}

void forEachSubregion(
    std::span<const std::uint8_t> nodes, std::span<const std::uint8_t> leaves, int levels,
    int level_below,
    const std::function<void(std::uint32_t code, const StreamRange& range)>& visit) {
  assert(level_below < levels);
  if (nodes.empty()) return;
  const std::uint8_t* node = nodes.data();
  const std::uint8_t* leaf = leaves.data();
  visitSubregions(node, leaf, nodes.data(), leaves.data(), 0, levels, level_below, 0, visit);
}

}  // namespace octopoint
