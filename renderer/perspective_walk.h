#pragma once
// The perspective walk over one level (docs/perspective.md): down the tree in camera space, where
// the rotation keeps every step an addition; a subtree wholly outside the frustum or behind the
// near plane is passed over; a subtree whose affine map is within `max_error` of the projection
// (affineErrorBound) is drawn from that map with per-level screen vectors, additions only, as the
// orthographic decoders do; a leaf reached before any such subtree is projected exactly. With its
// optional parts (PerspectiveWalkParts) it visits the upper levels nearest first through an upper
// tree index, draws only the parts of the frame detail by distance gives its depth, and passes
// over subtrees the sink finds hidden (occlusion culling).

#include <algorithm>
#include <array>
#include <atomic>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "renderer/bit_scan.h"
#include "renderer/occlusion_tiles.h"
#include "renderer/perspective.h"
#include "renderer/perspective_depth.h"
#include "renderer/perspective_detail.h"
#include "renderer/perspective_extent.h"
#include "renderer/perspective_walk_parts.h"
#include "renderer/perspective_walk_tables.h"
#include "renderer/upper_tree_index.h"

namespace octopoint {

// Calls sink(const PerspectiveLeaf&) for every leaf in front of the near plane whose subtree
// meets the frustum (and that parts.detail gives this depth), in stream order below the index's
// bottom and nearest first above it. Returns false when `abort` was set (checked per subtree).
// With parts.cull, a subtree the sink finds hidden (none of its leaves would change the frame) is
// passed over.
template <typename Sink>
class PerspectiveWalk {
 public:
  PerspectiveWalk(const LevelView& level, const PerspectiveView& view,
                  const PerspectiveWalkTables& tables, Sink& sink,
                  const std::atomic<bool>* abort = nullptr, const PerspectiveWalkParts& parts = {})
      : view_(view),
        tables_(tables),
        sink_(sink),
        abort_(abort),
        parts_(parts),
        nodes_(level.nodes.data()),
        node_(level.nodes.data()) {
    if (parts_.band != nullptr) {
      band_top_limit_ = smallProductLimit(parts_.band->top_q30);
      band_bottom_limit_ = smallProductLimit(parts_.band->bottom_q30);
    }
  }

  bool run() {
    // The root's centre is the model's origin. The walk's centres are Q.(24 + walk_bits) (fine);
    // every test and projection takes them rounded to Q.24 (unit).
    const CameraPoint root = toWalkSpace(view_, ModelPoint{0, 0, 0});
    if (parts_.index != nullptr && parts_.index->bottom >= 0) {
      visitIndexed(0, 0, root, ModelPoint{0, 0, 0}, parts_.detail.start());
    } else {
      visit(0, root, parts_.detail.start());
    }
    return !aborted_;
  }

 private:
  // A sink that can take part in occlusion culling.
  static constexpr bool kSinkCulls = requires(Sink & sink, const AffineSubtree& subtree) {
    sink.hidden(subtree);
    sink.drawn(subtree);
  };

  // A sink that takes the leaves of a subtree drawn from one affine map in 32 bits where its
  // positions fit: after enterAffine, narrowAffine() says whether every position of the subtree
  // (its centre plus any sum of its screen vectors, all within the AffineSubtree's reaches of
  // it) lies in [0, 2^31) on each axis, and then its leaves come as narrowLeaf(index, x, y, z)
  // (Q(32-F).F, depth Q.24), with the AffineSubtree's half extents: on a Cortex-M0+ each 64-bit
  // operation of the walk and the plot is several instructions or a library call.
  // Such a sink also takes a part of a clipped subtree (a node of it, its AffineSubtree) in 32
  // bits: enterPart says whether it may (as narrowAffine), leavePart restores the subtree's.
  static constexpr bool kSinkNarrows = requires(Sink & sink, const AffineSubtree& part) {
    { sink.narrowAffine() } -> std::same_as<bool>;
    sink.narrowLeaf(std::size_t{0}, std::int32_t{0}, std::int32_t{0}, std::int32_t{0});
    { sink.enterPart(part) } -> std::same_as<bool>;
    sink.leavePart();
  };

  // A sink that says whether a part of a subtree drawn from one affine map writes nothing on its
  // screen (offScreen(const AffineSubtree&): every leaf of it within the reaches of its centre,
  // and each leaf's splat, lies off the screen): in a band the walk passes over those parts of a
  // subtree that straddles the band's edge, instead of handing their leaves over to be clipped.
  static constexpr bool kSinkClips = requires(Sink & sink, const AffineSubtree& subtree) {
    { sink.offScreen(subtree) } -> std::same_as<bool>;
  };

  enum class Step : std::uint8_t { kPass, kAffine, kDescend };

  // What to do at an inner node: pass over it (aborted, outside the frustum, or drawn by another
  // depth), draw it from its affine map (`affine`), or descend.
  Step judge(int level, const CameraPoint& fine, DetailState& state, AffineProjection& affine) {
    if (abort_ != nullptr && abort_->load(std::memory_order_relaxed)) aborted_ = true;
    const CameraPoint centre = unit(fine);
    const std::int64_t reach = tables_.reach[static_cast<std::size_t>(level)];
    if (aborted_ || outsideFrustum(centre, reach + tables_.splat_margin)) return Step::kPass;
    if (!state.committed && parts_.detail.node(level, centre.z, state) == DetailVerdict::kOthers) {
      return Step::kPass;
    }
    const auto l = static_cast<std::size_t>(level);
    if (state.committed && centre.z >= tables_.affine_depth[kNearestBucket][l] &&
        centre.z - reach >= view_.camera.near) {
      const int bucket = affineBucket(centre);
      if (centre.z >= tables_.affine_depth[static_cast<std::size_t>(bucket)][l] &&
          affineAtInto(view_, centre, &affine)) {
        affine_bucket_ = bucket;
        return Step::kAffine;
      }
    }
    return Step::kDescend;
  }

  // A walk position, Q.(24 + walk_bits), rounded to Q.24 (ties toward +infinity, as
  // roundShiftRight): the same point where walk_bits is 0.
  CameraPoint unit(const CameraPoint& fine) const {
    const int bits = view_.walk_bits;
    if (bits == 0) return fine;
    return {roundShiftRight(fine.x, bits), roundShiftRight(fine.y, bits),
            roundShiftRight(fine.z, bits)};
  }

  // The bucket of tables_.affine_depth a node at `c` (c.z > 0) takes: the most lenient whose
  // bound on max(|c.x|, |c.y|) / c.z it meets, 0 (the frustum's) where none.
  static constexpr std::size_t kNearestBucket = PerspectiveWalkTables::kAffineBuckets - 1;
  static int affineBucket(const CameraPoint& c) {
    const std::int64_t off_axis = std::max(c.x < 0 ? -c.x : c.x, c.y < 0 ? -c.y : c.y);
    for (int bucket = PerspectiveWalkTables::kAffineBuckets - 1; bucket > 0; --bucket) {
      if (off_axis <= c.z >> (bucket - 1)) return bucket;
    }
    return 0;
  }

  // A node in stream order, its mask byte at node_; `centre` in the walk's units.
  void visit(int level, const CameraPoint& centre, DetailState state) {
    if (level == tables_.depth) {
      leaf(unit(centre), state);
      return;
    }
    const std::uint8_t mask = *node_++;
    AffineProjection affine;
    switch (judge(level, centre, state, affine)) {
      case Step::kPass:
        skipChildren(level, mask);
        return;
      case Step::kAffine:
        if (!drawAffine(level, mask, affine)) skipChildren(level, mask);
        return;
      case Step::kDescend:
        break;
    }
    const auto& offsets = tables_.child_offset[static_cast<std::size_t>(level)];
    for (unsigned k = 0; k < 8; ++k) {
      if (mask & (1u << k)) {
        const CameraPoint& o = offsets[k];
        visit(level + 1, {centre.x + o.x, centre.y + o.y, centre.z + o.z}, state);
      }
    }
  }

  // A leaf met in stream order, its centre in Q.24.
  void leaf(const CameraPoint& centre, DetailState& state) {
    if ((state.committed || parts_.detail.drawsLeaf(tables_.depth, centre.z, state)) &&
        !leafOutsideBand(centre)) {
      // The map at the leaf gives its splat's extent and its position (its centre: within half
      // a unit in the last place plus f * 2^-31 pixel of the exact projection, as project's);
      // where no map fits (an axis vector past int64), project alone, and no extent.
      AffineProjection affine;
      if (affineAtInto(view_, centre, &affine)) {
        const Point3<std::int64_t> half = widenedHalfExtent(
            voxelHalfExtent(cubeShadow(affine), tables_.depth), tables_.sample_reach);
        sink_(PerspectiveLeaf{leaf_, affine.centre.x, affine.centre.y, affine.centre.z, half.x,
                              half.y});
      } else if (const std::optional<ScreenPoint> p = project(view_, centre)) {
        sink_(PerspectiveLeaf{leaf_, p->x, p->y, p->z, 0, 0});
      }
    }
    ++leaf_;
  }

  // In a band, a leaf whose box (with its splat's margin) the eye sees wholly above or below the
  // band is passed over before its projection (three divisions), as judge passes over a node:
  // a leaf parent that straddles the band's edge hands over only the leaves that may reach it.
  // The whole frame projects every leaf of a leaf parent that meets the frustum (its count of
  // points handed over is unchanged).
  bool leafOutsideBand(const CameraPoint& centre) const {
    return parts_.band != nullptr &&
           outsideBand(centre, tables_.reach[static_cast<std::size_t>(tables_.depth)] +
                                   tables_.splat_margin);
  }

  // A node above the index's bottom, by its index entry: its children nearest the eye first.
  // Children k and j are ordered by the planes through their parent's centre: k is nearer than j
  // where it lies on the eye's side of every plane that parts them, so visiting them in the order
  // eye_octant ^ 0, ^ 1, ..., ^ 7 puts every child before those it may hide.
  void visitIndexed(int level, std::uint32_t entry, const CameraPoint& centre,
                    const ModelPoint& model_centre, DetailState state) {
    const UpperTreeNode& node = parts_.index->entries[entry];
    if (level == parts_.index->bottom) {
      node_ = nodes_ + node.node;
      leaf_ = node.leaf;
      visit(level, centre, state);
      return;
    }
    const unsigned mask = nodes_[node.node];
    AffineProjection affine;
    switch (judge(level, centre, state, affine)) {
      case Step::kPass:
        return;
      case Step::kAffine:
        node_ = nodes_ + node.node + 1;
        leaf_ = node.leaf;
        static_cast<void>(drawAffine(level, static_cast<std::uint8_t>(mask), affine, &node,
                                     model_centre));  // hidden: nothing to read past
        return;
      case Step::kDescend:
        break;
    }
    const unsigned eye_octant = eyeOctant(model_centre);
    const auto& offsets = tables_.child_offset[static_cast<std::size_t>(level)];
    for (unsigned order = 0; order < 8; ++order) {
      const unsigned k = eye_octant ^ order;
      if (!(mask & (1u << k))) continue;
      const CameraPoint& o = offsets[k];
      visitIndexed(level + 1, childEntry(node, mask, k),
                   {centre.x + o.x, centre.y + o.y, centre.z + o.z},
                   childCentre(model_centre, level, k), state);
    }
  }

  // Wholly behind the near plane, or wholly beyond one of the four side planes: every point of
  // the box has x >= centre.x - reach and z <= centre.z + reach, so centre.x - reach >
  // slope * (centre.z + reach) puts it right of the plane x = slope * z whatever its z.
  // In a band the band's two products come first: most nodes a band judges lie inside the frame
  // and outside the band, and then the sides' four are not made.
  bool outsideFrustum(const CameraPoint& c, std::int64_t reach) const {
    return (parts_.band != nullptr && outsideBand(c, reach)) ||
           outsideFrustumSides(tables_, c, reach, view_.camera.near);
  }

  // Wholly above the band (every point has y < top * z: y <= c.y + reach, and top * z is at
  // least top times the box's least z if top >= 0, its largest if not) or wholly below it.
  bool outsideBand(const CameraPoint& c, std::int64_t reach) const {
    const std::int64_t top = parts_.band->top_q30, bottom = parts_.band->bottom_q30;
    const std::optional<std::int64_t> above =
        mulShiftRoundLimited(top >= 0 ? c.z - reach : c.z + reach, top, band_top_limit_, 30);
    const std::optional<std::int64_t> below = mulShiftRoundLimited(
        bottom >= 0 ? c.z + reach : c.z - reach, bottom, band_bottom_limit_, 30);
    // Rounded to nearest: one unit more keeps the test conservative.
    return (above && c.y + reach < *above - 1) || (below && c.y - reach > *below + 1);
  }

  void skipChildren(int level, std::uint8_t mask) {
    if (level + 1 == tables_.depth) {  // a leaf parent: its leaves have no bytes of their own
      leaf_ += static_cast<std::size_t>(childCount(mask));
      return;
    }
    for (unsigned k = 0; k < 8; ++k) {
      if (mask & (1u << k)) skipNode(level + 1);
    }
  }
  void skipNode(int level) {
    if (level == tables_.depth) {
      ++leaf_;
      return;
    }
    skipChildren(level, *node_++);
  }

  // The subtree below a node of `level` whose children are `mask`, from the affine map at its
  // centre: per level m below, eight screen vectors, each the sum of the map's three axis vectors
  // with the child's signs times 2^-(m+2) (a child of a node of level m lies 2^-(m+2) cube edges
  // from it along each axis), rounded once; child 7 - k is child k mirrored (every sign flipped),
  // so four are made and four negated. No division. False, with nothing drawn and none of its
  // bytes read, where the sink finds the subtree hidden. With `indexed` (the node's index entry,
  // above the index's bottom, and its model-space centre) the subtree's upper levels are visited
  // nearest first through the index; every leaf is the same sum of the same vectors either way.
  bool drawAffine(int level, std::uint8_t mask, const AffineProjection& affine,
                  const UpperTreeNode* indexed = nullptr, const ModelPoint& model_centre = {}) {
    // The map's voxel is the size at the centre's depth; nearer voxels of the subtree are larger,
    // by up to z / (z - reach) (growth_q16): widened by that much, the subtree's splats leave no
    // crack. The sample reach widens them first (widenedHalfExtent).
    shadow_ = cubeShadow(affine);
    const Point3<std::int64_t> half =
        widenedHalfExtent(voxelHalfExtent(shadow_, tables_.depth), tables_.sample_reach);
    const std::int64_t growth_q16 =
        tables_
            .growth_q16[static_cast<std::size_t>(affine_bucket_)][static_cast<std::size_t>(level)];
    half_ = {(half.x * growth_q16 >> 16) + 1, (half.y * growth_q16 >> 16) + 1, 0};
    const AffineSubtree subtree = affineSubtree(
        level, Point3<std::int64_t>{affine.centre.x, affine.centre.y, affine.centre.z});
    if constexpr (kSinkCulls) {
      if (parts_.cull && sink_.hidden(subtree)) return false;
    }
    if constexpr (kSinkClips) {
      // In a band: a subtree the eye's box test let through may still write nothing in it.
      if (parts_.band != nullptr && sink_.offScreen(subtree)) return false;
    }
    const auto& a = affine.axis;
    // Children 0 to 3 (x's sign -): -a0 -+ a1 -+ a2.
    const Point3<std::int64_t> down = sub(neg(a[0]), a[1]), up = add(neg(a[0]), a[1]);
    const Point3<std::int64_t> sums[4] = {sub(down, a[2]), add(down, a[2]), sub(up, a[2]),
                                          add(up, a[2])};
    if constexpr (requires { sink_.enterAffine(subtree); }) sink_.enterAffine(subtree);
    bool narrow = false;
    if constexpr (kSinkNarrows) {
      narrow = sink_.narrowAffine();
      if (narrow) {
        fillScreenOffsets(level, tables_.depth, sums, narrow_offset_);
        walkAffine<std::int32_t>(level, mask, indexed, subtree, model_centre);
      }
    }
    if (!narrow) {
      fillScreenOffsets(level, tables_.depth, sums, screen_offset_);
      walkAffine<std::int64_t>(level, mask, indexed, subtree, model_centre);
    }
    if constexpr (requires { sink_.leaveAffine(); }) sink_.leaveAffine();
    return true;
  }

  // The walk below drawAffine's node, its positions in Int (int64, or int32 where they fit:
  // sums of the same vectors, so the same leaves either way).
  template <typename Int>
  void walkAffine(int level, std::uint8_t mask, const UpperTreeNode* indexed,
                  const AffineSubtree& subtree, const ModelPoint& model_centre) {
    const Point3<Int> centre{static_cast<Int>(subtree.centre.x), static_cast<Int>(subtree.centre.y),
                             static_cast<Int>(subtree.centre.z)};
    affine_level_ = level;
    if constexpr (kSinkCulls) {
      if (parts_.cull) {
        if (indexed != nullptr) {
          visitAffineIndexed<Int>(level, *indexed, centre, model_centre);
        } else {
          visitAffine<true>(level, mask, centre);
        }
        // A subtree below the grandparents' level has no grandparent that says where it drew.
        if (level + 2 > tables_.depth) sink_.drawn(subtree);
      } else {
        visitAffine<false>(level, mask, centre);
      }
    } else {
      static_cast<void>(indexed);
      static_cast<void>(subtree);
      static_cast<void>(model_centre);
      visitAffine<false>(level, mask, centre);
    }
  }

  template <typename Offset>
  const std::array<Point3<Offset>, 8>& screenOffsets(int level) const {
    if constexpr (sizeof(Offset) == sizeof(std::int32_t)) {
      return narrow_offset_[static_cast<std::size_t>(level)];
    } else {
      return screen_offset_[static_cast<std::size_t>(level)];
    }
  }

  // Where the leaves of a node of `level` at screen position `p` inside the subtree being drawn
  // from its map lie, and their splats: within the sum of the levels' largest vectors of p, the
  // cube's shadow over 2^(m+2) for m from `level`, each rounded (half a unit, counted as one).
  template <typename Int>
  AffineSubtree affineSubtree(int level, const Point3<Int>& p) const {
    const std::int64_t levels = tables_.depth - level;
    return {{p.x, p.y, p.z},
            (shadow_.x >> (level + 1)) + levels,
            (shadow_.y >> (level + 1)) + levels,
            (shadow_.z >> (level + 1)) + levels,
            half_.x,
            half_.y};
  }

  // A node of a subtree drawn from its affine map, at `p`, its children `mask`: set-bit
  // iteration over them, and a leaf parent hands its leaves over in one loop (no call per leaf).
  // kCull: each leaves' grandparent (below the subtree's root) is first asked whether it is
  // hidden, and says where it drew. Positions in Int, the level's vectors read as Offset (int64
  // vectors read as int32 in a part of a clipped subtree that is narrow: below).
  template <bool kCull, typename Int, typename Offset = Int>
  void visitAffine(int level, unsigned mask, const Point3<Int>& p) {
    if constexpr (kSinkClips && kSinkNarrows && sizeof(Int) == sizeof(std::int64_t)) {
      // In a band, a subtree drawn in 64 bits is one the plot clips (but for frames too large
      // for narrowAffine). Below its root (drawAffine asked for that), a node that writes
      // nothing in the band is passed over, its leaves not handed over; a node whose leaves all
      // lie within the band is drawn as narrowAffine's subtrees are (its positions and vectors,
      // within its reach of it, fit 32 bits as theirs do: the same sums, so the same leaves).
      if (parts_.band != nullptr && level != affine_level_) {
        const AffineSubtree node = affineSubtree(level, p);
        if (sink_.offScreen(node)) {
          skipChildren(level, static_cast<std::uint8_t>(mask));
          return;
        }
        const bool narrow = sink_.enterPart(node);
        if (narrow) {
          visitAffine<kCull, std::int32_t, std::int64_t>(level, mask, narrowed(p));
        }
        sink_.leavePart();
        if (narrow) return;
      }
    }
    const auto& offsets = screenOffsets<Offset>(level);
    if (level + 1 == tables_.depth) {
      for (unsigned bits = mask; bits != 0; bits &= bits - 1) {
        const Point3<Offset>& d = offsets[lowestChild(bits)];
        if constexpr (sizeof(Int) == sizeof(std::int32_t)) {
          sink_.narrowLeaf(leaf_++, p.x + static_cast<Int>(d.x), p.y + static_cast<Int>(d.y),
                           p.z + static_cast<Int>(d.z));
        } else {
          sink_(PerspectiveLeaf{leaf_++, p.x + d.x, p.y + d.y, p.z + d.z, half_.x, half_.y});
        }
      }
      return;
    }
    if constexpr (kCull) {
      if (level + 2 == tables_.depth) {
        const AffineSubtree node = affineSubtree(level, p);
        if (level != affine_level_ && sink_.hidden(node)) {
          skipChildren(level, static_cast<std::uint8_t>(mask));
          return;
        }
        for (unsigned bits = mask; bits != 0; bits &= bits - 1) {
          const unsigned child_mask = *node_++;
          visitAffine<kCull, Int, Offset>(level + 1, child_mask,
                                          add(p, offsets[lowestChild(bits)]));
        }
        sink_.drawn(node);
        return;
      }
    }
    for (unsigned bits = mask; bits != 0; bits &= bits - 1) {
      const unsigned child_mask = *node_++;
      visitAffine<kCull, Int, Offset>(level + 1, child_mask, add(p, offsets[lowestChild(bits)]));
    }
  }

  // A node of a subtree drawn from its affine map, above the index's bottom: asked whether it is
  // hidden (below the subtree's root), then its children nearest the eye first (as
  // visitIndexed), down to the bottom, from where the stream is read in order.
  template <typename Int>
  void visitAffineIndexed(int level, const UpperTreeNode& node, const Point3<Int>& p,
                          const ModelPoint& model_centre) {
    if (level != affine_level_ && sink_.hidden(affineSubtree(level, p))) return;
    const unsigned mask = nodes_[node.node];
    if (level == parts_.index->bottom) {
      node_ = nodes_ + node.node + 1;
      leaf_ = node.leaf;
      visitAffine<true>(level, mask, p);
      return;
    }
    const unsigned eye_octant = eyeOctant(model_centre);
    const auto& offsets = screenOffsets<Int>(level);
    for (unsigned order = 0; order < 8; ++order) {
      const unsigned k = eye_octant ^ order;
      if (!(mask & (1u << k))) continue;
      visitAffineIndexed<Int>(level + 1, parts_.index->entries[childEntry(node, mask, k)],
                              add(p, offsets[k]), childCentre(model_centre, level, k));
    }
  }

  // Which side of the planes through a node's centre (model space) the eye is on: bit 2 x, 1 y,
  // 0 z, as the child numbers.
  unsigned eyeOctant(const ModelPoint& centre) const {
    const ModelPoint& eye = view_.camera.eye;
    return (eye.x >= centre.x ? 4u : 0u) | (eye.y >= centre.y ? 2u : 0u) |
           (eye.z >= centre.z ? 1u : 0u);
  }
  static std::uint32_t childEntry(const UpperTreeNode& node, unsigned mask, unsigned k) {
    return node.first_child + static_cast<std::uint32_t>(childCount(mask & ((1u << k) - 1)));
  }
  static ModelPoint childCentre(const ModelPoint& centre, int level, unsigned k) {
    const std::int64_t step = kPerspectiveUnit >> (level + 2);  // Q.24: a child's offset per axis
    return {centre.x + ((k & 4) ? step : -step), centre.y + ((k & 2) ? step : -step),
            centre.z + ((k & 1) ? step : -step)};
  }
  // a + b in a's type (b's vectors fit it: int64 vectors of a narrow part read as int32).
  template <typename Int, typename Offset>
  static Point3<Int> add(const Point3<Int>& a, const Point3<Offset>& b) {
    return {static_cast<Int>(a.x + static_cast<Int>(b.x)),
            static_cast<Int>(a.y + static_cast<Int>(b.y)),
            static_cast<Int>(a.z + static_cast<Int>(b.z))};
  }
  static Point3<std::int32_t> narrowed(const Point3<std::int64_t>& p) {
    return {static_cast<std::int32_t>(p.x), static_cast<std::int32_t>(p.y),
            static_cast<std::int32_t>(p.z)};
  }
  static Point3<std::int64_t> sub(const Point3<std::int64_t>& a, const Point3<std::int64_t>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  static Point3<std::int64_t> neg(const Point3<std::int64_t>& a) { return {-a.x, -a.y, -a.z}; }

  const PerspectiveView& view_;
  const PerspectiveWalkTables& tables_;
  Sink& sink_;
  const std::atomic<bool>* abort_;
  PerspectiveWalkParts parts_;
  const std::uint8_t* nodes_;  // the level's node stream
  const std::uint8_t* node_;
  std::size_t leaf_ = 0;
  bool aborted_ = false;
  // The band's slopes' smallProductLimit (outsideBand): made once a walk, not per node.
  std::int64_t band_top_limit_ = 0, band_bottom_limit_ = 0;
  // The screen vectors of the subtree drawn from its affine map: Q(32-F).F, depth in Q.24; int64,
  // or int32 where the sink says the subtree's positions fit (narrowAffine). One storage: a
  // walk lives on a device's stack.
  union {
    std::array<std::array<Point3<std::int64_t>, 8>, kMaxRenderDepth> screen_offset_{};
    std::array<std::array<Point3<std::int32_t>, 8>, kMaxRenderDepth> narrow_offset_;
  };
  Point3<std::int64_t> half_{};  // voxelHalfExtent of that subtree, widened for its nearest voxels
  Point3<std::int64_t> shadow_{};  // its map's cube shadow (cubeShadow)
  int affine_level_ = 0;           // its root's level
  int affine_bucket_ = 0;          // the bucket of tables_.affine_depth it qualified by (judge)
};

}  // namespace octopoint

namespace octopoint {

// Draws `level` into `frame` (cleared by the caller): each leaf covers the pixels whose centres lie
// within its voxel's projected extent (padded by the rounding), or its one pixel where that
// extent holds no pixel centre; its position is within `max_error` plus depth / 2 units in the
// last place of its exact projection, plus what its camera-space centre's rounding moves it: half
// a Q.24 unit (at most 1/8 pixel, nearPlaneFloor) and the walk's sums (at most 1/8 pixel,
// walkFractionBits). False when aborted. A frame cleared with
// PixelPayload::kColourNormal takes each leaf's normal index and the depth code of
// renderer/perspective_depth.h (false, nothing drawn, for a level without normals).
bool drawPerspective(const LevelView& level, const PerspectiveView& view,
                     const PerspectiveWalkTables& tables, FrameView& frame,
                     const std::atomic<bool>* abort = nullptr);

// One stored depth a frame may draw: its stream, its walk's tables for the frame, and its upper
// tree index (may be null: stream order, and no subtree passed over unread).
struct PerspectiveLayer {
  const LevelView* level = nullptr;
  const PerspectiveWalkTables* tables = nullptr;
  const UpperTreeIndex* index = nullptr;
};

// What a frame drew, for the benchmark and the tests.
struct PerspectiveDrawStats {
  std::uint64_t leaves = 0;           // handed to the plot (each writes its splat)
  std::uint64_t hidden_subtrees = 0;  // passed over by occlusion culling
};

// Draws a frame into `frame` (cleared by the caller) from `layers` (ascending depths): with one
// layer all of it from that depth, as drawPerspective; with several, each part of the frame from
// the depth `detail` (made for the layers' depths) chooses for it, the finest's parts first (they
// are the nearest). With `occlusion` (tiles of this frame, reset by the caller after the clear)
// subtrees behind what is drawn are passed over: the same frame, bit for bit. `stats` may be
// null. With `band` (`frame` then holds the band's rows, `view` is shifted to them) only subtrees
// that may reach them are visited. False when aborted, or when `frame` carries normals
// (PixelPayload::kColourNormal, as drawPerspective) and a layer has none.
bool drawPerspectiveLayers(std::span<const PerspectiveLayer> layers,
                           const PerspectiveDetail* detail, const PerspectiveView& view,
                           FrameView& frame, OcclusionTiles* occlusion, PerspectiveDrawStats* stats,
                           const PerspectiveBand* band = nullptr,
                           const std::atomic<bool>* abort = nullptr);

}  // namespace octopoint
