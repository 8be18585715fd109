#pragma once
// Collision against a scene of many models (docs/city.md, "Collision"): the walk of
// renderer/collision_move.h among a city's instances, as they are drawn (the same
// InstanceTransform: turned, scaled, moved). A sphere is tested only against the instances whose
// box (instanceReach, renderer/collision.h) lies near it, found through a coarse grid over the
// ground plane (x, z) built once with the scene: cells a power of two at least as wide as the
// widest instance box, so each instance is listed in at most 2 x 2 cells, and at most 4 cells per
// instance (or 4,096) in all. A query looks at the few cells its sphere's box covers: its cost
// follows the instances near the eye, not the scene; it allocates nothing. Integer only.
// Instances that move (containers, cranes: place) leave the grid and are tested by every query:
// a query's cost grows by the moving ones, which are few; the grid is never rebuilt.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/scene.h"
#include "renderer/collision.h"

namespace octopoint {

class SceneCollision final : public CollisionWorld {
 public:
  // The models (each must outlive this) at their finest levels, and the instances (copied).
  // `*error` says why a scene is refused (as SceneRenderer refuses it); `unindexedModel()` names
  // a model whose finest level is too large to index (then nothing meets).
  SceneCollision(std::span<const ModelView* const> models, std::span<const SceneInstance> instances,
                 SceneError* error);

  // The first model whose finest level could not be indexed, if any.
  std::optional<std::size_t> unindexedModel() const { return unindexed_model_; }

  // Whether the sphere (Q.24 scene edges) meets any instance: sphereMeets over the instances near
  // it (renderer/collision.h: never missed, met at most the rounding's pad early).
  bool meets(const CollisionSphere& sphere) const override { return meets(sphere, nullptr); }
  bool meets(const CollisionSphere& sphere, CollisionStats* stats) const;

  // Moves instance `i` for collision, as SceneRenderer::place moves it for drawing: later queries
  // meet it there. Refused (the instance left where it was) for an unknown instance, a bad
  // transform (checkTransform) or a scene that was refused. Allocates nothing.
  SceneError place(std::size_t i, const InstanceTransform& transform);

  std::span<const CollisionInstance> instances() const { return instances_; }
  int cellShift() const { return cell_shift_; }  // the grid's cell edge: 2^cellShift Q.24 units

 private:
  std::vector<CollisionModel> models_;
  std::vector<CollisionInstance> instances_;
  // The grid: cells_x_ * cells_z_ cells from (min_x_, min_z_), each a run of cell_items_ from
  // cell_start_[cell] to cell_start_[cell + 1]: the instances whose box overlaps the cell.
  std::int64_t min_x_ = 0, min_z_ = 0;
  std::int64_t cells_x_ = 0, cells_z_ = 0;
  int cell_shift_ = 0;
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> cell_items_;
  // Per instance, 1 once it was moved: the grid's entries for it are passed over, and it is in
  // moving_ (sized with the scene), tested by every query.
  std::vector<std::uint8_t> moved_;
  std::vector<std::uint32_t> moving_;
  std::optional<std::size_t> unindexed_model_;
  bool valid_ = false;
};

}  // namespace octopoint
