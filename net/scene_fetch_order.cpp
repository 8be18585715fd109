#include "net/scene_fetch_order.h"

#include <algorithm>

#include "renderer/perspective_walk.h"
#include "renderer/scene_view.h"

namespace octopoint::net {
namespace {

// Items taken from each instance's order: a few requests' worth, recomputed for every request.
constexpr std::size_t kPerInstance = 512;
// The key: rank (2 bits), level (4 bits), urgency (40 bits), place in the instance's order (18).
constexpr int kRankShift = 62, kLevelShift = 58, kUrgencyShift = 18;
constexpr std::uint64_t kUrgencyMask = (std::uint64_t{1} << 40) - 1;
constexpr std::uint64_t kPlaceMask = (std::uint64_t{1} << kUrgencyShift) - 1;

std::uint64_t itemId(std::uint32_t model, bool head, const FetchItem& item) {
  if (head) return std::uint64_t{model} << 40 | std::uint64_t{1} << 38;
  return std::uint64_t{model} << 40 |
         (item.kind == FetchItem::Kind::kRecordTable ? std::uint64_t{1} << 39 : 0) |
         std::uint64_t(item.level) << 32 | item.index;
}

}  // namespace

void SceneFetchOrder::want(const SceneFetchEntry& entry) {
  const auto [found, added] =
      at_.try_emplace(itemId(entry.model, entry.head, entry.item), wanted_.size());
  if (added) {
    wanted_.push_back(entry);
  } else if (entry.key < wanted_[found->second].key) {
    wanted_[found->second].key = entry.key;
  }
}

void SceneFetchOrder::addInstance(std::span<ProgressiveModel* const> models,
                                  const SceneInstance& instance, const SceneFetchTier& tier,
                                  std::uint64_t rank) {
  const PerspectiveView& view = tier.view;
  const std::optional<InstanceBox> box = instanceBox(view, instance.transform);
  if (!box) return;  // beyond the draw distance: never drawn from here
  if (!tier.include_invisible) {
    // The frustum's side slopes (any depth's tables hold them), as SceneRenderer tests.
    const PerspectiveWalkTables frustum = perspectiveWalkTables(view, 1, 0);
    if (instanceOutsideFrustum(view, frustum, instance.transform, *box)) return;
  }
  // A region's size on screen, inverted: its nearest depth (1/2^20 model cube edge) times 2^r for
  // an edge of 2^-r cube edges (clamped to 40 bits).
  const auto key = [&](int level, std::uint64_t nearest, int region_level, std::size_t place) {
    const std::uint64_t far = std::min(nearest << region_level, kUrgencyMask);
    return rank | std::uint64_t(level) << kLevelShift | far << kUrgencyShift |
           std::min<std::uint64_t>(place, kPlaceMask);
  };
  // The box's nearest camera-space depth (Q.24 model cube edges; 0 when the eye is in it).
  const auto box_nearest = static_cast<std::uint64_t>(
      std::clamp<std::int64_t>((box->centre.z - box->reach) >> 4, 0, 0xFFFF'FFFF));
  ProgressiveModel* model = models[instance.model];
  if (model == nullptr) {
    want({instance.model, true, {}, key(0, box_nearest, 0, 0)});
    return;
  }
  PerspectiveView model_view;
  if (instanceView(view, instance.transform, kPerspectiveDepthShift, &model_view) !=
      PerspectiveError::kNone) {
    return;
  }
  items_.resize(kPerInstance);
  nearest_.resize(kPerInstance);
  const std::size_t count = perspective_order_.order(*model, model_view, tier.include_invisible,
                                                     items_, nullptr, nearest_);
  for (std::size_t k = 0; k < count; ++k) {
    const FetchItem& item = items_[k];
    const int region_level =
        model->head().levels[static_cast<std::size_t>(item.level)].region_level;
    const bool table = item.kind == FetchItem::Kind::kRecordTable;
    want({instance.model, false, item,
          key(item.level, table ? box_nearest : nearest_[k], region_level, k)});
  }
}

void SceneFetchOrder::order(std::span<ProgressiveModel* const> models,
                            std::span<const SceneInstance> instances,
                            std::span<const SceneFetchTier> tiers,
                            std::vector<SceneFetchEntry>& out) {
  wanted_.clear();
  at_.clear();
  for (std::size_t t = 0; t < tiers.size(); ++t) {
    const SceneFetchTier& tier = tiers[t];
    const std::uint64_t rank = std::uint64_t{std::min<std::size_t>(t, 3)} << kRankShift;
    const std::size_t count = tier.every_instance ? instances.size() : tier.instances.size();
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = tier.every_instance ? k : tier.instances[k];
      if (i >= instances.size() || instances[i].model >= models.size()) continue;
      addInstance(models, instances[i], tier, rank);
    }
  }
  std::sort(wanted_.begin(), wanted_.end(),
            [](const SceneFetchEntry& a, const SceneFetchEntry& b) { return a.key < b.key; });
  out = wanted_;
}

}  // namespace octopoint::net
