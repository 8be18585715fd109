#pragma once
// The stored depths a perspective frame draws and each one's walk tables (docs/perspective.md,
// "Detail by distance"), made once per frame in storage the caller gives: what
// PerspectiveRenderer (the desktop, which keeps its indexes on the heap) and the band renderer of
// a microcontroller (renderer/perspective_bands.h, static storage) share, so that both draw the
// same frame.

#include <array>
#include <cstddef>
#include <span>

#include "octopoint/model.h"
#include "renderer/perspective.h"
#include "renderer/perspective_detail.h"
#include "renderer/perspective_walk.h"
#include "renderer/upper_tree_index.h"

namespace octopoint {

struct PerspectiveLayers {
  std::array<PerspectiveLayer, format::kMaxLevels> layer{};  // ascending depths
  std::size_t count = 0;                                     // 0: nothing to draw
  PerspectiveDetail detail;                                  // for the layers' depths

  std::span<const PerspectiveLayer> layers() const { return {layer.data(), count}; }
};

// For a frame of `view` from `model`: the stored depth `depth`, or with 0 detail by distance over
// the model's densely sampled depths (docs/splats.md) up to kMaxRenderDepth; each drawn from its
// upper tree index `indexes[i]` (i the model's level index; bottom -1 or absent: none) and walked
// with tables[i] (filled here: at least as many as the model's levels up to kMaxRenderDepth), every
// leaf within a quarter pixel plus the additions' rounding of its exact projection. count 0 when
// the model stores no such depth (or this build draws none so deep). `coarser`: as
// perspectiveDetail's (the viewer's coarse frames while the eye moves; 0 elsewhere).
// `detail_depths` (ascending; empty: the model's densely sampled depths): the depths detail by
// distance chooses among, of which the model holds the first ones (a part of a partly held chunked
// model, renderer/chunked_assembly.h): the frame is the whole list's, each part at most as fine as
// the model's finest of them. count 0 when the model's depths are not a prefix of the list.
PerspectiveLayers perspectiveLayers(const ModelView& model, const PerspectiveView& view, int depth,
                                    std::span<const UpperTreeIndex> indexes,
                                    std::span<PerspectiveWalkTables> tables, int coarser = 0,
                                    std::span<const int> detail_depths = {},
                                    std::uint32_t pixels_q8 = kOnePixelQ8);

}  // namespace octopoint
