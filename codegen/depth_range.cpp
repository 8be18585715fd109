#include "codegen/depth_range.h"

#include <algorithm>
#include <optional>

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
