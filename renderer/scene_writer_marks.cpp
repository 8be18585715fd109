// SceneRenderer::markWriters: which instances would write a pixel of a z-buffer that holds a given
// depth map (the visibility cells' occlusion map, tools/cell_occlusion.h). Each instance is drawn
// alone into the map and the pixels it wrote are put back before the next, so a nearer instance
// never hides a farther one: only the map occludes. And the pixel winners (setPixelWinners): which
// instance wrote the word each pixel keeps.
#include <algorithm>

#include "renderer/scene_renderer.h"
#include "renderer/scene_view.h"

namespace octopoint {

std::size_t SceneRenderer::markWriters(const PerspectiveView& view,
                                       std::span<const std::uint32_t> depth_map,
                                       std::span<std::uint32_t> work,
                                       std::span<std::uint8_t> marks) {
  const std::int32_t width = view.camera.width, height = view.camera.height;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (!valid_ || depth_map.size() != pixels || work.size() != pixels) return 0;
  std::copy(depth_map.begin(), depth_map.end(), work.begin());
  RectFrame frame(work.data(), width, height);
  frame.forgetDrawn();
  if (width != tiles_width_ || height != tiles_height_) {
    tiles_.assign(occlusionTileCount(width, height, kOcclusionTileShift), {});
    tiles_width_ = width;
    tiles_height_ = height;
  }
  OcclusionTiles occlusion(frame, tiles_, kOcclusionTileShift);
  occlusion.reset();
  occlusion.touched(0, width - 1, 0, height - 1);  // the map's words: scanned when first asked
  SceneDrawStats counted;
  const std::size_t count = orderInView(view, counted);
  std::size_t drawn = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t id = order_[k].instance;
    const SceneInstance& instance = instances_[id];
    // Wholly behind the map: no point of it can write a pixel.
    if (instanceHidden(view, instance.transform, order_[k].box,
                       depth_shift_ - instance.transform.scale, occlusion)) {
      continue;
    }
    PerspectiveView model_view;
    PerspectiveLayers layers;
    if (!layersOf(view, instance, &model_view, &layers) || layers.count == 0) continue;
    static_cast<void>(drawPerspectiveLayers(layers.layers(), &layers.detail, model_view, frame,
                                            &occlusion, &counted.points, nullptr, nullptr));
    ++drawn;
    const PixelRect rect = frame.drawnRect();
    bool wrote = false;
    for (std::int32_t y = rect.y_begin; y < rect.y_end; ++y) {
      const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
      for (std::int32_t x = rect.x_begin; x < rect.x_end; ++x) {
        const std::size_t i = row + static_cast<std::size_t>(x);
        if (work[i] != depth_map[i]) {
          wrote = true;
          work[i] = depth_map[i];
        }
      }
    }
    if (!rect.empty()) {
      // Put back: the tiles that saw this instance's words must be scanned again.
      occlusion.touched(rect.x_begin, rect.x_end - 1, rect.y_begin, rect.y_end - 1);
    }
    frame.forgetDrawn();
    if (wrote && id < marks.size()) marks[id] = 1;
  }
  return drawn;
}

void SceneRenderer::setPixelWinners(std::span<std::uint32_t> winners) { winners_ = winners; }

void SceneRenderer::takeWinners(RectFrame& frame, std::uint32_t id) {
  const PixelRect rect = frame.drawnRect();
  const std::span<const std::uint32_t> words = frame.pixels();
  const std::size_t width = static_cast<std::size_t>(frame.width());
  for (std::int32_t y = rect.y_begin; y < rect.y_end; ++y) {
    for (std::int32_t x = rect.x_begin; x < rect.x_end; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
      if (words[i] != before_[i]) {
        before_[i] = words[i];
        winners_[i] = id;
      }
    }
  }
  frame.forgetDrawn();
}

}  // namespace octopoint
