#include "renderer/level_of_detail.h"

#include <algorithm>
#include <array>

namespace octopoint {
namespace {

// Whether a voxel of `depth` has an edge of at most one pixel for `camera`; nullopt if the camera
// is refused at that depth. The edge is zoom * min(width, height) / 2^depth pixels (at zoom 1 the
// cube's edge spans the shorter side), whatever the rotation; with the zoom in Q16.16 the test
// zoom_raw * min(width, height) <= 2^(16 + depth) is exact (both sides below 2^48).
std::optional<bool> edgeFitsAPixel(const Camera& camera, int depth) {
  if (!leafFootprint(camera, depth, kDefaultFractionBits)) return std::nullopt;
  const auto shorter_side = static_cast<std::uint64_t>(std::min(camera.width, camera.height));
  const auto zoom_raw = static_cast<std::uint64_t>(camera.zoom.raw());  // > 0: accepted above
  return zoom_raw * shorter_side <= std::uint64_t{1} << (Q16::kFractionBits + depth);
}

}  // namespace

std::size_t denseDepthCount(std::span<const std::uint64_t> voxels_per_depth,
                            std::span<const std::int32_t> sample_reaches) {
  std::size_t kept = std::min<std::size_t>(1, voxels_per_depth.size());
  while (kept < voxels_per_depth.size() &&
         ((kept < sample_reaches.size() && sample_reaches[kept] > kOneSampleReach) ||
          sampledDensely(voxels_per_depth[kept], voxels_per_depth[kept - 1]))) {
    ++kept;
  }
  return kept;
}

std::optional<int> autoDepth(std::span<const int> stored_depths, const Camera& camera) {
  std::optional<int> finest_accepted;
  for (const int depth : stored_depths) {  // coarsest first
    const std::optional<bool> fits = edgeFitsAPixel(camera, depth);
    if (!fits) continue;
    if (*fits) return depth;
    finest_accepted = depth;
  }
  return finest_accepted;
}

std::optional<int> neededDepth(const Camera& camera) {
  std::array<int, format::kMaxDepth> every_depth{};
  for (int d = 1; d <= format::kMaxDepth; ++d) every_depth[static_cast<std::size_t>(d - 1)] = d;
  return autoDepth(every_depth, camera);
}

const LevelView* autoLevel(const ModelView& model, const Camera& camera) {
  std::array<int, format::kMaxLevels> depths{};
  std::array<std::uint64_t, format::kMaxLevels> voxels{};
  const auto count = static_cast<std::size_t>(model.levelCount());
  for (std::size_t i = 0; i < count; ++i) {
    depths[i] = model.level(static_cast<int>(i)).depth;
    voxels[i] = model.level(static_cast<int>(i)).leaves.size();
  }
  // A depth the scan samples more coarsely than its voxels, but whose reach the model stores
  // (format version 6: more than one footprint), draws whole with it: it counts as dense.
  std::array<std::int32_t, format::kMaxLevels> reaches{};
  for (std::size_t i = 0; i < count; ++i) reaches[i] = model.sampleReach(static_cast<int>(i));
  const std::size_t dense =
      denseDepthCount(std::span(voxels).first(count), std::span(reaches).first(count));
  const std::optional<int> depth = autoDepth(std::span<const int>(depths.data(), dense), camera);
  return depth ? model.levelOfDepth(*depth) : nullptr;
}

}  // namespace octopoint
