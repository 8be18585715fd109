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
#include <array>
#include <cstdlib>

#include "octopoint/progressive.h"
#include "renderer/level_of_detail.h"

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

// Adds each piece to a smooth frame (ProgressiveModel::drawSmooth) with the set-up draw gave it.
struct PieceBlender {
  SmoothSplats& smooth;
  FrameView& frame;
  const PaletteRgb& palette;
  const std::atomic<bool>* abort;
  bool failed = false;

  void operator()(FrameSetup& setup, const Vec3& centre, std::span<const std::uint8_t> nodes,
                  std::span<const std::uint8_t> leaves, bool) {
    if (nodes.empty() || failed) return;
    setup.root = centre;
    failed =
        !smooth.accumulate(LevelView{setup.depth, nodes, leaves}, setup, frame, palette, abort);
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
  return wantedDepth(tables_, camera);
}

// Depth by projected size over the depths the scan samples densely (renderer/level_of_detail.h,
// denseDepthCount): the known levels' voxel counts and stored reaches say which those are, as for
// a one-file model (autoLevel); a level whose table is not
// known yet may be dense, so it stays a candidate until its table says otherwise.
std::optional<int> ProgressiveModel::wantedDepth(const ProgressiveTables& tables,
                                                 const Camera& camera) const {
  const auto known = static_cast<std::size_t>(tables.known_levels);
  // The head's reaches (version 7; one footprint before), as autoLevel takes a model's.
  std::array<std::int32_t, chunked::kMaxChunkedLevels> reaches{};
  for (std::size_t j = 0; j < known; ++j) reaches[j] = head_.levels[j].sample_reach;
  const std::size_t dense =
      denseDepthCount(std::span(tables.points).first(known), std::span(reaches).first(known));
  const std::size_t candidates =
      dense < known && !every_stored_depth_ ? dense : static_cast<std::size_t>(head_.level_count);
  std::array<int, chunked::kMaxChunkedLevels> depths{};
  for (std::size_t j = 0; j < candidates; ++j) depths[j] = levelDepth(static_cast<int>(j));
  return autoDepth(std::span<const int>(depths.data(), candidates), camera);
}

bool ProgressiveModel::prepareFrame(const ProgressiveTables& tables, const Camera& camera,
                                    int coarser_levels, Setups& frame) const {
  const std::optional<int> wanted = wantedDepth(tables, camera);
  if (!wanted) return false;
  int drawn = 0;
  while (drawn + 1 < head_.level_count && levelDepth(drawn + 1) <= *wanted) ++drawn;
  drawn = std::max(0, drawn - coarser_levels);
  frame.drawn_level = drawn;
  frame.wanted_depth = *wanted;
  frame.budget_level = 0;
  // Where a leaf's splat reaches from its position, over every depth that may be drawn.
  frame.splat_low = {0, 0, 0};
  frame.splat_high = {0, 0, 0};
  for (int j = 0; j <= drawn; ++j) {
    FrameSetup& full = frame.full[static_cast<std::size_t>(j)];
    // Each level as wide as its samples lie apart (the reach a version 7 head stores).
    if (buildFrameSetup(camera, levelDepth(j), kDefaultFractionBits, &full,
                        head_.levels[static_cast<std::size_t>(j)].sample_reach) !=
        CameraError::kNone)
      return false;
    frame.splat_low.x = std::min(frame.splat_low.x, full.splat.offset_x);
    frame.splat_low.y = std::min(frame.splat_low.y, full.splat.offset_y);
    frame.splat_high.x = std::max(frame.splat_high.x, full.splat.offset_x + full.splat.span_x);
    frame.splat_high.y = std::max(frame.splat_high.y, full.splat.offset_y + full.splat.span_y);
  }
  frame.width = camera.width;
  frame.height = camera.height;
  const FrameSetup& finest = frame.full[static_cast<std::size_t>(drawn)];
  for (int j = 0; j <= drawn; ++j) {
    const auto at = static_cast<std::size_t>(j);
    const int own_level = j == 0 ? 0 : head_.levels[at].region_level;
    frame.own[at] = movedToLevel(frame.full[at], own_level, finest);
    frame.own_reach[at] = reachBelow(frame, own_level);
    if (j + 1 < head_.level_count) {
      frame.restricted[at] =
          movedToLevel(frame.full[at], head_.levels[at + 1].region_level, finest);
      frame.restricted_reach[at] = reachBelow(frame, head_.levels[at + 1].region_level);
    }
  }
  return true;
}

// Leaves of a node at `tree_level` lie within the sum, over the levels below it down to the finest
// depth drawn, of the largest child offset per axis (as in renderer/subtree_clip.h). Coarser depths
// stop earlier, so this bounds them too.
Vec3 ProgressiveModel::reachBelow(const Setups& frame, int tree_level) const {
  const FrameSetup& finest = frame.full[static_cast<std::size_t>(frame.drawn_level)];
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

bool ProgressiveModel::offScreen(const Setups& frame, const Vec3& centre, const Vec3& reach) {
  const int f = kDefaultFractionBits;
  const std::int64_t x_end = std::int64_t{frame.width} << f,
                     y_end = std::int64_t{frame.height} << f;
  return std::int64_t{centre.x} + reach.x < 0 || std::int64_t{centre.x} - reach.x >= x_end ||
         std::int64_t{centre.y} + reach.y < 0 || std::int64_t{centre.y} - reach.y >= y_end;
}

// The part of a region's bounds that lies on screen, in Q(64-2F).2F square pixels: exact (sides
// below 2^28), so that regions wholly on screen at one level compare equal whatever their
// sub-pixel position.
std::uint64_t ProgressiveModel::screenArea(const Setups& frame, const Vec3& c, const Vec3& reach) {
  const int f = kDefaultFractionBits;
  const std::int64_t w = std::int64_t{frame.width} << f, h = std::int64_t{frame.height} << f;
  const std::int64_t x0 = std::clamp<std::int64_t>(std::int64_t{c.x} - reach.x, 0, w);
  const std::int64_t x1 = std::clamp<std::int64_t>(std::int64_t{c.x} + reach.x, 0, w);
  const std::int64_t y0 = std::clamp<std::int64_t>(std::int64_t{c.y} - reach.y, 0, h);
  const std::int64_t y1 = std::clamp<std::int64_t>(std::int64_t{c.y} + reach.y, 0, h);
  return static_cast<std::uint64_t>((x1 - x0) * (y1 - y0));
}

Vec3 ProgressiveModel::regionCentre(const Setups& frame, int level, std::uint32_t region) const {
  const FrameSetup& full = frame.full[static_cast<std::size_t>(frame.drawn_level)];
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

// Reads only what `snapshot` says is published: the tables of its known levels and the streams of
// its drawable chunks (never a slot's state, which the feeder may be changing).
template <typename PieceVisitor>
void ProgressiveModel::visitPieces(ProgressiveFrame& snapshot, int level, std::uint32_t index,
                                   PieceVisitor& visitor) const {
  const auto at = static_cast<std::size_t>(level);
  Setups& frame = snapshot.setups_;
  const ProgressiveTables& tables = snapshot.tables_;
  const Slot& slot = levels_[at].slots[index];
  if (level == 0 && snapshot.drawable_[0] == 0) return;  // the base contradicted level 1's table
  const Vec3 centre = regionCentre(frame, level, levels_[at].records[index].region);
  if (offScreen(frame, centre, frame.own_reach[at])) return;
  if (level == frame.drawn_level || level + 1 >= tables.known_levels) {
    visitor(frame.own[at], centre, slot.nodes, slot.leaves, level < frame.drawn_level);
    return;
  }
  const Level& finer = levels_[at + 1];
  const std::uint8_t* finer_drawable = snapshot.drawable_.data() + tables.first_chunk[at + 1];
  const bool budget_splits = level + 1 == frame.budget_level;
  for (std::uint32_t c = slot.child_begin; c < slot.child_end; ++c) {
    if (finer_drawable[c] != 0 && (!budget_splits || snapshot.kept_[c] != 0)) {
      visitPieces(snapshot, level + 1, c, visitor);
      continue;
    }
    const Vec3 child_centre = regionCentre(frame, level + 1, finer.records[c].region);
    if (offScreen(frame, child_centre, frame.restricted_reach[at])) continue;
    // Known: this chunk is drawable and the finer table is known, so linkChildren set it.
    const StreamRange& r = finer.slots[c].in_parent;
    visitor(
        frame.restricted[at], child_centre,
        std::span<const std::uint8_t>(slot.nodes).subspan(r.node_begin, r.node_end - r.node_begin),
        std::span<const std::uint8_t>(slot.leaves).subspan(r.leaf_begin, r.leafCount()), true);
  }
}

// The points of the visible chunks of `level` (its table known) at their depth and one coarser.
ProgressiveModel::BudgetCost ProgressiveModel::visibleCost(const ProgressiveFrame& snapshot,
                                                           int level) const {
  const Setups& frame = snapshot.setups_;
  const auto at = static_cast<std::size_t>(level);
  BudgetCost cost;
  for (const ChunkRecord& rec : levels_[at].records) {
    if (offScreen(frame, regionCentre(frame, level, rec.region), frame.own_reach[at])) continue;
    cost.own += rec.points;
    cost.coarser += rec.coarse_points;
  }
  return cost;
}

// The point budget (see draw): after prepareFrame, chooses the level it splits and which of its
// visible chunks keep their depth (snapshot.kept_). Returns false for a camera prepareFrame
// refuses at a coarser level.
bool ProgressiveModel::applyPointBudget(ProgressiveFrame& snapshot, const Camera& camera,
                                        int coarser_levels) const {
  const std::uint64_t budget = snapshot.point_budget_;
  Setups& frame = snapshot.setups_;
  if (budget == 0) return true;
  int level = 0;
  BudgetCost cost;
  for (;;) {
    level = std::min(frame.drawn_level, snapshot.tables_.known_levels - 1);
    if (level < 1) return true;  // the base alone: nothing coarser to draw
    cost = visibleCost(snapshot, level);
    if (cost.own <= budget) return true;  // the view fits
    if (cost.coarser <= budget || level == 1) break;
    // Even one depth coarser everywhere is over the budget: the level above is the one to split.
    coarser_levels += frame.drawn_level - level + 1;
    if (!prepareFrame(snapshot.tables_, camera, coarser_levels, frame)) return false;
  }
  const auto at = static_cast<std::size_t>(level);
  const std::vector<ChunkRecord>& records = levels_[at].records;
  std::vector<ProgressiveFrame::BudgetEntry>& order = snapshot.budget_order_;
  order.clear();  // capacity: every chunk of the largest known level (snapshot)
  for (std::uint32_t i = 0; i < records.size(); ++i) {
    const Vec3 centre = regionCentre(frame, level, records[i].region);
    const bool visible = !offScreen(frame, centre, frame.own_reach[at]);
    snapshot.kept_[i] = visible ? 0 : 1;  // an invisible chunk draws nothing either way
    if (visible) order.push_back({screenArea(frame, centre, frame.own_reach[at]), centre.z, i});
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    if (a.area != b.area) return a.area > b.area;
    if (a.z != b.z) return a.z < b.z;
    return a.index < b.index;
  });
  std::uint64_t total = cost.coarser;  // every visible chunk one depth coarser
  for (const ProgressiveFrame::BudgetEntry& entry : order) {
    const ChunkRecord& rec = records[entry.index];
    const std::uint64_t with_it = total - rec.coarse_points + rec.points;
    if (with_it > budget) break;  // the rest, smaller or farther, stay coarser
    total = with_it;
    snapshot.kept_[entry.index] = 1;
  }
  frame.budget_level = level;
  return true;
}

bool ProgressiveModel::draw(const Camera& camera, Variant variant, FrameView& frame,
                            ProgressiveDrawStats* stats, const std::atomic<bool>* abort,
                            int coarser_levels) {
  snapshot(own_frame_);
  return draw(own_frame_, camera, variant, frame, stats, abort, coarser_levels);
}

bool ProgressiveModel::draw(ProgressiveFrame& snapshot, const Camera& camera, Variant variant,
                            FrameView& frame, ProgressiveDrawStats* stats,
                            const std::atomic<bool>* abort, int coarser_levels) const {
  if (snapshot.drawable_.empty()) return false;  // never given a snapshot
  if (!prepareFrame(snapshot.tables_, camera, coarser_levels, snapshot.setups_)) return false;
  if (!applyPointBudget(snapshot, camera, coarser_levels)) return false;
  PieceDrawer drawer{variant, frame, abort, {}};
  visitPieces(snapshot, 0, 0, drawer);
  if (stats != nullptr) {
    *stats = drawer.stats;
    const int split = snapshot.setups_.budget_level;
    if (split != 0) {
      for (std::uint32_t i = 0; i < chunkCount(split); ++i)
        stats->over_budget_chunks += snapshot.kept_[i] == 0;
    }
    stats->wanted_depth = snapshot.setups_.wanted_depth;
    stats->drawn_depth = levelDepth(snapshot.setups_.drawn_level);
  }
  return !drawer.aborted;
}

bool ProgressiveModel::drawSmooth(ProgressiveFrame& snapshot, const Camera& camera, Variant variant,
                                  FrameView& frame, SmoothSplats& smooth, const PaletteRgb& palette,
                                  ProgressiveDrawStats* stats, const std::atomic<bool>* abort,
                                  int coarser_levels) const {
  if (!draw(snapshot, camera, variant, frame, stats, abort, coarser_levels)) return false;
  // Whether the frame blends follows the depth drawn (the whole frame's set-up at that depth);
  // pieces drawn coarser blend with their own, wider kernel.
  const FrameSetup& drawn =
      snapshot.setups_.full[static_cast<std::size_t>(snapshot.setups_.drawn_level)];
  if (drawn.splat.active() && !drawsSplats(variant)) return false;
  if (!smooth.begin(drawn, frame)) return false;
  PieceBlender blender{smooth, frame, palette, abort};
  visitPieces(snapshot, 0, 0, blender);
  return !blender.failed && smooth.finish(frame);
}

bool ProgressiveModel::drawSmooth(const Camera& camera, Variant variant, FrameView& frame,
                                  SmoothSplats& smooth, const PaletteRgb& palette,
                                  ProgressiveDrawStats* stats) {
  snapshot(own_frame_);
  return drawSmooth(own_frame_, camera, variant, frame, smooth, palette, stats);
}

bool ProgressiveModel::viewComplete(const Camera& camera) {
  snapshot(own_frame_);
  if (!prepareFrame(own_frame_.tables_, camera, 0, own_frame_.setups_)) return false;
  PieceCounter counter;
  visitPieces(own_frame_, 0, 0, counter);
  return counter.stats.coarser_pieces == 0;
}

std::size_t ProgressiveModel::fetchPriority(const Camera& camera, bool include_invisible,
                                            std::span<FetchItem> out, std::size_t* total) {
  if (total != nullptr) *total = 0;
  Setups& frame = own_frame_.setups_;
  if (!prepareFrame(tables_, camera, 0, frame)) return 0;
  priority_scratch_.clear();
  const std::int64_t frame_w = camera.width, frame_h = camera.height;
  for (int level = 1; level <= frame.drawn_level; ++level) {
    const auto at = static_cast<std::size_t>(level);
    // Key, most significant first: invisible (1 bit), level (4 bits), 2^32 - 1 - on-screen area
    // (32 bits; a record table takes 0, before its level's chunks), index (27 bits).
    const std::uint64_t level_key = std::uint64_t(level) << 59;
    if (levels_[at].table_unavailable) break;  // nothing of this level or finer will come
    if (!levels_[at].table_known) {
      // A finer level's table is checked against this one, so it is refused until this one is
      // in: asking for it now would fetch its bytes again and again while this one is on its way.
      priority_scratch_.push_back({level_key, recordTableItem(level)});
      break;
    }
    const std::int64_t reach_x = frame.own_reach[at].x, reach_y = frame.own_reach[at].y;
    const int f = kDefaultFractionBits;
    Level& target = levels_[at];
    const Level& coarser = levels_[at - 1];
    for (std::uint32_t i = 0; i < target.records.size(); ++i) {
      Slot& slot = target.slots[i];
      const ChunkRecord& rec = target.records[i];
      slot.blocked = slot.state == ChunkState::kUnavailable || coarser.slots[rec.parent].blocked;
      if (slot.state != ChunkState::kMissing || slot.blocked) continue;
      const Vec3 c = regionCentre(frame, level, rec.region);
      const bool visible = !offScreen(frame, c, frame.own_reach[at]);
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
