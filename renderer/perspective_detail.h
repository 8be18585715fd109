#pragma once
// Detail by distance (docs/perspective.md): which of a model's stored depths draws each part of a
// perspective frame. The rule is depth auto's (docs/splats.md, "depth by projected size") evaluated
// per node with the node's own distance: a voxel of depth d at camera-space depth z spans
// e = f * 2^-d / z pixels (f the focal length in pixels, z in cube edges), and a node asks for
// the coarsest stored depth whose voxel at the node's NEAREST depth spans at most a pixel (the
// finest when none does). Along a path from the root the ask is kept as a running minimum
// (chosen), so it never grows on the way down.
//
// A voxel V of stored depth d_j is drawn exactly when its ancestor at the next coarser stored depth
// d_(j-1) chose a depth of at least d_j (it wanted finer than itself) and V chose at most d_j (it
// is fine enough). Along any path the chosen depths fall, so exactly one stored depth draws each
// point of space: no part twice, none left out (the walk of each depth skips what others draw,
// every depth's walk computes the same node centres, so they agree). Integer only: per node, the
// comparison of its nearest and farthest depth with a table of thresholds.

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/perspective.h"

namespace octopoint {

// Once per frame: the stored depths a frame chooses among and the distance from which each is
// fine enough.
struct PerspectiveDetail {
  int count = 0;                                // stored depths, at most format::kMaxLevels
  std::array<int, format::kMaxLevels> depth{};  // ascending
  // near_enough[i]: the least camera-space depth (Q.24 cube edges) at which a voxel of depth[i]
  // spans at most one pixel: f * 2^(24 - depth) / 1 pixel, rounded up. Descending in i.
  std::array<std::int64_t, format::kMaxLevels> near_enough{};
  // A node of tree level l lies within reach[l] (Q.24) of its camera-space centre on every axis,
  // its centre's rounding included: the same for every depth, so that every depth's walk decides
  // alike.
  std::array<std::int64_t, kMaxRenderDepth + 1> reach{};

  // The index of the coarsest depth fine enough at camera-space depth z (Q.24); the finest when
  // none is (z below every threshold: near the eye or behind it).
  // Never finer than `finest` (the model's finest held depth there, below).
  int ask(std::int64_t z) const {
    for (int i = 0; i < finest; ++i) {
      if (z >= near_enough[static_cast<std::size_t>(i)]) return std::max(0, i - coarser);
    }
    return std::max(0, finest - coarser);
  }
  // Asks this many stored depths coarser (never past the coarsest): the interactive viewer's
  // coarse frames, drawn while the eye moves. Still non-increasing in z, so the rule below holds.
  int coarser = 0;
  // The finest depth (an index) any node asks for: count - 1, or less where the model holds only
  // the coarser depths of the list (a partly held chunked model, renderer/chunked_assembly.h:
  // each held part drawn with the detail of the whole list, so that a part holding every depth
  // draws what the whole model draws, and capped at the part's finest depth).
  int finest = 0;
};

// Q.8 pixels: one pixel, the size on screen up to which a voxel is fine enough (depth auto's rule).
inline constexpr std::uint32_t kOnePixelQ8 = 256;

// `depths`: ascending, 1..kMaxRenderDepth, 1 to format::kMaxLevels of them. `coarser` (0..8)
// makes every node ask for that many stored depths coarser than its distance asks (never past the
// coarsest): the interactive viewer's coarse frames, drawn while the eye moves. `pixels_q8`
// (Q.8 pixels, kOnePixelQ8..2^24): the size on screen a voxel may span and still be fine enough;
// larger, every part of the frame is drawn coarser where its voxels are smallest on screen, the
// far parts first (a point budget: tools/perspective_render.h).
PerspectiveDetail perspectiveDetail(const PerspectiveView& view, std::span<const int> depths,
                                    int coarser = 0, std::uint32_t pixels_q8 = kOnePixelQ8);

// What the walk of one stored depth (index `layer` of the detail's depths) carries down a path.
struct DetailState {
  std::uint8_t chosen = 0;    // the running minimum of the path's asks (an index)
  bool ancestors_ok = false;  // the node at the next coarser depth, on or above this path,
                              // chose at least this layer (or this layer is the coarsest)
  bool committed = false;     // this layer draws the whole subtree: no more checks
};

enum class DetailVerdict : std::uint8_t { kOthers, kThisLayer };

// The walk of one stored depth: the verdict on an inner node of tree `level` whose camera-space
// centre has depth `z` (state updated for its children): kOthers when other depths draw all of
// it (passed over), else kThisLayer (state.committed: all of it).
struct DetailPass {
  const PerspectiveDetail* detail = nullptr;  // none: a single depth draws everything
  int layer = 0;
  int coarser_depth = -1;  // depth[layer - 1], or -1 for the coarsest

  DetailState start() const {
    DetailState state;
    state.chosen = static_cast<std::uint8_t>(detail == nullptr ? 0 : detail->count - 1);
    state.ancestors_ok = layer == 0;
    state.committed = detail == nullptr || detail->count == 1;
    return state;
  }

  DetailVerdict node(int level, std::int64_t z, DetailState& state) const {
    const std::int64_t reach = detail->reach[static_cast<std::size_t>(level)];
    const int chosen = std::min<int>(state.chosen, detail->ask(z - reach));
    const int lowest = std::min(chosen, detail->ask(z + reach));  // no voxel inside asks less
    if (lowest > layer) return DetailVerdict::kOthers;            // finer depths draw it all
    if (!state.ancestors_ok) {  // level <= coarser_depth: not yet past the coarser depth's voxel
      if (chosen < layer) return DetailVerdict::kOthers;  // coarser depths draw it all
      state.ancestors_ok = lowest >= layer || level == coarser_depth;
    }
    state.chosen = static_cast<std::uint8_t>(chosen);
    state.committed = state.ancestors_ok && chosen <= layer;
    return DetailVerdict::kThisLayer;
  }

  // Whether this layer draws its leaf at camera-space depth `z` (not yet committed).
  bool drawsLeaf(int level, std::int64_t z, const DetailState& state) const {
    const std::int64_t reach = detail->reach[static_cast<std::size_t>(level)];
    return std::min<int>(state.chosen, detail->ask(z - reach)) <= layer;
  }
};

}  // namespace octopoint
