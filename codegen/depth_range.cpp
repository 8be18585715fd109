#include "codegen/depth_range.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "codegen/sample_reach.h"
#include "octopoint/model.h"
#include "renderer/level_of_detail.h"

namespace octopoint::prepare {

std::vector<int> defaultDepths() {
  std::vector<int> depths;
  for (int d = kDefaultCoarsestDepth; d <= kDefaultFinestDepth; ++d) depths.push_back(d);
  return depths;
}

std::size_t denseDepthCount(std::span<const std::size_t> voxels_per_depth) {
  const std::vector<std::uint64_t> counts(voxels_per_depth.begin(), voxels_per_depth.end());
  return octopoint::denseDepthCount(counts);  // the renderer's depth auto cuts at the same depth
}

std::size_t drawableDepthCount(
    std::span<const int> depths, std::span<const std::size_t> voxels_per_depth,
    const std::function<std::vector<std::uint64_t>(std::size_t)>& keys_of,
    std::vector<std::int32_t>* kept_reaches) {
  if (kept_reaches != nullptr) kept_reaches->assign(1, kOneSampleReach);
  if (depths.empty()) return 0;
  // Finer than kMaxMeasuredDepth a reach is not measured (one footprint): the counts alone decide,
  // and no keys are decoded.
  const auto measured = [&](std::size_t i) { return depths[i] <= kMaxMeasuredDepth; };
  std::vector<std::uint64_t> coarse;
  if (measured(0)) coarse = keys_of(0);
  std::int32_t coarse_reach = kOneSampleReach;  // the coarsest depth's (measureSampleReaches)
  std::size_t kept = 1;
  for (; kept < depths.size(); ++kept) {
    const bool dense =
        octopoint::sampledDensely(voxels_per_depth[kept], voxels_per_depth[kept - 1]);
    MeasuredReach reach;
    std::vector<std::uint64_t> keys;
    if (measured(kept)) {
      keys = keys_of(kept);
      reach = measureReach(keys, depths[kept], coarse, depths[kept - 1], coarse_reach);
    }
    const bool reached = reach.reach > kOneSampleReach && reach.reach <= kMaxKeptSampleReach &&
                         reach.whole_in_every_view;
    if (!dense && !reached) break;
    if (kept_reaches != nullptr) kept_reaches->push_back(reach.reach);
    coarse = std::move(keys);
    coarse_reach = reach.reach;
  }
  return kept;
}

std::vector<int> neededDepthRange(std::span<const Camera> cameras) {
  int coarsest = format::kMaxDepth + 1, finest = 0;
  for (const Camera& camera : cameras) {
    const std::optional<int> depth = neededDepth(camera);
    if (!depth) continue;
    coarsest = std::min(coarsest, *depth);
    finest = std::max(finest, *depth);
  }
  if (finest == 0) return {};
  coarsest = std::max({1, coarsest - 1, finest - format::kMaxLevels + 1});
  std::vector<int> depths;
  for (int d = coarsest; d <= finest; ++d) depths.push_back(d);
  return depths;
}

std::string describeDepths(std::span<const int> depths) {
  if (depths.empty()) return "none";
  const bool consecutive = depths.back() - depths.front() + 1 == static_cast<int>(depths.size());
  if (consecutive && depths.size() > 1)
    return std::to_string(depths.front()) + ".." + std::to_string(depths.back());
  std::string text;
  for (const int d : depths) {
    if (!text.empty())
      text += ',';  // appended apart: GCC 12 warns falsely (-Wrestrict) on "," + string
    text += std::to_string(d);
  }
  return text;
}

}  // namespace octopoint::prepare
