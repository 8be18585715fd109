#include "codegen/normal_palette.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace octopoint::prepare {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kLloydPasses = 8;

float dot(const Normal3f& a, const Normal3f& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Normal3f normalized(const std::array<double, 3>& v) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(length > 0)) return {0, 0, -1};
  return {static_cast<float>(v[0] / length), static_cast<float>(v[1] / length),
          static_cast<float>(v[2] / length)};
}

// Q1.14, each component rounded; the validator accepts the small length error that leaves.
NormalQ14 toQ14(const Normal3f& n) {
  NormalQ14 q{};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    q[axis] = static_cast<std::int16_t>(std::lround(static_cast<double>(n[axis]) * 16384.0));
  }
  return q;
}

Normal3f fromQ14(const NormalQ14& q) {
  return normalized({q[0] / 16384.0, q[1] / 16384.0, q[2] / 16384.0});
}

std::size_t nearest(const std::vector<Normal3f>& entries, const Normal3f& n) {
  std::size_t best = 0;
  float best_dot = -2;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const float d = dot(entries[i], n);
    if (d > best_dot) {
      best_dot = d;
      best = i;
    }
  }
  return best;
}

// Lloyd passes on the sphere: each entry moves to the normalized mean of the normals nearest to
// it; an entry nobody is nearest to stays where it is.
void refine(std::vector<Normal3f>& entries, std::span<const Normal3f> normals, int passes) {
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<std::array<double, 3>> sum(entries.size(), {0, 0, 0});
    std::vector<std::size_t> members(entries.size(), 0);
    for (const Normal3f& n : normals) {
      const std::size_t i = nearest(entries, n);
      for (std::size_t axis = 0; axis < 3; ++axis) sum[i][axis] += n[axis];
      ++members[i];
    }
    for (std::size_t i = 0; i < entries.size(); ++i) {
      if (members[i] > 0) entries[i] = normalized(sum[i]);
    }
  }
}

// `count` of the normals, spread over the directions they take: the first is the first normal,
// each next the normal farthest (in angle) from all chosen so far (farthest-point sampling).
// Every normal then lies within the last chosen one's distance of some entry.
std::vector<Normal3f> farthestPoints(std::span<const Normal3f> normals, int count) {
  std::vector<Normal3f> chosen;
  if (normals.empty()) return chosen;
  std::vector<float> nearest_dot(normals.size(), -2.0f);
  std::size_t next = 0;
  while (static_cast<int>(chosen.size()) < count) {
    chosen.push_back(normals[next]);
    std::size_t farthest = 0;
    for (std::size_t i = 0; i < normals.size(); ++i) {
      nearest_dot[i] = std::max(nearest_dot[i], dot(normals[i], chosen.back()));
      if (nearest_dot[i] < nearest_dot[farthest]) farthest = i;
    }
    if (nearest_dot[farthest] >= 1.0f) break;  // every normal is an entry already
    next = farthest;
  }
  return chosen;
}

}  // namespace

std::vector<Normal3f> fibonacciSphere(int count) {
  std::vector<Normal3f> points;
  const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double r = std::sqrt(1.0 - z * z);
    points.push_back(
        normalized({r * std::cos(golden_angle * i), r * std::sin(golden_angle * i), z}));
  }
  return points;
}

NormalPalette NormalPalette::build(std::span<const Normal3f> normals, NormalPaletteKind kind,
                                   int entries) {
  assert(entries >= 1 && entries <= kNormalPaletteEntries);
  std::vector<Normal3f> unit = fibonacciSphere(entries);
  if (kind == NormalPaletteKind::kAdaptive && !normals.empty()) {
    unit = farthestPoints(normals, entries);
    refine(unit, normals, kLloydPasses);
  }
  NormalPalette palette;
  for (const Normal3f& n : unit) {
    palette.entries_.push_back(toQ14(n));
    palette.unit_.push_back(fromQ14(palette.entries_.back()));  // search what is stored
  }
  return palette;
}

std::uint8_t NormalPalette::indexOf(const Normal3f& normal) const {
  return static_cast<std::uint8_t>(nearest(unit_, normal));
}

double NormalPalette::errorDegrees(const Normal3f& normal) const {
  const double d = std::clamp(static_cast<double>(dot(unit_[indexOf(normal)], normal)), -1.0, 1.0);
  return std::acos(d) * 180.0 / kPi;
}

}  // namespace octopoint::prepare
