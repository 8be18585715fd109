// ProgressiveModel: taking record tables and chunks, and joining each chunk to the coarser stream
// it refines. Drawing and fetch priorities are in progressive_draw.cpp.
#include <algorithm>
#include <cassert>

#include "octopoint/progressive.h"

namespace octopoint {

std::optional<ProgressiveModel> ProgressiveModel::fromHead(std::span<const std::uint8_t> bytes,
                                                           ChunkedIssue* issue) {
  std::optional<ChunkedHead> head = parseChunkedHead(bytes, issue);
  if (!head) return std::nullopt;
  ProgressiveModel model;
  model.head_ = std::move(*head);
  model.base_palette_.assign(model.head_.palette_rgb.begin(), model.head_.palette_rgb.end());
  const EmbeddedLevel base_level{
      static_cast<std::uint8_t>(model.head_.levels[0].depth), model.head_.base_nodes.data(),
      static_cast<std::uint32_t>(model.head_.base_nodes.size()), model.head_.base_leaves.data(),
      static_cast<std::uint32_t>(model.head_.base_leaves.size())};
  // Field by field as octopoint/model.h (format version 2, no normals).
  const EmbeddedModel base{"chunked model base",
                           format::kVersion2,
                           0,
                           model.head_.cube_edge_pm,
                           static_cast<std::uint16_t>(model.head_.palette_count),
                           model.base_palette_.data(),
                           0,
                           nullptr,
                           1,
                           &base_level};
  ModelIssue base_issue;
  model.base_view_ = ModelView::fromEmbedded(base, &base_issue);
  assert(model.base_view_);  // parseChunkedHead validated the same stream

  Level& level0 = model.levels_[0];
  level0.table_known = true;
  level0.records.push_back(
      ChunkRecord{0, 0, static_cast<std::uint32_t>(model.head_.base_leaves.size()), 0, 0, 0, 0});
  level0.slots.resize(1);
  Slot& base_slot = level0.slots[0];
  base_slot.state = ChunkState::kHeld;
  base_slot.nodes = model.head_.base_nodes;
  base_slot.leaves = model.head_.base_leaves;
  model.tables_.points[0] = model.head_.base_leaves.size();
  model.drawable_.assign(1, 1);
  model.own_frame_.drawable_.reserve(1);
  model.priority_scratch_.reserve(
      chunked::kMaxChunkedLevels);  // tables asked for before any is known
  return model;
}

FetchItem ProgressiveModel::recordTableItem(int level) const {
  const ChunkedLevel& info = head_.levels[static_cast<std::size_t>(level)];
  return {FetchItem::Kind::kRecordTable,
          level,
          0,
          info.table_offset,
          chunked::kRecordBytes * std::uint64_t{info.chunk_count},
          true};
}

std::uint32_t ProgressiveModel::chunkCount(int level) const {
  return static_cast<std::uint32_t>(levels_[static_cast<std::size_t>(level)].records.size());
}

const ChunkRecord& ProgressiveModel::record(int level, std::uint32_t index) const {
  return levels_[static_cast<std::size_t>(level)].records[index];
}

ChunkState ProgressiveModel::chunkState(int level, std::uint32_t index) const {
  return levels_[static_cast<std::size_t>(level)].slots[index].state;
}

FetchItem ProgressiveModel::chunkItem(int level, std::uint32_t index) const {
  const ChunkRecord& r = record(level, index);
  return {FetchItem::Kind::kChunk, level, index, r.offset, r.bytes, true};
}

ChunkedIssue ProgressiveModel::accept(const FetchItem& item, std::span<const std::uint8_t> bytes) {
  if (item.level < 1 || item.level >= head_.level_count)
    return {ChunkedError::kUnknownChunk, item.offset, item.level};
  if (item.kind == FetchItem::Kind::kRecordTable) {
    ChunkedIssue issue;
    if (hasRecordTable(item.level)) return {};
    if (!hasRecordTable(item.level - 1))
      return {ChunkedError::kTableOutOfOrder, item.offset, item.level};
    if (!acceptRecordTable(item.level, bytes, &issue)) return issue;
    return {};
  }
  return acceptChunk(item.level, item.index, bytes);
}

bool ProgressiveModel::acceptRecordTable(int level, std::span<const std::uint8_t> bytes,
                                         ChunkedIssue* issue) {
  Level& coarser = levels_[static_cast<std::size_t>(level - 1)];
  const std::span<const ChunkRecord> coarser_records =
      level == 1 ? std::span<const ChunkRecord>() : std::span<const ChunkRecord>(coarser.records);
  std::optional<std::vector<ChunkRecord>> records =
      parseRecordTable(bytes, head_, level, coarser_records, issue);
  if (!records) return false;
  Level& target = levels_[static_cast<std::size_t>(level)];
  target.records = std::move(*records);
  target.slots.resize(target.records.size());
  target.table_known = true;
  // Published to snapshots from here: the records, slots and the coarser slots' child ranges
  // below are not written again.
  tables_.known_levels = level + 1;
  tables_.first_chunk[static_cast<std::size_t>(level)] =
      static_cast<std::uint32_t>(drawable_.size());
  std::uint64_t points = 0;
  for (const ChunkRecord& r : target.records) points += r.points;
  tables_.points[static_cast<std::size_t>(level)] = points;
  drawable_.resize(drawable_.size() + target.records.size(), 0);
  own_frame_.drawable_.reserve(drawable_.size());
  if (own_frame_.kept_.size() < target.records.size())
    own_frame_.kept_.resize(target.records.size());
  own_frame_.budget_order_.reserve(target.records.size());
  for (Slot& parent : coarser.slots) parent.child_begin = parent.child_end = 0;
  for (std::uint32_t i = 0; i < target.records.size(); ++i) {
    Slot& parent = coarser.slots[target.records[i].parent];
    if (parent.child_begin == parent.child_end) parent.child_begin = i;
    parent.child_end = i + 1;
  }
  std::size_t total = 0;
  for (const Level& l : levels_) total += l.records.size();
  priority_scratch_.reserve(total +
                            chunked::kMaxChunkedLevels);  // so that fetchPriority never allocates
  for (std::uint32_t p = 0; p < coarser.slots.size(); ++p) {
    if (coarser.slots[p].state == ChunkState::kHeld) linkChildren(level - 1, p);
  }
  return true;
}

ChunkedIssue ProgressiveModel::acceptChunk(int level, std::uint32_t index,
                                           std::span<const std::uint8_t> bytes) {
  Level& target = levels_[static_cast<std::size_t>(level)];
  if (!target.table_known || index >= target.records.size())
    return {ChunkedError::kUnknownChunk, 0, level};
  Slot& slot = target.slots[index];
  if (slot.state != ChunkState::kMissing) return {};  // already have it, or gave up on it
  const ChunkRecord& rec = target.records[index];
  ChunkedIssue issue =
      validateChunk(bytes, rec, refinementLevels(head_, level), head_.palette_count);
  if (issue.error != ChunkedError::kNone) {
    if (++slot.refusals >= kMaxChunkAttempts) slot.state = ChunkState::kUnavailable;
    issue.offset += rec.offset;
    issue.level = level;
    return issue;
  }
  slot.raw.assign(bytes.begin(), bytes.end());
  slot.state = ChunkState::kWaiting;
  const Slot& parent = levels_[static_cast<std::size_t>(level - 1)].slots[rec.parent];
  if (parent.state == ChunkState::kHeld && slot.range_known) becomeHeld(level, index);
  return {};
}

// Called for a held chunk once the next level's table is known: finds each finer region's part of
// its stream, checks them against that table, and joins the finer chunks already waiting.
void ProgressiveModel::linkChildren(int level, std::uint32_t index) {
  if (level + 1 >= head_.level_count) return;
  Level& finer = levels_[static_cast<std::size_t>(level + 1)];
  if (!finer.table_known) return;
  Slot& slot = levels_[static_cast<std::size_t>(level)].slots[index];
  const ChunkedLevel& info = head_.levels[static_cast<std::size_t>(level)];
  const int stream_levels = info.depth - info.region_level;
  const int level_below =
      head_.levels[static_cast<std::size_t>(level + 1)].region_level - info.region_level;
  const std::uint32_t region = levels_[static_cast<std::size_t>(level)].records[index].region;
  std::uint32_t next = slot.child_begin;
  bool agrees = true;
  forEachSubregion(slot.nodes, slot.leaves, stream_levels, level_below,
                   [&](std::uint32_t code, const StreamRange& range) {
                     if (!agrees) return;
                     const std::uint32_t child_region = region << (3 * level_below) | code;
                     if (next == slot.child_end || finer.records[next].region != child_region ||
                         finer.records[next].coarse_points != range.leafCount()) {
                       agrees = false;
                       return;
                     }
                     finer.slots[next].in_parent = range;
                     finer.slots[next].range_known = true;
                     ++next;
                   });
  if (!agrees || next != slot.child_end) {
    // The chunk's voxels are not the ones the directory says its finer chunks refine: the file is
    // inconsistent, so no amount of refetching helps. Drop it; its region stays coarser.
    // Its stream is kept: a frame drawing an earlier snapshot may be reading it.
    for (std::uint32_t c = slot.child_begin; c < slot.child_end; ++c)
      finer.slots[c].range_known = false;
    slot.state = ChunkState::kUnavailable;
    setDrawable(level, index, false);
    return;
  }
  for (std::uint32_t c = slot.child_begin; c < slot.child_end; ++c) {
    if (finer.slots[c].state == ChunkState::kWaiting) becomeHeld(level + 1, c);
  }
}

// A waiting chunk whose coarser chunk is held: builds its region's stream and joins its own
// waiting finer chunks.
void ProgressiveModel::becomeHeld(int level, std::uint32_t index) {
  Level& target = levels_[static_cast<std::size_t>(level)];
  Slot& slot = target.slots[index];
  const ChunkRecord& rec = target.records[index];
  const Slot& parent = levels_[static_cast<std::size_t>(level - 1)].slots[rec.parent];
  assert(slot.state == ChunkState::kWaiting && parent.state == ChunkState::kHeld &&
         slot.range_known);
  const StreamRange& range = slot.in_parent;
  const int coarse_levels = head_.levels[static_cast<std::size_t>(level - 1)].depth -
                            head_.levels[static_cast<std::size_t>(level)].region_level;
  const std::span<const std::uint8_t> coarse(parent.nodes.data() + range.node_begin,
                                             range.node_end - range.node_begin);
  refineRegion(coarse, coarse_levels, slot.raw, rec.points, refinementLevels(head_, level),
               slot.nodes, slot.leaves);
  slot.raw = {};
  slot.nodes.shrink_to_fit();
  slot.state = ChunkState::kHeld;
  setDrawable(level, index, true);  // its stream is not written again
  linkChildren(level, index);
}

void ProgressiveModel::setDrawable(int level, std::uint32_t index, bool drawable) {
  drawable_[tables_.first_chunk[static_cast<std::size_t>(level)] + index] = drawable ? 1 : 0;
}

void ProgressiveModel::snapshot(ProgressiveFrame& frame) const {
  frame.tables_ = tables_;
  frame.drawable_.assign(drawable_.begin(), drawable_.end());
  // The point budget's per-frame scratch: one entry per chunk of the largest known level.
  std::size_t most = 0;
  for (int level = 1; level < tables_.known_levels; ++level)
    most = std::max<std::size_t>(most, chunkCount(level));
  if (frame.kept_.size() < most) frame.kept_.resize(most);
  frame.budget_order_.reserve(most);
}

std::uint64_t ProgressiveModel::acceptBytes(std::uint64_t file_offset,
                                            std::span<const std::uint8_t> bytes,
                                            ChunkedIssue* issue) {
  const std::uint64_t end = file_offset + bytes.size();
  const auto whole = [&](std::uint64_t at, std::uint64_t size) {
    return at >= file_offset && at + size <= end;
  };
  const auto piece = [&](std::uint64_t at, std::uint64_t size) {
    return bytes.subspan(static_cast<std::size_t>(at - file_offset),
                         static_cast<std::size_t>(size));
  };
  if (issue != nullptr) *issue = {};
  std::uint64_t taken = file_offset;
  const auto take = [&](const FetchItem& item) {
    const ChunkedIssue result = accept(item, piece(item.offset, item.bytes));
    if (result.error != ChunkedError::kNone) {
      if (issue != nullptr && issue->error == ChunkedError::kNone) *issue = result;
      return;
    }
    taken = std::max(taken, item.offset + item.bytes);
  };
  for (int level = 1; level < head_.level_count; ++level) {
    const FetchItem table = recordTableItem(level);
    if (!hasRecordTable(level) && whole(table.offset, table.bytes)) take(table);
  }
  for (int level = 1; level < head_.level_count; ++level) {
    const std::vector<ChunkRecord>& records = levels_[static_cast<std::size_t>(level)].records;
    auto it =
        std::lower_bound(records.begin(), records.end(), file_offset,
                         [](const ChunkRecord& r, std::uint64_t at) { return r.offset < at; });
    for (; it != records.end() && it->offset + it->bytes <= end; ++it) {
      take(chunkItem(level, static_cast<std::uint32_t>(it - records.begin())));
    }
  }
  return taken;
}

std::uint64_t ProgressiveModel::heldBytes() const {
  std::uint64_t total = head_.base_nodes.size() + head_.base_leaves.size();
  for (const Level& level : levels_) {
    total += level.records.capacity() * sizeof(ChunkRecord) + level.slots.capacity() * sizeof(Slot);
    for (const Slot& slot : level.slots)
      total += slot.raw.capacity() + slot.nodes.capacity() + slot.leaves.capacity();
  }
  return total;
}

std::uint32_t ProgressiveModel::chunksIn(ChunkState state) const {
  std::uint32_t count = 0;
  for (int level = 1; level < head_.level_count; ++level) {
    for (const Slot& slot : levels_[static_cast<std::size_t>(level)].slots)
      count += slot.state == state;
  }
  return count;
}

std::optional<ProgressiveModel> progressiveModelFromPrefix(std::span<const std::uint8_t> bytes,
                                                           ChunkedIssue* issue) {
  std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(bytes, issue);
  if (!model) return std::nullopt;
  // Where the reading stopped is not needed: `issue` says why, and the model keeps what came
  // before.
  static_cast<void>(model->acceptBytes(0, bytes, issue));
  return model;
}

}  // namespace octopoint
