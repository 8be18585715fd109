#include "renderer/perspective_fetch.h"

#include <algorithm>

#include "renderer/perspective_detail.h"
#include "renderer/perspective_walk.h"

namespace octopoint {
namespace {

// The model-space centre (Q.24 cube edges about the cube's centre) of the region `code` at tree
// level `region_level`: each level's child k = (x << 2) | (y << 1) | z moves it by a quarter of
// that level's edge along each axis, + where the bit is set.
ModelPoint regionCentre(std::uint32_t code, int region_level) {
  ModelPoint centre{0, 0, 0};
  for (int level = 0; level < region_level; ++level) {
    const unsigned child = (code >> (3 * (region_level - 1 - level))) & 7u;
    const std::int64_t step = std::int64_t{1} << (kPerspectiveUnitBits - 2 - level);
    centre.x += (child & 4u) ? step : -step;
    centre.y += (child & 2u) ? step : -step;
    centre.z += (child & 1u) ? step : -step;
  }
  return centre;
}

}  // namespace

std::size_t PerspectiveFetchOrder::order(const ProgressiveModel& model, const PerspectiveView& view,
                                         bool include_invisible, std::span<FetchItem> out,
                                         std::size_t* total, std::span<std::uint32_t> nearest_out) {
  if (total != nullptr) *total = 0;
  scratch_.clear();
  // Detail by distance over the model's depths (the base's included), as many as a frame draws.
  const int levels = std::min(model.levelCount(), format::kMaxLevels);
  std::array<int, format::kMaxLevels> depths{};
  for (int level = 0; level < levels; ++level)
    depths[static_cast<std::size_t>(level)] = model.levelDepth(level);
  const PerspectiveDetail detail = perspectiveDetail(
      view, std::span<const int>(depths.data(), static_cast<std::size_t>(levels)));
  // The frustum's side planes x = +-slope_x * z, y = +-slope_y * z (Q1.30).
  const PerspectiveWalkTables tables =
      perspectiveWalkTables(view, depths[0], std::int64_t{1} << (view.fraction_bits - 2));
  blocked_[0].assign(1, 0);
  for (int level = 1; level < levels; ++level) {
    const auto at = static_cast<std::size_t>(level);
    const std::uint64_t level_key = std::uint64_t(level) << 59;
    if (!model.hasRecordTable(level)) {
      scratch_.push_back({level_key, model.recordTableItem(level)});
      break;  // the finer levels' tables come after it
    }
    const int region_level = model.head().levels[at].region_level;
    // The reach detail by distance gives a node of the region's level (half its edge, rotated,
    // and the rounding the walk's centres gather), plus the rounding of the walk's centre against
    // this exact one (half a unit per level and the root's unit): no node a frame draws in the
    // region is nearer, or reaches further aside, than this says, so a chunk left unfetched is
    // never one a frame of the view would draw (a partly held model draws the same frame).
    const std::int64_t reach =
        detail.reach[static_cast<std::size_t>(region_level)] + region_level + 1;
    const std::uint32_t count = model.chunkCount(level);
    blocked_[at].assign(count, 0);
    for (std::uint32_t i = 0; i < count; ++i) {
      const ChunkRecord& record = model.record(level, i);
      const ChunkState state = model.chunkState(level, i);
      const bool blocked =
          state == ChunkState::kUnavailable || blocked_[at - 1][record.parent] != 0;
      blocked_[at][i] = blocked ? 1 : 0;
      if (state != ChunkState::kMissing || blocked) continue;
      const CameraPoint c = toCameraSpace(view, regionCentre(record.region, region_level));
      const std::int64_t nearest = c.z - reach;
      if (detail.ask(nearest) < level) continue;  // coarser depths are fine enough all over it
      // Widened by the level's splat margin (its sample reach), as the walk's frustum test.
      const bool invisible = outsideFrustumSides(
          tables, c,
          reach + perspectiveSplatMargin(depths[at], model.head().levels[at].sample_reach),
          view.camera.near);
      if (invisible && !include_invisible) continue;
      // Nearest depth in 1/2^20 cube edge, 0 for a region the eye is in, at most 2^32 - 1 (the
      // eye lies within 128 cube edges: 2^31 of them).
      const auto near_key = static_cast<std::uint64_t>(
          std::clamp<std::int64_t>(nearest >> 4, 0, std::int64_t{0xFFFF'FFFF}));
      FetchItem item = model.chunkItem(level, i);
      item.visible = !invisible;
      scratch_.push_back(
          {(invisible ? std::uint64_t{1} << 63 : 0) | level_key | near_key << 27 | i, item});
    }
  }
  if (total != nullptr) *total = scratch_.size();
  const std::size_t count = std::min(out.size(), scratch_.size());
  std::partial_sort(scratch_.begin(), scratch_.begin() + static_cast<std::ptrdiff_t>(count),
                    scratch_.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  for (std::size_t i = 0; i < count; ++i) out[i] = scratch_[i].item;
  for (std::size_t i = 0; i < count && i < nearest_out.size(); ++i)
    nearest_out[i] = static_cast<std::uint32_t>(scratch_[i].key >> 27);  // the key's near_key bits
  return count;
}

}  // namespace octopoint
