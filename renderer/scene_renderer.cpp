#include "renderer/scene_renderer.h"

#include <algorithm>
#include <optional>

#include "renderer/scene_view.h"

namespace octopoint {

SceneRenderer::SceneRenderer(std::span<const ModelView* const> models,
                             std::span<const SceneInstance> instances, SceneError* error,
                             std::span<const std::vector<int>> detail_depths) {
  *error = SceneError::kNone;
  if (models.empty() || models.size() > kMaxSceneModels) {
    *error = SceneError::kNoModels;
  } else if (instances.empty() || instances.size() > kMaxSceneInstances) {
    *error = SceneError::kNoInstances;
  }
  for (std::size_t i = 0; i < instances.size() && *error == SceneError::kNone; ++i) {
    if (instances[i].model >= models.size()) {
      *error = SceneError::kBadModelIndex;
    } else {
      *error = checkTransform(instances[i].transform);
    }
  }
  if (*error != SceneError::kNone) return;
  models_.assign(models.begin(), models.end());
  detail_depths_.resize(models_.size());
  for (std::size_t m = 0; m < models_.size() && m < detail_depths.size(); ++m)
    detail_depths_[m] = detail_depths[m];
  for (std::size_t m = 0; m < models_.size(); ++m)
    renderers_.push_back(std::make_unique<PerspectiveRenderer>(*models_[m], detail_depths_[m]));
  instances_.assign(instances.begin(), instances.end());
  for (const SceneInstance& instance : instances_)
    largest_scale_ = std::max(largest_scale_, instance.transform.scale);
  depth_shift_ = sceneDepthShift(largest_scale_);
  order_.resize(instances_.size());
  valid_ = true;
}

SceneError SceneRenderer::place(std::size_t i, const InstanceTransform& transform) {
  if (i >= instances_.size()) return SceneError::kBadInstanceIndex;
  if (const SceneError error = checkTransform(transform); error != SceneError::kNone) return error;
  if (transform.scale > largest_scale_) return SceneError::kScaleAboveScene;
  instances_[i].transform = transform;
  return SceneError::kNone;
}

void SceneRenderer::setVisibleSet(std::span<const std::uint32_t> ids) {
  visible_ = ids;
  restricted_ = true;
}

void SceneRenderer::clearVisibleSet() {
  visible_ = {};
  restricted_ = false;
}

void SceneRenderer::setSubmittedMarks(std::span<std::uint8_t> marks) { marks_ = marks; }

std::size_t SceneRenderer::orderInView(const PerspectiveView& view, SceneDrawStats& counted) {
  // The frustum's side slopes for the instances' boxes (any depth's tables hold them).
  const PerspectiveWalkTables frustum = perspectiveWalkTables(view, 1, 0);
  std::size_t count = 0;
  const std::size_t candidates = restricted_ ? visible_.size() : instances_.size();
  for (std::size_t k = 0; k < candidates; ++k) {
    const std::size_t i = restricted_ ? visible_[k] : k;
    if (i >= instances_.size()) continue;
    if (count == order_.size()) break;  // a set with repeated ids: never more slots than instances
    const InstanceTransform& transform = instances_[i].transform;
    const std::optional<InstanceBox> box = instanceBox(view, transform);
    if (!box) {
      ++counted.beyond_reach;
    } else if (instanceOutsideFrustum(view, frustum, transform, *box)) {
      ++counted.outside_frustum;
    } else {
      const std::int64_t nearest = box->centre.z - box->reach;  // model units
      order_[count++] = {transform.scale >= 0 ? nearest * (std::int64_t{1} << transform.scale)
                                              : nearest >> -transform.scale,
                         static_cast<std::uint32_t>(i), *box};
    }
  }
  // Nearest first: what they draw hides the farther instances' subtrees from the culling.
  std::sort(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(count),
            [](const Slot& a, const Slot& b) {
              return a.nearest != b.nearest ? a.nearest < b.nearest : a.instance < b.instance;
            });
  return count;
}

bool SceneRenderer::layersOf(const PerspectiveView& view, const SceneInstance& instance,
                             PerspectiveView* model_view, PerspectiveLayers* layers) {
  if (instanceView(view, instance.transform, depth_shift_, model_view) != PerspectiveError::kNone)
    return false;  // turned, its eye lies beyond the camera's reach
  *layers = perspectiveLayers(*models_[instance.model], *model_view, 0,
                              renderers_[instance.model]->upperTreeIndexes(), tables_, coarser_,
                              detail_depths_[instance.model]);
  return true;
}

std::size_t SceneRenderer::setUp(const PerspectiveView& view, SceneDrawStats* stats) {
  if (!valid_) return 0;
  SceneDrawStats local;
  SceneDrawStats& counted = stats != nullptr ? *stats : local;
  const std::size_t count = orderInView(view, counted);
  std::size_t set_up = 0;
  for (std::size_t k = 0; k < count; ++k) {
    PerspectiveView model_view;
    PerspectiveLayers layers;
    set_up += layersOf(view, instances_[order_[k].instance], &model_view, &layers) ? 1 : 0;
  }
  return set_up;
}

bool SceneRenderer::draw(const PerspectiveView& view, FrameView& frame, SceneDrawStats* stats,
                         const std::atomic<bool>* abort) {
  if (!valid_) return false;
  SceneDrawStats local;
  SceneDrawStats& counted = stats != nullptr ? *stats : local;
  const std::size_t count = orderInView(view, counted);
  if (frame.width() != tiles_width_ || frame.height() != tiles_height_) {
    tiles_.assign(occlusionTileCount(frame.width(), frame.height(), kOcclusionTileShift), {});
    tiles_width_ = frame.width();
    tiles_height_ = frame.height();
  }
  // The pixel winners: the instances draw into a frame over the same words whose rectangle is
  // forgotten after each, so only what that instance may have written is compared with before.
  const std::size_t pixels =
      static_cast<std::size_t>(frame.width()) * static_cast<std::size_t>(frame.height());
  std::optional<RectFrame> winning;
  if (!winners_.empty() && winners_.size() == pixels && frame.payload() == PixelPayload::kColour) {
    winning.emplace(frame.pixelData(), frame.width(), frame.height());
    winning->forgetDrawn();
    before_.assign(frame.pixels().begin(), frame.pixels().end());
  }
  FrameView& target = winning ? *winning : frame;
  OcclusionTiles occlusion(target, tiles_, kOcclusionTileShift);
  occlusion.reset();
  for (std::size_t k = 0; k < count; ++k) {
    const SceneInstance& instance = instances_[order_[k].instance];
    if (frame.payload() == PixelPayload::kColour &&
        instanceHidden(view, instance.transform, order_[k].box,
                       depth_shift_ - instance.transform.scale, occlusion)) {
      ++counted.occluded;  // wholly behind nearer instances: not set up, not walked
      continue;
    }
    PerspectiveView model_view;
    PerspectiveLayers layers;
    if (!layersOf(view, instance, &model_view, &layers)) {
      ++counted.beyond_reach;
      continue;
    }
    if (layers.count == 0) continue;  // a model with no depth this build draws
    const std::uint64_t before = counted.points.leaves;
    if (!drawPerspectiveLayers(layers.layers(), &layers.detail, model_view, target, &occlusion,
                               &counted.points, nullptr, abort)) {
      return false;
    }
    ++counted.instances_drawn;
    const std::uint32_t drawn = order_[k].instance;
    if (winning) takeWinners(*winning, drawn);
    if (counted.points.leaves != before && drawn < marks_.size()) marks_[drawn] = 1;
  }
  return true;
}

}  // namespace octopoint
