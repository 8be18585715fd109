#include "codegen/voxelizer.h"

#include <algorithm>
#include <utility>

namespace octopoint::prepare {
namespace {

// Grey levels of the depth shade: the nearest voxel gets kNearShade, the farthest kFarShade; the
// nearest stays well darker than the light background octopoint-render draws on (236).
constexpr int kNearShade = 190;
constexpr int kFarShade = 40;

void applyDepthShade(VoxelSet& voxels) {
  std::uint32_t near = UINT32_MAX;
  std::uint32_t far = 0;
  for (std::uint64_t key : voxels.keys) {
    const std::uint32_t z = mortonDecode(key, voxels.depth)[2];
    near = std::min(near, z);
    far = std::max(far, z);
  }
  for (std::size_t i = 0; i < voxels.keys.size(); ++i) {
    const std::uint8_t grey = depthShade(mortonDecode(voxels.keys[i], voxels.depth)[2], near, far);
    voxels.colours[i] = {grey, grey, grey};
  }
}

}  // namespace

std::uint8_t depthShade(std::uint32_t z, std::uint32_t near, std::uint32_t far) {
  const std::uint32_t span = std::max<std::uint32_t>(far - near, 1);
  return static_cast<std::uint8_t>(
      kNearShade -
      static_cast<int>((z - near) * static_cast<std::uint64_t>(kNearShade - kFarShade) / span));
}

std::array<std::uint32_t, 3> mortonDecode(std::uint64_t key, int depth) {
  std::array<std::uint32_t, 3> xyz{};
  for (int bit = 0; bit < depth; ++bit) {
    const auto digit = static_cast<std::uint32_t>(key >> (3 * bit)) & 7u;
    xyz[0] |= ((digit >> 2) & 1u) << bit;
    xyz[1] |= ((digit >> 1) & 1u) << bit;
    xyz[2] |= (digit & 1u) << bit;
  }
  return xyz;
}

VoxelSet voxelize(const Scan& scan, const CubeFit& fit, int depth) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(scan.positions.size());
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    const auto& p = scan.positions[i];
    keyed[i] = {mortonKey(voxelIndex(p[0], fit.origin[0], fit.edge, depth),
                          voxelIndex(p[1], fit.origin[1], fit.edge, depth),
                          voxelIndex(p[2], fit.origin[2], fit.edge, depth), depth),
                static_cast<std::uint32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());

  VoxelSet voxels;
  voxels.depth = depth;
  const bool has_colour = !scan.colours.empty();
  for (std::size_t begin = 0; begin < keyed.size();) {
    std::size_t end = begin;
    std::array<std::uint64_t, 3> sum{};
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) {
      if (has_colour) {
        const Rgb8& c = scan.colours[keyed[end].second];
        for (std::size_t ch = 0; ch < 3; ++ch) sum[ch] += c[ch];
      }
      ++end;
    }
    const std::uint64_t count = end - begin;
    Rgb8 mean{};
    for (std::size_t ch = 0; ch < 3; ++ch) {
      mean[ch] = static_cast<std::uint8_t>((sum[ch] + count / 2) / count);  // rounded mean
    }
    voxels.keys.push_back(keyed[begin].first);
    voxels.colours.push_back(mean);
    begin = end;
  }
  if (!has_colour) applyDepthShade(voxels);
  return voxels;
}

}  // namespace octopoint::prepare
