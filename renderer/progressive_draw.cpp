// ProgressiveModel: drawing a view from the chunks held, and the order in which to fetch the rest.
//
// A frame walks the chunks from the base down. A held chunk whose depth is the one the view needs
// (or which has nothing finer yet known) is drawn whole; otherwise each of its finer regions is
// visited: held, it is walked in turn; missing, this chunk's part of it is drawn instead. Each
// piece is an ordinary octree stream rooted at a region, drawn by the decoders with the frame's
// set-up for its depth moved to the region: its root at the region's centre and its per-level
// vectors starting at the region's tree level. Every piece's z keys use the bias and shift of the
// finest depth drawn, so pieces of different depths compare, and a view holding all it needs is bit
// for bit the frame of the whole-model stream of that depth (positions are sums of the same vectors
// in any order).
#include <algorithm>
#include <cstdlib>

#include "renderer/level_of_detail.h"
#include "renderer/progressive_model.h"

namespace octopoint {
namespace {

// The set-up `full` (for a whole-model stream) moved to subtrees rooted at tree level `level`;
// the root is set per piece.
FrameSetup movedToLevel(const FrameSetup& full, int level, const FrameSetup& finest) {
  FrameSetup moved = full;
  moved.depth = full.depth - level;
  for (int l = 0; l < moved.depth; ++l) {
    moved.child_offset[static_cast<std::size_t>(l)] =
        full.child_offset[static_cast<std::size_t>(l + level)];
  }
  moved.depth_bias = finest.depth_bias;
  moved.depth_shift = finest.depth_shift;
  return moved;
}

// Draws pieces into a frame, counting them.
struct PieceDrawer {
  Variant variant;
  FrameView& frame;
  const std::atomic<bool>* abort;
  ProgressiveDrawStats stats;
  bool aborted = false;

  void operator()(FrameSetup& setup, const Vec3& centre, std::span<const std::uint8_t> nodes,
                  std::span<const std::uint8_t> leaves, bool coarser) {
    ++stats.pieces;
    stats.coarser_pieces += coarser;
    if (nodes.empty() || aborted) return;  // an empty region: its voxels all vanished at this depth
    stats.points += leaves.size();
    setup.root = centre;
    aborted = !renderLevel(variant, LevelView{setup.depth, nodes, leaves}, setup, frame, abort);
  }
};

// Only counts: whether any piece is coarser than the view needs.
struct PieceCounter {
  ProgressiveDrawStats stats;
  void operator()(FrameSetup&, const Vec3&, std::span<const std::uint8_t>,
                  std::span<const std::uint8_t> leaves, bool coarser) {
    ++stats.pieces;
    stats.coarser_pieces += coarser;
    stats.points += leaves.size();
  }
};

}  // namespace

std::optional<int> ProgressiveModel::wantedDepth(const Camera& camera) const {
  std::array<int, chunked::kMaxChunkedLevels> depths{};
  for (int j = 0; j < head_.level_count; ++j) depths[static_cast<std::size_t>(j)] = levelDepth(j);
  return autoDepth(std::span<const int>(depths.data(), static_cast<std::size_t>(head_.level_count)),
                   camera);
}

bool ProgressiveModel::prepareFrame(const Camera& camera, int coarser_levels) {
  const std::optional<int> wanted = wantedDepth(camera);
  if (!wanted) return false;
  int drawn = 0;
  while (drawn + 1 < head_.level_count && levelDepth(drawn + 1) <= *wanted) ++drawn;
  drawn = std::max(0, drawn - coarser_levels);
  frame_.drawn_level = drawn;
  frame_.wanted_depth = *wanted;
  // Where a leaf's splat reaches from its position, over every depth that may be drawn.
  frame_.splat_low = {0, 0, 0};
  frame_.splat_high = {0, 0, 0};
  for (int j = 0; j <= drawn; ++j) {
    FrameSetup& full = frame_.full[static_cast<std::size_t>(j)];
    if (buildFrameSetup(camera, levelDepth(j), kDefaultFractionBits, &full) != CameraError::kNone)
      return false;
    frame_.splat_low.x = std::min(frame_.splat_low.x, full.splat.offset_x);
    frame_.splat_low.y = std::min(frame_.splat_low.y, full.splat.offset_y);
    frame_.splat_high.x = std::max(frame_.splat_high.x, full.splat.offset_x + full.splat.span_x);
    frame_.splat_high.y = std::max(frame_.splat_high.y, full.splat.offset_y + full.splat.span_y);
  }
  const FrameSetup& finest = frame_.full[static_cast<std::size_t>(drawn)];
  for (int j = 0; j <= drawn; ++j) {
    const auto at = static_cast<std::size_t>(j);
    const int own_level = j == 0 ? 0 : head_.levels[at].region_level;
    frame_.own[at] = movedToLevel(frame_.full[at], own_level, finest);
    frame_.own_reach[at] = reachBelow(own_level);
    if (j + 1 < head_.level_count) {
      frame_.restricted[at] =
          movedToLevel(frame_.full[at], head_.levels[at + 1].region_level, finest);
      frame_.restricted_reach[at] = reachBelow(head_.levels[at + 1].region_level);
    }
  }
  frame_.width = camera.width;
  frame_.height = camera.height;
  return true;
}

// Leaves of a node at `tree_level` lie within the sum, over the levels below it down to the finest
// depth drawn, of the largest child offset per axis (as in renderer/subtree_clip.h). Coarser depths
// stop earlier, so this bounds them too.
Vec3 ProgressiveModel::reachBelow(int tree_level) const {
  const FrameSetup& finest = frame_.full[static_cast<std::size_t>(frame_.drawn_level)];
  Vec3 reach{0, 0, 0};
  for (int l = tree_level; l < finest.depth; ++l) {
    std::int32_t widest_x = 0, widest_y = 0;
    for (const Vec3& d : finest.child_offset[static_cast<std::size_t>(l)]) {
      widest_x = std::max(widest_x, std::abs(d.x));
      widest_y = std::max(widest_y, std::abs(d.y));
    }
    reach.x += widest_x;  // bounded by buildFrameSetup's overflow check
    reach.y += widest_y;
  }
  return reach;
}

bool ProgressiveModel::offScreen(const Vec3& centre, const Vec3& reach) const {
  const int f = kDefaultFractionBits;
  const std::int64_t x_end = std::int64_t{frame_.width} << f,
                     y_end = std::int64_t{frame_.height} << f;
  return std::int64_t{centre.x} + reach.x < 0 || std::int64_t{centre.x} - reach.x >= x_end ||
         std::int64_t{centre.y} + reach.y < 0 || std::int64_t{centre.y} - reach.y >= y_end;
}

Vec3 ProgressiveModel::regionCentre(int level, std::uint32_t region) const {
  const FrameSetup& full = frame_.full[static_cast<std::size_t>(frame_.drawn_level)];
  const int region_level =
      level == 0 ? 0 : head_.levels[static_cast<std::size_t>(level)].region_level;
  Vec3 centre = full.root;
  for (int l = 0; l < region_level; ++l) {
    const unsigned child = (region >> (3 * (region_level - 1 - l))) & 7u;
    const Vec3& d = full.child_offset[static_cast<std::size_t>(l)][child];
    centre = {centre.x + d.x, centre.y + d.y, centre.z + d.z};
  }
  return centre;
}

template <typename PieceVisitor>
void ProgressiveModel::visitPieces(int level, std::uint32_t index, PieceVisitor& visitor) {
  const auto at = static_cast<std::size_t>(level);
  Slot& slot = levels_[at].slots[index];
  const Vec3 centre = regionCentre(level, levels_[at].records[index].region);
  if (offScreen(centre, frame_.own_reach[at])) return;
  if (level == frame_.drawn_level || !levels_[at + 1].table_known) {
    visitor(frame_.own[at], centre, slot.nodes, slot.leaves, level < frame_.drawn_level);
    return;
  }
  Level& finer = levels_[at + 1];
  for (std::uint32_t c = slot.child_begin; c < slot.child_end; ++c) {
    const Slot& child = finer.slots[c];
    if (child.state == ChunkState::kHeld) {
      visitPieces(level + 1, c, visitor);
      continue;
    }
    const Vec3 child_centre = regionCentre(level + 1, finer.records[c].region);
    if (offScreen(child_centre, frame_.restricted_reach[at])) continue;
    const StreamRange& r =
        child.in_parent;  // known: the chunk is held and its finer table is known
    visitor(
        frame_.restricted[at], child_centre,
        std::span<const std::uint8_t>(slot.nodes).subspan(r.node_begin, r.node_end - r.node_begin),
        std::span<const std::uint8_t>(slot.leaves).subspan(r.leaf_begin, r.leafCount()), true);
  }
}

bool ProgressiveModel::draw(const Camera& camera, Variant variant, FrameView& frame,
                            ProgressiveDrawStats* stats, const std::atomic<bool>* abort,
                            int coarser_levels) {
  if (!prepareFrame(camera, coarser_levels)) return false;
  PieceDrawer drawer{variant, frame, abort, {}};
  visitPieces(0, 0, drawer);
  if (stats != nullptr) {
    *stats = drawer.stats;
    stats->wanted_depth = frame_.wanted_depth;
    stats->drawn_depth = levelDepth(frame_.drawn_level);
  }
  return !drawer.aborted;
}

bool ProgressiveModel::viewComplete(const Camera& camera) {
  if (!prepareFrame(camera)) return false;
  PieceCounter counter;
  visitPieces(0, 0, counter);
  return counter.stats.coarser_pieces == 0;
}

std::size_t ProgressiveModel::fetchPriority(const Camera& camera, bool include_invisible,
                                            std::span<FetchItem> out, std::size_t* total) {
  if (total != nullptr) *total = 0;
  if (!prepareFrame(camera)) return 0;
  priority_scratch_.clear();
  const std::int64_t frame_w = camera.width, frame_h = camera.height;
  for (int level = 1; level <= frame_.drawn_level; ++level) {
    const auto at = static_cast<std::size_t>(level);
    // Key, most significant first: invisible (1 bit), level (4 bits), 2^32 - 1 - on-screen area
    // (32 bits; a record table takes 0, before its level's chunks), index (27 bits).
    const std::uint64_t level_key = std::uint64_t(level) << 59;
    if (levels_[at].table_unavailable) break;  // nothing of this level or finer will come
    if (!levels_[at].table_known) {
      priority_scratch_.push_back({level_key, recordTableItem(level)});
      continue;
    }
    const std::int64_t reach_x = frame_.own_reach[at].x, reach_y = frame_.own_reach[at].y;
    const int f = kDefaultFractionBits;
    Level& target = levels_[at];
    const Level& coarser = levels_[at - 1];
    for (std::uint32_t i = 0; i < target.records.size(); ++i) {
      Slot& slot = target.slots[i];
      const ChunkRecord& rec = target.records[i];
      slot.blocked = slot.state == ChunkState::kUnavailable || coarser.slots[rec.parent].blocked;
      if (slot.state != ChunkState::kMissing || slot.blocked) continue;
      const Vec3 c = regionCentre(level, rec.region);
      const bool visible = !offScreen(c, frame_.own_reach[at]);
      if (!visible && !include_invisible) continue;
      const std::int64_t x0 = std::clamp<std::int64_t>((c.x - reach_x) >> f, 0, frame_w);
      const std::int64_t x1 = std::clamp<std::int64_t>(((c.x + reach_x) >> f) + 1, 0, frame_w);
      const std::int64_t y0 = std::clamp<std::int64_t>((c.y - reach_y) >> f, 0, frame_h);
      const std::int64_t y1 = std::clamp<std::int64_t>(((c.y + reach_y) >> f) + 1, 0, frame_h);
      const auto area = static_cast<std::uint64_t>((x1 - x0) * (y1 - y0));
      const std::uint64_t key = (visible ? 0 : std::uint64_t{1} << 63) | level_key |
                                (std::uint64_t{0xFFFF'FFFF} - area) << 27 | i;
      FetchItem item = chunkItem(level, i);
      item.visible = visible;
      priority_scratch_.push_back({key, item});
    }
  }
  if (total != nullptr) *total = priority_scratch_.size();
  const std::size_t count = std::min(out.size(), priority_scratch_.size());
  std::partial_sort(
      priority_scratch_.begin(), priority_scratch_.begin() + static_cast<std::ptrdiff_t>(count),
      priority_scratch_.end(), [](const Priority& a, const Priority& b) { return a.key < b.key; });
  for (std::size_t i = 0; i < count; ++i) out[i] = priority_scratch_[i].item;
  return count;
}

}  // namespace octopoint
