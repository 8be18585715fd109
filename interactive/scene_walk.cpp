#include "interactive/scene_walk.h"

#include <algorithm>

namespace octopoint {

SceneWalk::SceneWalk(std::span<const ModelView* const> models,
                     std::span<const SceneInstance> instances, SceneError* error,
                     const CellTable* cells)
    : collision_(models, instances, error), first_model_(models.empty() ? nullptr : models[0]) {
  if (*error != SceneError::kNone) return;
  for (std::size_t i = 0; i < renderers_.size(); ++i) {
    renderers_[i] = std::make_unique<SceneRenderer>(models, instances, error);
    if (*error != SceneError::kNone) return;
    if (cells != nullptr) cells_[i] = std::make_unique<SceneCells>(*cells);
  }
  renderers_[0]->setCoarser(1);  // the coarse thread's frames, as a model's walk draws them
  for (const ModelView* model : models)
    finest_depth_ = std::max(finest_depth_, model->finestLevel().depth);
}

InteractiveConfig SceneWalk::configure(InteractiveConfig config) {
  config.walk_draw = [this](FrameSource source, const PerspectiveView& view, Framebuffer& frame,
                            const std::atomic<bool>* abort, int* finest_depth) {
    return draw(source, view, frame, abort, finest_depth);
  };
  config.walk_world = &collision_;
  config.walk_only = true;
  config.initial_view.walk = true;
  return config;
}

ViewDrawFunction SceneWalk::noOrbitView() {
  return [](FrameSource, const Camera&, Framebuffer&, const std::atomic<bool>*, int* depth) {
    *depth = 0;
    return true;
  };
}

bool SceneWalk::draw(FrameSource source, const PerspectiveView& view, Framebuffer& frame,
                     const std::atomic<bool>* abort, int* finest_depth) {
  // Each render thread draws with its own renderer: its order, tables and tiles are its own.
  const bool coarse = source == FrameSource::kCoarse;
  SceneRenderer& renderer = *renderers_[coarse ? 0 : 1];
  if (const std::unique_ptr<SceneCells>& cells = cells_[coarse ? 0 : 1]) {
    cells->apply(renderer, view.camera.eye);
  }
  if (!renderer.draw(view, frame, nullptr, abort)) {
    *finest_depth = 0;
    return abort == nullptr || !abort->load();  // a refused scene draws nothing, not aborted
  }
  *finest_depth = coarse ? std::max(1, finest_depth_ - 1) : finest_depth_;
  return true;
}

}  // namespace octopoint
