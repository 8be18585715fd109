#include "renderer/perspective_renderer.h"

#include "renderer/level_of_detail.h"

namespace octopoint {

PerspectiveRenderer::PerspectiveRenderer(const ModelView& model) : model_(model) {
  std::array<std::uint64_t, format::kMaxLevels> voxels{};
  for (int i = 0; i < model.levelCount(); ++i) {
    const LevelView& level = model.level(i);
    if (level.depth > kMaxRenderDepth) break;  // ascending: every later one is deeper too
    depths_[count_] = level.depth;
    level_of_[count_] = i;
    voxels[count_] = level.leaves.size();
    ++count_;
  }
  dense_ = denseDepthCount(std::span(voxels).first(count_));
  index_storage_.resize(count_);
  for (std::size_t i = 0; i < count_; ++i) {
    const LevelView& level = model.level(level_of_[i]);
    index_storage_[i].resize(upperTreeEntries(level));
    indexes_[i] = buildUpperTreeIndex(level, index_storage_[i]);
  }
}

bool PerspectiveRenderer::draw(const PerspectiveView& view, const Options& options,
                               FrameView& frame, PerspectiveDrawStats* stats,
                               const std::atomic<bool>* abort) {
  // The layers drawn: one stored depth, or the densely sampled ones by distance.
  std::size_t first = 0, count = dense_;
  if (options.depth != 0) {
    first = count_;
    for (std::size_t i = 0; i < count_; ++i) {
      if (depths_[i] == options.depth) first = i;
    }
    if (first == count_) return false;
    count = 1;
  }
  if (count == 0) return false;
  // A quarter pixel: with the rounding of the additions, every leaf within half a pixel.
  const std::int64_t max_error = std::int64_t{1} << (view.fraction_bits - 2);
  std::array<PerspectiveLayer, format::kMaxLevels> layers{};
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t k = first + i;
    const LevelView& level = model_.level(level_of_[k]);
    tables_[k] = perspectiveWalkTables(view, level.depth, max_error);
    layers[i] = {&level, &tables_[k], indexes_[k].bottom >= 0 ? &indexes_[k] : nullptr};
  }
  const PerspectiveDetail detail =
      perspectiveDetail(view, std::span<const int>(depths_.data() + first, count), options.coarser);
  std::optional<OcclusionTiles> occlusion;
  if (options.cull) {
    if (frame.width() != tiles_width_ || frame.height() != tiles_height_ ||
        options.tile_shift != tiles_shift_) {
      tiles_.assign(occlusionTileCount(frame.width(), frame.height(), options.tile_shift), {});
      tiles_width_ = frame.width();
      tiles_height_ = frame.height();
      tiles_shift_ = options.tile_shift;
    }
    occlusion.emplace(frame, tiles_, options.tile_shift);
    occlusion->reset();
  }
  return drawPerspectiveLayers(std::span<const PerspectiveLayer>(layers.data(), count), &detail,
                               view, frame, occlusion ? &*occlusion : nullptr, stats, abort);
}

}  // namespace octopoint
