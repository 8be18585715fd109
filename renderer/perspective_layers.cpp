#include "renderer/perspective_layers.h"

#include <algorithm>

#include "renderer/level_of_detail.h"

namespace octopoint {

PerspectiveLayers perspectiveLayers(const ModelView& model, const PerspectiveView& view, int depth,
                                    std::span<const UpperTreeIndex> indexes,
                                    std::span<PerspectiveWalkTables> tables, int coarser,
                                    std::span<const int> detail_depths, std::uint32_t pixels_q8) {
  // The levels this build draws: a prefix, the levels being ascending.
  // A depth sampled more coarsely than its voxels whose stored reach draws it whole counts as
  // dense, as depth auto counts it (autoLevel).
  std::array<std::uint64_t, format::kMaxLevels> voxels{};
  std::array<std::int32_t, format::kMaxLevels> reaches{};
  std::size_t drawable = 0;
  while (drawable < static_cast<std::size_t>(model.levelCount()) &&
         model.level(static_cast<int>(drawable)).depth <= kMaxRenderDepth) {
    voxels[drawable] = model.level(static_cast<int>(drawable)).leaves.size();
    reaches[drawable] = model.sampleReach(static_cast<int>(drawable));
    ++drawable;
  }
  std::size_t first = 0, count = denseDepthCount(std::span(voxels).first(drawable),
                                                 std::span(reaches).first(drawable));
  if (!detail_depths.empty()) {
    // The model holds a prefix of these depths: detail by distance over all of them, capped.
    count = std::min(drawable, detail_depths.size());
    for (std::size_t i = 0; i < count; ++i) {
      if (model.level(static_cast<int>(i)).depth != detail_depths[i]) return {};
    }
  }
  if (depth != 0) {
    first = drawable;
    for (std::size_t i = 0; i < drawable; ++i) {
      if (model.level(static_cast<int>(i)).depth == depth) first = i;
    }
    count = first == drawable ? 0 : 1;
  }
  PerspectiveLayers result;
  if (count == 0 || tables.size() < first + count) return result;
  // A quarter pixel: with the rounding of the additions, every leaf within half a pixel.
  const std::int64_t max_error = std::int64_t{1} << (view.fraction_bits - 2);
  std::array<int, format::kMaxLevels> depths{};
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t k = first + i;
    const LevelView& level = model.level(static_cast<int>(k));
    // Each depth's splats widened by its stored sample reach (docs/splats.md).
    tables[k] =
        perspectiveWalkTables(view, level.depth, max_error, model.sampleReach(static_cast<int>(k)));
    const UpperTreeIndex* index =
        k < indexes.size() && indexes[k].bottom >= 0 ? &indexes[k] : nullptr;
    result.layer[i] = {&level, &tables[k], index};
    depths[i] = level.depth;
  }
  result.count = count;
  if (!detail_depths.empty() && depth == 0) {
    result.detail = perspectiveDetail(view, detail_depths, coarser, pixels_q8);
    result.detail.finest = static_cast<int>(count) - 1;
  } else {
    result.detail =
        perspectiveDetail(view, std::span<const int>(depths.data(), count), coarser, pixels_q8);
  }
  return result;
}

}  // namespace octopoint
