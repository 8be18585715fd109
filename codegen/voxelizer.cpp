#include "codegen/voxelizer.h"

#include <algorithm>
#include <cmath>
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

using Vec3f = std::array<float, 3>;

// Groups of normals agree within this angle (cos 30 degrees); a mean as long as kAgreeing (every
// normal within about 25 degrees of it) needs no grouping.
constexpr double kSameGroup = 0.8660254;
constexpr double kAgreeing = 0.9;
constexpr std::size_t kMostCandidates = 32;  // group seeds tried per voxel

double dot(const Vec3f& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The voxel's normal from its points' (unit or NaN) normals; `fallback` when none is known.
Vec3f voxelNormal(const std::vector<Vec3f>& normals, const Vec3f& fallback) {
  std::vector<const Vec3f*> known;
  std::array<double, 3> sum{};
  for (const Vec3f& n : normals) {
    if (!std::isfinite(n[0])) continue;
    known.push_back(&n);
    for (std::size_t axis = 0; axis < 3; ++axis) sum[axis] += n[axis];
  }
  if (known.empty()) return fallback;
  auto unit = [](const std::array<double, 3>& v) {
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return Vec3f{static_cast<float>(v[0] / length), static_cast<float>(v[1] / length),
                 static_cast<float>(v[2] / length)};
  };
  const double length = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
  if (length >= kAgreeing * static_cast<double>(known.size())) return unit(sum);
  // Disagreement: the seed with the most normals within kSameGroup of it, then their mean.
  const std::size_t stride = std::max<std::size_t>(known.size() / kMostCandidates, 1);
  std::size_t best_count = 0;
  std::array<double, 3> best_sum{};
  for (std::size_t s = 0; s < known.size(); s += stride) {
    const std::array<double, 3> seed = {(*known[s])[0], (*known[s])[1], (*known[s])[2]};
    std::size_t count = 0;
    std::array<double, 3> group{};
    for (const Vec3f* n : known) {
      if (dot(*n, seed) < kSameGroup) continue;
      ++count;
      for (std::size_t axis = 0; axis < 3; ++axis) group[axis] += (*n)[axis];
    }
    if (count > best_count) {
      best_count = count;
      best_sum = group;
    }
  }
  return unit(best_sum);
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

std::vector<std::uint64_t> occupiedVoxelKeys(const Scan& scan, const CubeFit& fit, int depth) {
  std::vector<std::uint64_t> keys;
  keys.reserve(scan.positions.size());
  for (const auto& p : scan.positions) {
    keys.push_back(mortonKey(voxelIndex(p[0], fit.origin[0], fit.edge, depth),
                             voxelIndex(p[1], fit.origin[1], fit.edge, depth),
                             voxelIndex(p[2], fit.origin[2], fit.edge, depth), depth));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
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
  const bool has_normals = !scan.normals.empty();
  std::vector<Vec3f> normals;
  for (std::size_t begin = 0; begin < keyed.size();) {
    std::size_t end = begin;
    std::array<std::uint64_t, 3> sum{};
    normals.clear();
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) {
      if (has_colour) {
        const Rgb8& c = scan.colours[keyed[end].second];
        for (std::size_t ch = 0; ch < 3; ++ch) sum[ch] += c[ch];
      }
      if (has_normals) normals.push_back(scan.normals[keyed[end].second]);
      ++end;
    }
    if (has_normals) {
      // A voxel without a known normal faces the sensor.
      const auto xyz = mortonDecode(keyed[begin].first, depth);
      const double cell = fit.edge / std::ldexp(1.0, depth);
      std::array<double, 3> toward_sensor{};
      for (std::size_t axis = 0; axis < 3; ++axis) {
        toward_sensor[axis] =
            scan.sensor_origin[axis] - (fit.origin[axis] + (xyz[axis] + 0.5) * cell);
      }
      const double length =
          std::sqrt(toward_sensor[0] * toward_sensor[0] + toward_sensor[1] * toward_sensor[1] +
                    toward_sensor[2] * toward_sensor[2]);
      const Vec3f fallback = length > 0 ? Vec3f{static_cast<float>(toward_sensor[0] / length),
                                                static_cast<float>(toward_sensor[1] / length),
                                                static_cast<float>(toward_sensor[2] / length)}
                                        : Vec3f{0, 0, -1};
      voxels.normals.push_back(voxelNormal(normals, fallback));
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
