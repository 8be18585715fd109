#pragma once
// A model's perspective frames (docs/perspective.md), with detail by distance and occlusion
// culling: what outlives a frame is kept here, so that drawing one allocates nothing. Each
// stored depth's upper tree index is built once, with the renderer; the occlusion tiles once per
// framebuffer size (the first frame of a size). Not on a bare-metal build (it keeps them on the
// heap); there, the walk's parts take storage the caller provides (renderer/perspective_walk.h).

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "renderer/occlusion_tiles.h"
#include "renderer/perspective.h"
#include "renderer/perspective_walk.h"
#include "renderer/upper_tree_index.h"

namespace octopoint {

// Tiles of 4 x 4 pixels: the cheapest of 4, 8 and 16 by measurement (docs/perspective.md,
// "Occlusion culling": a stale tile is scanned again whole, and a smaller one is scanned less).
inline constexpr int kOcclusionTileShift = 2;

class PerspectiveRenderer {
 public:
  struct Options {
    int depth = 0;     // 0: detail by distance over the model's densely sampled depths; else this
                       // stored depth alone
    bool cull = true;  // occlusion culling (the same frame, bit for bit)
    int tile_shift = kOcclusionTileShift;  // its tiles: 2^shift pixels square, 1..6
    int coarser = 0;  // detail by distance: each part this many stored depths coarser than its
                      // distance asks, 0..8 (the viewer's coarse frames: 1)
    // Detail by distance: the size on screen (Q.8 pixels, kOnePixelQ8..2^24) a voxel may span
    // and still be fine enough; larger draws fewer points, the far parts coarser first (a point
    // budget, tools/perspective_render.h).
    std::uint32_t pixels_q8 = kOnePixelQ8;
  };

  // `model` must outlive the renderer. `detail_depths` (ascending; empty: the model's densely
  // sampled depths, docs/splats.md): the depths detail by distance chooses among when the model
  // holds only the first of them (a part of a partly held chunked model,
  // renderer/chunked_assembly.h): each part of the frame as the whole list would draw it, but never
  // finer than the model's finest.
  explicit PerspectiveRenderer(const ModelView& model, std::span<const int> detail_depths = {});

  // The depths detail by distance chooses among that the model holds.
  std::span<const int> detailDepths() const { return {depths_.data(), dense_}; }

  // Each drawn level's upper tree index, by the model's level index (perspectiveLayers takes
  // them): a scene of many models (renderer/scene_renderer.h) draws its instances of this model
  // with them, into one frame.
  std::span<const UpperTreeIndex> upperTreeIndexes() const { return {indexes_.data(), count_}; }

  // Draws `view` into `frame` (cleared by the caller; its size the view's): each leaf within a
  // quarter pixel plus the additions' rounding of its exact projection. False when the depth is
  // not one the model stores (or is deeper than this build draws), or when aborted.
  bool draw(const PerspectiveView& view, const Options& options, FrameView& frame,
            PerspectiveDrawStats* stats = nullptr, const std::atomic<bool>* abort = nullptr);

 private:
  const ModelView& model_;
  std::array<int, format::kMaxLevels> depths_{};         // of the levels drawn, ascending
  std::array<int, format::kMaxLevels> level_of_{};       // the model's level index of each
  std::size_t count_ = 0;                                // levels this build draws
  std::size_t dense_ = 0;                                // of them densely sampled
  std::array<int, format::kMaxLevels> detail_depths_{};  // the constructor's, when given
  std::size_t detail_count_ = 0;
  std::vector<std::vector<UpperTreeNode>> index_storage_;
  std::array<UpperTreeIndex, format::kMaxLevels> indexes_{};
  std::array<PerspectiveWalkTables, format::kMaxLevels> tables_{};  // per frame, by level
  std::vector<OcclusionTile> tiles_;
  std::int32_t tiles_width_ = 0, tiles_height_ = 0;
  int tiles_shift_ = 0;
};

}  // namespace octopoint
