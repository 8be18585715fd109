#pragma once
// What the perspective walk (renderer/perspective_walk.h) hands over and takes: a leaf, a subtree
// drawn from one affine map, a band's rows and the walk's optional parts; in a header of their own
// so that the walk's stays small.

#include <array>
#include <cstddef>
#include <cstdint>

#include "renderer/perspective.h"
#include "renderer/perspective_detail.h"
#include "renderer/upper_tree_index.h"

namespace octopoint {

// A leaf as the walk hands it over: its index in the level's leaf stream (and payload: palette
// index, and normal index << 8 when the level has normals and the walk reads them), its screen
// position in Q(32-F).F pixels (int64: a leaf may lie far off the screen) and its camera-space
// depth in Q.24 cube edges.
struct PerspectiveLeaf {
  std::size_t index = 0;
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
  // Half the voxel's projected extent per screen axis, Q(32-F).F: from the affine map of the
  // subtree it was drawn with, or at the leaf itself (0 when even that cannot be had).
  std::int64_t half_x = 0;
  std::int64_t half_y = 0;
};

// A subtree the walk draws from one affine map, announced to a sink that has enterAffine (and
// leaveAffine, called when its last leaf was handed over): every leaf it hands over meanwhile
// lies within `reach_x`, `reach_y` (Q(32-F).F) and `reach_z` (Q.24) of `centre`, and has the
// half extents `half_x`, `half_y`. A sink may then drop what it checks per leaf.
struct AffineSubtree {
  Point3<std::int64_t> centre;
  std::int64_t reach_x = 0, reach_y = 0, reach_z = 0;
  std::int64_t half_x = 0, half_y = 0;
};

// The rows of one band of a frame, as the eye sees them: every point drawn into the band has a
// camera-space y / z within [top_q30, bottom_q30] (Q.30; the band's rows widened by a margin, so
// that a subtree passed over writes nothing into them).
struct PerspectiveBand {
  std::int64_t top_q30 = 0;
  std::int64_t bottom_q30 = 0;
};

// What a walk may use besides its level's stream, each optional.
struct PerspectiveWalkParts {
  // Random access to the stream's upper levels: above its bottom the walk visits a node's children
  // nearest the eye first (so that occlusion culling finds the near surfaces drawn first) and
  // passes over a subtree without reading its bytes.
  const UpperTreeIndex* index = nullptr;
  // Detail by distance: this walk draws only the parts of the frame its depth is chosen for
  // (DetailPass::detail null: all of it).
  DetailPass detail;
  // Occlusion culling: the sink has hidden(const AffineSubtree&) and drawn(const AffineSubtree&);
  // subtrees drawn from an affine map, and their leaves' grandparents, are asked whether they
  // are hidden before they are drawn, and say where they drew.
  bool cull = false;
  // A band of the frame's rows (renderer/perspective_bands.h): subtrees wholly above or below it
  // as the eye sees it are passed over too, and so are leaves near the eye, before their
  // projection, and the nodes of a subtree drawn from one map that write nothing in it. Null:
  // the whole frame.
  const PerspectiveBand* band = nullptr;
};

// fillScreenOffsets' roundings, in Sum (int32 or int64).
template <typename Sum, typename Int>
void roundScreenOffsets(int level, int depth, const Point3<std::int64_t> (&sums)[4],
                        std::array<std::array<Point3<Int>, 8>, kMaxRenderDepth>& offsets) {
  for (int m = level; m < depth; ++m) {
    const int shift = m + 2;
    const Sum round = Sum{1} << (shift - 1);
    auto& level_offsets = offsets[static_cast<std::size_t>(m)];
    for (unsigned k = 0; k < 4; ++k) {
      const auto x = static_cast<Int>((static_cast<Sum>(sums[k].x) + round) >> shift);
      const auto y = static_cast<Int>((static_cast<Sum>(sums[k].y) + round) >> shift);
      const auto z = static_cast<Int>((static_cast<Sum>(sums[k].z) + round) >> shift);
      level_offsets[k] = {x, y, z};
      level_offsets[7 - k] = {static_cast<Int>(-x), static_cast<Int>(-y), static_cast<Int>(-z)};
    }
  }
}

// The screen vectors of a subtree of a level-depth tree drawn from one affine map
// (PerspectiveWalk::drawAffine), per level m from `level` down: each sum of the map's axis vectors
// with child k's signs (`sums`: children 0 to 3; child 7 - k is child k mirrored) times
// 2^-(m+2), rounded once (roundShiftRight, with the half added once per level: the sums are far
// below 2^62), into `offsets`: int64, or int32 where the walk's sink said every position of the
// subtree fits (then each vector does too: it is the difference of two of them, both in
// [0, 2^31)). On 32-bit ARM, where every sum lies within +-2^30 (a subtree of up to 2^(30-F)
// pixels a cube edge: most) the roundings are made in 32 bits, which cannot overflow (the half
// added is at most 2^16): the same values, and there a 64-bit shift by a variable is several
// instructions (a dozen on a Cortex-M0+); on a 64-bit host it is one, and the test cost more
// than it saved (callgrind: 0.7% of a 320x240 frame at 60 degrees).
template <typename Int>
void fillScreenOffsets(int level, int depth, const Point3<std::int64_t> (&sums)[4],
                       std::array<std::array<Point3<Int>, 8>, kMaxRenderDepth>& offsets) {
#if defined(__arm__)
  constexpr std::int64_t kNarrowSum = std::int64_t{1} << 30;
  bool narrow = true;
  for (const Point3<std::int64_t>& sum : sums) {
    for (const std::int64_t v : {sum.x, sum.y, sum.z})
      narrow = narrow && v > -kNarrowSum && v < kNarrowSum;
  }
  if (narrow) {
    roundScreenOffsets<std::int32_t>(level, depth, sums, offsets);
  } else {
    roundScreenOffsets<std::int64_t>(level, depth, sums, offsets);
  }
#else
  roundScreenOffsets<std::int64_t>(level, depth, sums, offsets);
#endif
}

}  // namespace octopoint
