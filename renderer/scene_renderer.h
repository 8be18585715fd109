#pragma once
// Draws a scene of many models (octopoint/scene.h, docs/city.md) in perspective into one frame:
// each instance as its model is drawn alone by the inverse camera (renderer/scene_view.h), with
// detail by distance, nearest instance first, and occlusion culling across instances (one set of
// tiles for the frame: what a near building hides of a far one is passed over). Instances wholly
// outside the frustum, or beyond the draw distance (more than kMaxEyeDistance of their own cube
// edges from the eye), cost a few products each and are not drawn.
//
// Memory: per distinct model its upper tree indexes (as PerspectiveRenderer keeps them); per
// instance its transform and a sort slot, sized when the scene is made; the occlusion tiles once
// per framebuffer size. A frame allocates nothing after the first of its size. Not on a
// bare-metal build (it keeps these on the heap). Integer only.

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/scene.h"
#include "renderer/occlusion_tiles.h"
#include "renderer/perspective.h"
#include "renderer/perspective_layers.h"
#include "renderer/perspective_renderer.h"
#include "renderer/perspective_walk.h"
#include "renderer/scene_view.h"

namespace octopoint {

// What a scene frame drew.
struct SceneDrawStats {
  std::uint64_t instances_drawn = 0;
  std::uint64_t outside_frustum = 0;  // instances passed over by the frustum test
  std::uint64_t beyond_reach = 0;     // instances beyond the draw distance
  std::uint64_t occluded = 0;   // instances in view whose box nearer instances hid (not set up)
  PerspectiveDrawStats points;  // summed over the drawn instances
};

class SceneRenderer {
 public:
  // `models` (each must outlive the renderer) and the instances; `*error` says why a scene is
  // refused (then nothing is drawn). `detail_depths`, when given, one list per model (ascending;
  // an empty list: the model's densely sampled depths): the depths detail by distance chooses
  // among for that model, as PerspectiveRenderer's (a part of a partly held chunked model,
  // renderer/chunked_assembly.h, holds only the first of them: a scene streaming in,
  // renderer/held_scene.h).
  SceneRenderer(std::span<const ModelView* const> models, std::span<const SceneInstance> instances,
                SceneError* error, std::span<const std::vector<int>> detail_depths = {});

  std::size_t instanceCount() const { return instances_.size(); }
  const SceneInstance& instance(std::size_t i) const { return instances_[i]; }
  // The scene's depth shift (renderer/scene_view.h: sceneDepthShift of its largest scale).
  int depthShift() const { return depth_shift_; }

  // Moves instance `i` (containers, cranes): the next frame draws it there. Refused (and the
  // instance left where it was) for a bad transform, an unknown instance, or a scale larger than
  // the largest the scene was made with (the depth keys' shift is fixed with the scene).
  SceneError place(std::size_t i, const InstanceTransform& transform);

  // Draws the scene as `view` sees it (the eye in Q.24 scene edges about the scene's origin) into
  // `frame` (cleared by the caller, the view's size). False when the scene was refused or when
  // aborted.
  bool draw(const PerspectiveView& view, FrameView& frame, SceneDrawStats* stats = nullptr,
            const std::atomic<bool>* abort = nullptr);

  // What draw does per frame before any point is drawn (the instances' boxes, the frustum test,
  // the nearest-first order, each instance's view and walk tables), without drawing: the
  // benchmark's measure of the set-up (bench/scene_bench.cpp). Returns the instances set up.
  std::size_t setUp(const PerspectiveView& view, SceneDrawStats* stats = nullptr);

  // Visibility cells (renderer/cell_table.h, docs/city.md): from now on draw and setUp consider
  // only the instances `ids` (sorted, distinct; the caller's memory, kept alive while it is set);
  // the others cost nothing per frame. Ids past the instances are passed over.
  void setVisibleSet(std::span<const std::uint32_t> ids);
  // Back to every instance.
  void clearVisibleSet();
  // Detail by distance from now on: each instance `coarser` stored depths coarser than its
  // distance asks, 0..8 (the viewer's coarse frames: 1; PerspectiveRenderer::Options::coarser).
  void setCoarser(int coarser) { coarser_ = coarser < 0 ? 0 : (coarser > 8 ? 8 : coarser); }
  // For computing the cells (tools/cell_build.h): from now on draw sets marks[i] to 1 for each
  // instance i that submitted a point, its subtrees not all passed over by the frustum or the
  // occlusion tiles (the caller's memory, at least instanceCount() bytes); empty to stop.
  void setSubmittedMarks(std::span<std::uint8_t> marks);
  // For computing the cells by who wins each pixel (tools/cell_build.h): from now on draw sets
  // winners[p] to i for each pixel p of a kColour frame whose word instance i wrote last (the word
  // the frame keeps); the other pixels keep what the caller put there. `winners` is the caller's
  // memory, the frame's size, row-major (another size: ignored); empty to stop. The frame drawn is
  // the same bit for bit (it then counts as wholly drawn until its next clear); it costs a copy of
  // the frame's words and a scan of each instance's written rectangle.
  void setPixelWinners(std::span<std::uint32_t> winners);
  // For computing the cells from an occlusion depth map (tools/cell_occlusion.h): sets marks[i]
  // to 1 for each instance i in view with a point that writes a pixel of a z-buffer holding
  // `depth_map` (words of a PixelPayload::kColour frame of the view's size, row-major): a word
  // smaller than the map's there. Each instance is tested against the map alone, never against
  // the others (a nearer instance's pixels do not hide a farther one's here: the map stands for
  // all occlusion). `work` (the map's size) is the z-buffer drawn into, restored to the map after
  // each instance; `marks` at least instanceCount() bytes. Returns the instances drawn. Allocates
  // nothing after the first call of its size. False-free: an instance left unmarked writes no
  // pixel (the box test and the walk's culling against the map's tiles are exact bounds).
  std::size_t markWriters(const PerspectiveView& view, std::span<const std::uint32_t> depth_map,
                          std::span<std::uint32_t> work, std::span<std::uint8_t> marks);

 private:
  // A frame over another's words whose drawn rectangle can be forgotten: after each instance,
  // drawnRect() is what that instance may have written (markWriters, the pixel winners).
  class RectFrame : public FrameView {
   public:
    using FrameView::FrameView;
    void forgetDrawn() { drawn_ = {}; }
  };
  // The pixels of `frame`'s drawn rectangle whose words differ from before_: instance `id` wrote
  // them (winners_), and before_ takes their words. Then the rectangle is forgotten.
  void takeWinners(RectFrame& frame, std::uint32_t id);

  struct Slot {
    std::int64_t nearest = 0;  // the box's nearest camera-space depth, scene units (sort key)
    std::uint32_t instance = 0;
    InstanceBox box;  // in its model's units (renderer/scene_view.h)
  };

  std::vector<const ModelView*> models_;
  std::vector<std::unique_ptr<PerspectiveRenderer>> renderers_;  // per model: its indexes
  std::vector<std::vector<int>> detail_depths_;  // per model: the constructor's (empty: its own)
  // The instances in view, nearest first, in order_: their count.
  std::size_t orderInView(const PerspectiveView& view, SceneDrawStats& counted);
  // Instance `instance`'s model view and layers; false when the camera cannot reach it.
  bool layersOf(const PerspectiveView& view, const SceneInstance& instance,
                PerspectiveView* model_view, PerspectiveLayers* layers);

  std::vector<SceneInstance> instances_;
  std::vector<Slot> order_;  // this frame's instances to draw, nearest first
  std::array<PerspectiveWalkTables, format::kMaxLevels> tables_{};  // per instance drawn
  std::vector<OcclusionTile> tiles_;
  std::int32_t tiles_width_ = 0, tiles_height_ = 0;
  int depth_shift_ = kPerspectiveDepthShift;
  int largest_scale_ = 0;
  bool valid_ = false;
  int coarser_ = 0;                         // setCoarser's
  bool restricted_ = false;                 // only visible_ is drawn
  std::span<const std::uint32_t> visible_;  // setVisibleSet's ids
  std::span<std::uint8_t> marks_;           // setSubmittedMarks's
  std::span<std::uint32_t> winners_;        // setPixelWinners's
  std::vector<std::uint32_t> before_;       // the frame's words before the instance being drawn
};

}  // namespace octopoint
