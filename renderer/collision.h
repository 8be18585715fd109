#pragma once
// Collision (docs/perspective.md, "Collision"): does a sphere meet any occupied voxel of a model,
// and where is the ground under a point. Integer only, in the perspective camera's units: Q.24
// cube edges about the model cube's centre (ModelPoint, renderer/perspective.h), the model's axes
// (x right, y down, z away). A voxel of depth d at index (i, j, k) is the closed cube
// [i * 2^(24-d) - 2^23, (i + 1) * 2^(24-d) - 2^23] along x, and so on; the voxels are exact in
// these units at every depth up to format::kMaxDepth (an edge of at least 2^8 units).
//
// A query walks the level's octree from the root through its upper-tree index
// (renderer/upper_tree_index.h: random access down to the leaves' great-grandparents), entering
// only the nodes whose cube the sphere meets, then the few bytes below them in stream order. Its
// cost is bounded by the nodes the sphere's box meets at each level, not by the model; nothing is
// allocated per query (the index is built once, on the heap, when the CollisionModel is made).

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "octopoint/fixed.h"
#include "octopoint/model.h"
#include "octopoint/scene.h"
#include "renderer/perspective.h"
#include "renderer/upper_tree_index.h"

namespace octopoint {

// A sphere's radius is 1 .. one cube edge (Q.24): its squared distances fit 64 bits with room.
inline constexpr std::int64_t kMaxCollisionRadius = kPerspectiveUnit;

struct CollisionSphere {
  ModelPoint centre;        // Q.24 cube edges about the cube's centre
  std::int64_t radius = 0;  // Q.24 cube edges, 1 .. kMaxCollisionRadius
};

// How much a query read: the nodes and leaves whose cube it tested.
struct CollisionStats {
  std::uint64_t boxes_tested = 0;
  std::uint64_t instances_tested = 0;  // instances whose model a scene's query entered
};

// One level of a validated model, ready for queries: the level's bytes (owned by the model, which
// must outlive this) and its upper-tree index (owned here).
class CollisionModel {
 public:
  // The level of `depth` of `model`, or its finest level when `depth` is 0; nullopt when the model
  // has no level of that depth or the level is too large to index (offsets past 32 bits).
  static std::optional<CollisionModel> of(const ModelView& model, int depth = 0);
  // A level that is valid (validated by ModelView, or made by a test's encoder).
  static std::optional<CollisionModel> ofLevel(const LevelView& level);

  int depth() const { return level_.depth; }

  // Whether the open sphere meets a closed occupied voxel: the squared distance from the centre
  // to the voxel's cube is below radius^2 (a sphere that only touches a voxel does not meet it).
  // Any centre (a centre far outside the cube meets nothing); a radius outside
  // 1 .. kMaxCollisionRadius meets nothing either.
  bool meets(const CollisionSphere& sphere, CollisionStats* stats = nullptr) const;

  // The ground under `point`: the top face (the smallest y: y points down) of the occupied voxels
  // that overlap the vertical column |x - point.x| < half_width, |z - point.z| < half_width, from
  // point.y down to point.y + reach (closed); nullopt when none does. half_width and reach:
  // 1 .. 2^30.
  std::optional<std::int64_t> groundBelow(const ModelPoint& point, std::int64_t half_width,
                                          std::int64_t reach) const;

 private:
  CollisionModel(const LevelView& level, std::vector<UpperTreeNode> storage, int bottom)
      : level_(level), index_(std::move(storage)), bottom_(bottom) {}
  // From the root; true when the visitor stopped the walk.
  template <typename Visitor>
  bool walk(Visitor& visitor) const;
  template <typename Visitor>
  bool walkIndexed(Visitor& visitor, std::size_t entry, int tree_level, const ModelPoint& lo) const;
  template <typename Visitor>
  bool walkStream(Visitor& visitor, const std::uint8_t*& cursor, int tree_level,
                  const ModelPoint& lo) const;
  void skipStream(const std::uint8_t*& cursor, int tree_level) const;

  LevelView level_;
  std::vector<UpperTreeNode> index_;  // the upper-tree index: root first, level by level
  int bottom_ = 0;                    // its deepest tree level
};

// An instance of a model placed for collision by the scene's own transform (octopoint/scene.h):
// world = at + 2^scale * Ry(turn) * model, Ry turning +z towards +x (the walk's forward, sin yaw,
// 0, cos yaw) about the vertical (y) axis; Q.24 units both sides (the world's: scene edges). One
// placement type for drawing and colliding, so that a scene's walk collides with its instances.
struct CollisionInstance {
  const CollisionModel* model = nullptr;
  InstanceTransform transform;
};

// Whether the sphere (world units) meets any instance. The sphere is carried into each instance's
// model units, padded by the rotation's and the scale's rounding (at most 3 units), so the answer
// errs towards "meets" by that much and never the other way. An instance whose transform
// checkTransform refuses (a scale outside -8..8, a coordinate past 2^44) meets nothing.
bool sphereMeets(std::span<const CollisionInstance> instances, const CollisionSphere& sphere,
                 CollisionStats* stats = nullptr);
// What a walk collides with (renderer/collision_move.h): whether a sphere meets occupied space.
class CollisionWorld {
 public:
  virtual ~CollisionWorld() = default;
  virtual bool meets(const CollisionSphere& sphere) const = 0;
};

// A few instances, each tested in turn (a single model: one instance at the identity). A scene of
// many: renderer/scene_collision.h, which finds the nearby ones first.
class CollisionInstances final : public CollisionWorld {
 public:
  explicit CollisionInstances(std::span<const CollisionInstance> instances)
      : instances_(instances) {}
  bool meets(const CollisionSphere& sphere) const override {
    return sphereMeets(instances_, sphere);
  }

 private:
  std::span<const CollisionInstance> instances_;
};

// One whole model at the identity, owned: walk mode's world for the viewer's model (the same
// answers as CollisionInstances of that one instance).
class ModelCollision final : public CollisionWorld {
 public:
  explicit ModelCollision(CollisionModel model) : model_(std::move(model)) {}
  ModelCollision(const ModelCollision&) = delete;
  ModelCollision& operator=(const ModelCollision&) = delete;
  bool meets(const CollisionSphere& sphere) const override {
    const CollisionInstance instance{&model_, {}};
    return sphereMeets({&instance, 1}, sphere);
  }

 private:
  CollisionModel model_;
};

// The same for one instance.
bool instanceMeets(const CollisionInstance& instance, const CollisionSphere& sphere,
                   CollisionStats* stats = nullptr);

// How far from an instance's `at` (world units) its model's turned cube, padded by the carried
// centre's rounding, may reach: `across` on x and z (sqrt(2)/2 of the cube's edge and a little
// more), `up` on y (half the edge and a little more). A sphere whose centre lies farther than
// its radius beyond this box meets nothing of the instance (scene_collision.h finds instances by
// it).
struct InstanceReach {
  std::int64_t across = 0;
  std::int64_t up = 0;
};
InstanceReach instanceReach(int scale);

// The ground under `point` over all instances (CollisionModel::groundBelow in world units; a
// turned instance's column is the world column turned, the same half-width).
std::optional<std::int64_t> groundBelow(std::span<const CollisionInstance> instances,
                                        const ModelPoint& point, std::int64_t half_width,
                                        std::int64_t reach);

}  // namespace octopoint
