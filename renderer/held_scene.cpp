#include "renderer/held_scene.h"

#include <algorithm>

namespace octopoint {

HeldScene::HeldScene(std::span<const SceneInstance> instances, std::size_t model_count)
    : instances_(instances.begin(), instances.end()), models_(model_count) {}

bool HeldScene::update(std::size_t m, const ProgressiveModel& model) {
  if (m >= models_.size()) return false;
  Held& held = models_[m];
  if (!held.known) {
    // Its colours into the scene's palette: each one the scene does not hold yet is added.
    const ModelView& base = model.baseModel();
    std::array<std::uint8_t, 256 * 3> palette = palette_;
    int count = palette_count_;
    for (int c = 0; c < base.paletteCount(); ++c) {
      const Rgb rgb = base.paletteColour(c);
      int found = 0;
      while (found < count && !(palette[3 * found] == rgb.r && palette[3 * found + 1] == rgb.g &&
                                palette[3 * found + 2] == rgb.b)) {
        ++found;
      }
      if (found == count) {
        if (count == 255) return false;  // index 255 marks an empty pixel
        palette[3 * found] = rgb.r;
        palette[3 * found + 1] = rgb.g;
        palette[3 * found + 2] = rgb.b;
        ++count;
      }
      held.map[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(found);
    }
    palette_ = palette;
    palette_count_ = count;
    held.known = true;
  }
  held.parts = assembleHeldParts(model);
  const std::span<const int> depths = held.parts.detailDepths();
  held.detail.assign(depths.begin(), depths.end());
  for (const std::unique_ptr<AssembledModel>& part : held.parts.parts) {
    // The leaves in the scene's palette, in place (the part's levels point into them).
    for (std::vector<std::uint8_t>& leaves : part->leaves)
      for (std::uint8_t& leaf : leaves) leaf = held.map[leaf];
    part->embedded.palette_rgb = palette_.data();
    part->embedded.palette_count = static_cast<std::uint16_t>(palette_count_);
    ModelIssue issue;
    part->view = ModelView::fromEmbedded(part->embedded, &issue);
  }
  // A part the palette made invalid (it cannot: only its indices changed) is left out.
  std::erase_if(held.parts.parts,
                [](const std::unique_ptr<AssembledModel>& part) { return !part->view; });
  return true;
}

void HeldScene::rebuild() {
  renderer_.reset();
  part_views_.clear();
  part_detail_.clear();
  std::vector<std::uint32_t> first_part(models_.size() + 1, 0);
  for (std::size_t m = 0; m < models_.size(); ++m) {
    first_part[m] = static_cast<std::uint32_t>(part_views_.size());
    for (const std::unique_ptr<AssembledModel>& part : models_[m].parts.parts) {
      part_views_.push_back(&*part->view);
      part_detail_.push_back(models_[m].detail);
    }
  }
  first_part[models_.size()] = static_cast<std::uint32_t>(part_views_.size());
  part_instances_.clear();
  first_.assign(instances_.size() + 1, 0);
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    first_[i] = static_cast<std::uint32_t>(part_instances_.size());
    const std::uint32_t m = instances_[i].model;
    if (m >= models_.size()) continue;
    for (std::uint32_t p = first_part[m]; p < first_part[m + 1]; ++p)
      part_instances_.push_back({p, instances_[i].transform});
  }
  first_[instances_.size()] = static_cast<std::uint32_t>(part_instances_.size());
  if (part_instances_.empty()) return;
  SceneError error;
  renderer_.emplace(part_views_, part_instances_, &error, part_detail_);
  if (error != SceneError::kNone) renderer_.reset();  // cannot be: the scene's own instances
}

void HeldScene::setVisibleSet(std::span<const std::uint32_t> ids) {
  visible_.assign(ids.begin(), ids.end());
  restricted_ = true;
}

bool HeldScene::draw(const PerspectiveView& view, FrameView& frame, SceneDrawStats* stats) {
  if (!renderer_) return false;
  if (restricted_) {
    // Each instance of the set as its parts' instances.
    part_visible_.clear();
    for (const std::uint32_t i : visible_) {
      if (i >= instances_.size()) continue;
      for (std::uint32_t k = first_[i]; k < first_[i + 1]; ++k) part_visible_.push_back(k);
    }
    renderer_->setVisibleSet(part_visible_);
  } else {
    renderer_->clearVisibleSet();
  }
  return renderer_->draw(view, frame, stats);
}

}  // namespace octopoint
