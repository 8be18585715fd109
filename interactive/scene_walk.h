#pragma once
// Walk mode through a scene of many models (octopoint-view --city, docs/city.md): the walk frames
// of the dual-resolution render threads drawn by SceneRenderer (renderer/scene_renderer.h), and
// the eye colliding with the scene's instances (renderer/scene_collision.h). The scene has no
// orbit view: the config it makes stays in walk mode.

#include <array>
#include <memory>
#include <span>

#include "octopoint/interactive.h"
#include "octopoint/scene.h"
#include "renderer/scene_cells.h"
#include "renderer/scene_collision.h"
#include "renderer/scene_renderer.h"

namespace octopoint {

class SceneWalk {
 public:
  // The models (each must outlive this) and the instances; `*error` says why a scene is refused.
  // With `cells` (validated for these instances; must outlive this), each frame draws only what
  // the eye's cell sees (renderer/scene_cells.h).
  SceneWalk(std::span<const ModelView* const> models, std::span<const SceneInstance> instances,
            SceneError* error, const CellTable* cells = nullptr);
  SceneWalk(const SceneWalk&) = delete;
  SceneWalk& operator=(const SceneWalk&) = delete;

  // `config` made to walk this scene (this must outlive the renderer built from it): its walk
  // frames drawn by one SceneRenderer per render thread (the coarse thread's each instance one
  // stored depth coarser), its eye colliding with the instances when config.walk_radius is set
  // (Q.24 scene edges), no orbit view. initial_view.walk is set; the walker is the caller's.
  InteractiveConfig configure(InteractiveConfig config);

  // Orbit views, which a scene does not have: an empty frame (the renderer never asks for one
  // in walk_only mode, but its constructor takes a drawer).
  static ViewDrawFunction noOrbitView();

  const SceneCollision& collision() const { return collision_; }
  // The scene's first model (a scene file's models share one palette: tools/scene_file.h).
  const ModelView& firstModel() const { return *first_model_; }

 private:
  bool draw(FrameSource source, const PerspectiveView& view, Framebuffer& frame,
            const std::atomic<bool>* abort, int* finest_depth);

  std::array<std::unique_ptr<SceneRenderer>, 2> renderers_;  // coarse, fine: one per thread
  std::array<std::unique_ptr<SceneCells>, 2> cells_;         // theirs, with a cell table
  SceneCollision collision_;
  int finest_depth_ = 0;  // the deepest level of any model
  const ModelView* first_model_ = nullptr;
};

}  // namespace octopoint
