#include "renderer/collision.h"

#include <algorithm>
#include <limits>

#include "fixedpoint/trig.h"
#include "renderer/bit_scan.h"

namespace octopoint {
namespace {

constexpr std::int64_t kHalfCube = kPerspectiveUnit / 2;  // Q.24: the cube is [-2^23, 2^23]^3
// A model query's sphere may be larger than a world sphere (an instance scaled down by 2^8: up to
// 2^32 + 2^10). Gaps below 2^31 keep three squares within an unsigned 64-bit sum; a larger
// radius compares gaps and radius a quarter as large (SphereVisitor).
constexpr std::int64_t kExactModelRadius = (std::int64_t{1} << 31) - 1;
constexpr std::int64_t kMaxModelRadius = std::int64_t{1} << 33;
// Coordinates past this are far outside every cube a query can reach; clamping them there keeps
// every difference within 64 bits.
constexpr std::int64_t kFarAway = std::int64_t{1} << 40;
// The rotation's rounding (two Q1.30 products of a difference below 2^31, each within 1/2 ulp of
// the exact sine, then rounded) moves a point by at most 2 units on each turned axis: 3 units
// in all, which pads a carried sphere.
constexpr std::int64_t kTurnPad = 3;

ModelPoint clampedFar(const ModelPoint& p) {
  return {std::clamp(p.x, -kFarAway, kFarAway), std::clamp(p.y, -kFarAway, kFarAway),
          std::clamp(p.z, -kFarAway, kFarAway)};
}

// The distance from `c` to the closed interval [lo, lo + edge].
std::int64_t axisGap(std::int64_t c, std::int64_t lo, std::int64_t edge) {
  if (c < lo) return lo - c;
  if (c > lo + edge) return c - lo - edge;
  return 0;
}

// The child cube's lowest corner: child k = (x << 2) | (y << 1) | z.
ModelPoint childCorner(const ModelPoint& lo, unsigned child, std::int64_t child_edge) {
  return {lo.x + ((child >> 2) & 1u) * child_edge, lo.y + ((child >> 1) & 1u) * child_edge,
          lo.z + (child & 1u) * child_edge};
}

struct SphereVisitor {
  ModelPoint centre;
  std::int64_t radius;
  // 0, or 2 for a radius past kExactModelRadius: gaps rounded down and the radius rounded up by
  // that many bits before squaring, which errs towards "meets" by less than 12 units.
  int shift;
  std::uint64_t radius_squared;  // of the radius so shifted
  CollisionStats* stats;

  bool enter(const ModelPoint& lo, std::int64_t edge) {
    if (stats != nullptr) ++stats->boxes_tested;
    const std::int64_t gx = axisGap(centre.x, lo.x, edge), gy = axisGap(centre.y, lo.y, edge),
                       gz = axisGap(centre.z, lo.z, edge);
    if (gx >= radius || gy >= radius || gz >= radius) return false;
    const auto ux = static_cast<std::uint64_t>(gx) >> shift,
               uy = static_cast<std::uint64_t>(gy) >> shift,
               uz = static_cast<std::uint64_t>(gz) >> shift;
    return ux * ux + uy * uy + uz * uz < radius_squared;  // each square below 2^62
  }
  bool leaf(const ModelPoint&, std::int64_t) { return true; }  // entered: met; stop
};

struct GroundVisitor {
  ModelPoint point;
  std::int64_t half_width;
  std::int64_t reach;
  std::int64_t best = std::numeric_limits<std::int64_t>::max();

  bool enter(const ModelPoint& lo, std::int64_t edge) const {
    return lo.y < best && lo.x < point.x + half_width && lo.x + edge > point.x - half_width &&
           lo.z < point.z + half_width && lo.z + edge > point.z - half_width &&
           lo.y <= point.y + reach && lo.y + edge >= point.y;
  }
  bool leaf(const ModelPoint& lo, std::int64_t) {
    best = lo.y;  // entered: higher than every top found so far
    return false;
  }
};

}  // namespace

std::optional<CollisionModel> CollisionModel::ofLevel(const LevelView& level) {
  const std::size_t entries = upperTreeEntries(level);
  if (entries == 0) return std::nullopt;
  std::vector<UpperTreeNode> storage(entries);
  const UpperTreeIndex index = buildUpperTreeIndex(level, storage);
  if (index.bottom < 0) return std::nullopt;
  return CollisionModel(level, std::move(storage), index.bottom);
}

std::optional<CollisionModel> CollisionModel::of(const ModelView& model, int depth) {
  const LevelView* level = depth == 0 ? &model.finestLevel() : model.levelOfDepth(depth);
  if (level == nullptr) return std::nullopt;
  return ofLevel(*level);
}

template <typename Visitor>
bool CollisionModel::walk(Visitor& visitor) const {
  const ModelPoint root{-kHalfCube, -kHalfCube, -kHalfCube};
  return visitor.enter(root, kPerspectiveUnit) && walkIndexed(visitor, 0, 0, root);
}

// A node of the index whose cube the visitor entered; true when the visitor stops the walk.
template <typename Visitor>
bool CollisionModel::walkIndexed(Visitor& visitor, std::size_t entry, int tree_level,
                                 const ModelPoint& lo) const {
  const UpperTreeNode& node = index_[entry];
  if (tree_level == bottom_) {
    const std::uint8_t* cursor = level_.nodes.data() + node.node;
    return walkStream(visitor, cursor, tree_level, lo);
  }
  const unsigned mask = level_.nodes[node.node];
  const std::int64_t child_edge = kPerspectiveUnit >> (tree_level + 1);
  std::size_t child_entry = node.first_child;
  for (unsigned child = 0; child < 8; ++child) {
    if ((mask >> child & 1u) == 0) continue;
    const ModelPoint child_lo = childCorner(lo, child, child_edge);
    if (visitor.enter(child_lo, child_edge) &&
        walkIndexed(visitor, child_entry, tree_level + 1, child_lo)) {
      return true;
    }
    ++child_entry;
  }
  return false;
}

// Below the index, in stream order: `cursor` is at the node's mask byte; when the walk goes on
// (false), it is left just past the node's subtree.
template <typename Visitor>
bool CollisionModel::walkStream(Visitor& visitor, const std::uint8_t*& cursor, int tree_level,
                                const ModelPoint& lo) const {
  const unsigned mask = *cursor++;
  const int child_level = tree_level + 1;
  const std::int64_t child_edge = kPerspectiveUnit >> child_level;
  for (unsigned child = 0; child < 8; ++child) {
    if ((mask >> child & 1u) == 0) continue;
    const ModelPoint child_lo = childCorner(lo, child, child_edge);
    if (child_level == level_.depth) {  // a leaf: no byte of its own
      if (visitor.enter(child_lo, child_edge) && visitor.leaf(child_lo, child_edge)) return true;
    } else if (!visitor.enter(child_lo, child_edge)) {
      skipStream(cursor, child_level);
    } else if (walkStream(visitor, cursor, child_level, child_lo)) {
      return true;
    }
  }
  return false;
}

// At most the three levels below the index's bottom.
void CollisionModel::skipStream(const std::uint8_t*& cursor, int tree_level) const {
  const unsigned mask = *cursor++;
  if (tree_level + 1 == level_.depth) return;
  for (int child = childCount(mask); child > 0; --child) skipStream(cursor, tree_level + 1);
}

bool CollisionModel::meets(const CollisionSphere& sphere, CollisionStats* stats) const {
  if (sphere.radius < 1 || sphere.radius > kMaxModelRadius) return false;
  const int shift = sphere.radius > kExactModelRadius ? 2 : 0;
  const std::uint64_t radius =
      (static_cast<std::uint64_t>(sphere.radius) + (1u << shift) - 1) >> shift;
  SphereVisitor visitor{clampedFar(sphere.centre), sphere.radius, shift, radius * radius, stats};
  return walk(visitor);
}

std::optional<std::int64_t> CollisionModel::groundBelow(const ModelPoint& point,
                                                        std::int64_t half_width,
                                                        std::int64_t reach) const {
  constexpr std::int64_t kMaxExtent = std::int64_t{1} << 30;
  if (half_width < 1 || half_width > kMaxExtent || reach < 1 || reach > kMaxExtent) {
    return std::nullopt;
  }
  GroundVisitor visitor{clampedFar(point), half_width, reach};
  walk(visitor);
  if (visitor.best == std::numeric_limits<std::int64_t>::max()) return std::nullopt;
  return visitor.best;
}

namespace {

// Instance positions are within kMaxSceneCoordinate (2^44); a point past this is far from all
// of them, and clamping it here keeps every difference within 64 bits.
constexpr std::int64_t kFarFromInstances = std::int64_t{1} << 46;

ModelPoint clampedFromInstances(const ModelPoint& p) {
  return {std::clamp(p.x, -kFarFromInstances, kFarFromInstances),
          std::clamp(p.y, -kFarFromInstances, kFarFromInstances),
          std::clamp(p.z, -kFarFromInstances, kFarFromInstances)};
}

// A point of the world in an instance's model units.
struct LocalFrame {
  int shift;            // the instance's scale
  std::int32_t sine;    // Q1.30
  std::int32_t cosine;  // Q1.30
  ModelPoint at;

  // World differences within instanceReach's box plus the margin (the caller checks): below
  // 2^31.6 on each axis, so each Q1.30 product is below 2^61.6 and the sum of two below 2^62.1.
  ModelPoint toModel(const ModelPoint& world) const {
    const std::int64_t dx = world.x - at.x, dy = world.y - at.y, dz = world.z - at.z;
    constexpr std::int64_t kHalfQ30 = std::int64_t{1} << 29;
    // The inverse turn Ry(-turn): model x = cos dx - sin dz, model z = sin dx + cos dz (Q1.30,
    // rounded to the unit).
    const std::int64_t tx = (cosine * dx - sine * dz + kHalfQ30) >> 30;
    const std::int64_t tz = (sine * dx + cosine * dz + kHalfQ30) >> 30;
    return {scaledDown(tx), scaledDown(dy), scaledDown(tz)};
  }
  // World units to model units: divided by 2^shift, rounded to the nearest (a half unit more of
  // error, which the padding covers), or multiplied for an instance scaled down.
  std::int64_t scaledDown(std::int64_t v) const {
    if (shift >= 0) return (v + ((std::int64_t{1} << shift) >> 1)) >> shift;
    return v * (std::int64_t{1} << -shift);
  }
  // A length in world units as model units, rounded up.
  std::int64_t lengthToModel(std::int64_t v) const {
    if (shift >= 0) return (v + (std::int64_t{1} << shift) - 1) >> shift;
    return v * (std::int64_t{1} << -shift);
  }
  // A model y back in world units, rounded down (the ground a little higher, never lower).
  std::int64_t yToWorld(std::int64_t y) const {
    const std::int64_t scaled = shift >= 0 ? y * (std::int64_t{1} << shift) : y >> -shift;
    return at.y + scaled;
  }
};

// The frame of `instance` when `point` lies within `margin` (world units, at most 2^26) of the
// box that holds its turned cube (instanceReach); nullopt otherwise, or for a transform
// checkTransform refuses.
std::optional<LocalFrame> frameNear(const CollisionInstance& instance, const ModelPoint& point,
                                    std::int64_t margin) {
  const InstanceTransform& t = instance.transform;
  if (instance.model == nullptr || checkTransform(t) != SceneError::kNone) return std::nullopt;
  const InstanceReach reach = instanceReach(t.scale);
  const ModelPoint p = clampedFromInstances(point);
  const std::int64_t dx = p.x - t.at.x, dy = p.y - t.at.y, dz = p.z - t.at.z;
  const std::int64_t across = reach.across + margin, up = reach.up + margin;
  if (dx > across || -dx > across || dy > up || -dy > up || dz > across || -dz > across) {
    return std::nullopt;
  }
  return LocalFrame{t.scale, sinQ30(t.turn), cosQ30(t.turn), t.at};
}

}  // namespace

bool sphereMeets(std::span<const CollisionInstance> instances, const CollisionSphere& sphere,
                 CollisionStats* stats) {
  if (sphere.radius < 1 || sphere.radius > kMaxCollisionRadius) return false;
  for (const CollisionInstance& instance : instances) {
    if (instanceMeets(instance, sphere, stats)) return true;
  }
  return false;
}

bool instanceMeets(const CollisionInstance& instance, const CollisionSphere& sphere,
                   CollisionStats* stats) {
  if (sphere.radius < 1 || sphere.radius > kMaxCollisionRadius) return false;
  const std::optional<LocalFrame> frame = frameNear(instance, sphere.centre, sphere.radius);
  if (!frame) return false;
  const bool turned = instance.transform.turn != Angle{};
  // The half unit of the scale's rounding, rounded up to one model unit, and the turn's pad.
  const std::int64_t radius =
      frame->lengthToModel(sphere.radius + (turned ? kTurnPad : 0)) + (frame->shift > 0 ? 1 : 0);
  return instance.model->meets({frame->toModel(sphere.centre), radius}, stats);
}

InstanceReach instanceReach(int scale) {
  const std::int64_t edge =
      scale >= 0 ? kPerspectiveUnit << scale : kPerspectiveUnit >> -scale;  // 2^16 .. 2^32
  // Turned, the cube's half-width across is at most sqrt(2)/2 edges (182/256 > 0.7072); the
  // carried centre's rounding (kTurnPad) and a unit more on both.
  return {(edge >> 8) * 182 + kTurnPad + 1, edge / 2 + kTurnPad + 1};
}

std::optional<std::int64_t> groundBelow(std::span<const CollisionInstance> instances,
                                        const ModelPoint& point, std::int64_t half_width,
                                        std::int64_t reach) {
  constexpr std::int64_t kMaxExtent = std::int64_t{1} << 24;
  if (half_width < 1 || half_width > kMaxExtent || reach < 1 || reach > kMaxExtent) {
    return std::nullopt;
  }
  std::optional<std::int64_t> ground;
  for (const CollisionInstance& instance : instances) {
    const std::optional<LocalFrame> frame = frameNear(instance, point, half_width + reach);
    if (!frame) continue;
    // A turned column's square reaches sqrt(2) times as far: 3/2 covers it.
    const bool turned = instance.transform.turn != Angle{};
    const std::int64_t width = turned ? (half_width * 3 + 1) / 2 : half_width;
    const std::optional<std::int64_t> top = instance.model->groundBelow(
        frame->toModel(point), frame->lengthToModel(width), frame->lengthToModel(reach) + 1);
    if (top) {
      const std::int64_t world_top = frame->yToWorld(*top);
      if (!ground || world_top < *ground) ground = world_top;
    }
  }
  return ground;
}

}  // namespace octopoint
