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
#include <vector>

#include "octopoint/fixed.h"
#include "octopoint/model.h"
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

// Where an instance of a model stands for collision: world =
// translation + 2^scale_log2 * Ry(yaw) * model, where Ry turns +z towards +x by yaw (the walk's
// forward, sin yaw, 0, cos yaw) about the vertical (y) axis. Q.24 units both sides. (The scenes
// of many models, octopoint/scene.h, place instances by an InstanceTransform of their own: turning
// one into the other, so that a scene's walk collides with its instances, is still to be done.)
struct CollisionTransform {
  ModelPoint translation{0, 0, 0};
  Angle yaw;
  int scale_log2 = 0;  // kMinInstanceScaleLog2 .. kMaxInstanceScaleLog2
  bool operator==(const CollisionTransform&) const = default;
};

inline constexpr int kMinInstanceScaleLog2 = -8;
inline constexpr int kMaxInstanceScaleLog2 = 6;

struct CollisionInstance {
  const CollisionModel* model = nullptr;
  CollisionTransform transform;
};

// Whether the sphere (world units) meets any instance. The sphere is carried into each instance's
// model units, padded by the rotation's and the scale's rounding (at most 3 units), so the answer
// errs towards "meets" by that much and never the other way. An instance with a scale outside the
// range meets nothing.
bool sphereMeets(std::span<const CollisionInstance> instances, const CollisionSphere& sphere,
                 CollisionStats* stats = nullptr);

// The ground under `point` over all instances (CollisionModel::groundBelow in world units; a
// turned instance's column is the world column turned, the same half-width).
std::optional<std::int64_t> groundBelow(std::span<const CollisionInstance> instances,
                                        const ModelPoint& point, std::int64_t half_width,
                                        std::int64_t reach);

}  // namespace octopoint
