#include "renderer/perspective_renderer.h"

#include <algorithm>

#include "renderer/level_of_detail.h"
#include "renderer/perspective_layers.h"

namespace octopoint {

PerspectiveRenderer::PerspectiveRenderer(const ModelView& model, std::span<const int> detail_depths)
    : model_(model) {
  std::array<std::uint64_t, format::kMaxLevels> voxels{};
  std::array<std::int32_t, format::kMaxLevels> reaches{};
  for (int i = 0; i < model.levelCount(); ++i) {
    const LevelView& level = model.level(i);
    if (level.depth > kMaxRenderDepth) break;  // ascending: every later one is deeper too
    depths_[count_] = level.depth;
    level_of_[count_] = i;
    voxels[count_] = level.leaves.size();
    reaches[count_] = model.sampleReach(i);
    ++count_;
  }
  // With the stored sample reaches: a depth they draw whole counts as dense (perspectiveLayers).
  dense_ = denseDepthCount(std::span(voxels).first(count_), std::span(reaches).first(count_));
  if (!detail_depths.empty()) {
    detail_count_ = std::min(detail_depths.size(), detail_depths_.size());
    std::copy_n(detail_depths.begin(), detail_count_, detail_depths_.begin());
    dense_ = std::min(count_, detail_count_);
  }
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
  const PerspectiveLayers layers = perspectiveLayers(
      model_, view, options.depth, std::span<const UpperTreeIndex>(indexes_.data(), count_),
      tables_, options.coarser, std::span<const int>(detail_depths_.data(), detail_count_),
      options.pixels_q8);
  if (layers.count == 0) return false;
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
  return drawPerspectiveLayers(layers.layers(), &layers.detail, view, frame,
                               occlusion ? &*occlusion : nullptr, stats, nullptr, abort);
}

}  // namespace octopoint
