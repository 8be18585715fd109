#include "tests/support/landscape.h"

#include <algorithm>
#include <cmath>

namespace octopoint::testing {
namespace {

constexpr int kTownBlocks = 12;          // buildings per side of the town's grid
constexpr double kTownOrigin = 300.0;    // the town's south-west corner, metres
constexpr double kBlockPitch = 30.0;     // one building per block, streets between
constexpr double kBuildingShare = 0.18;  // of all points, on roofs and walls
constexpr double kRoofShare = 0.6;       // of the building points
constexpr double kLakeLevel = 44.0;      // water below this height is flat and dark
constexpr double kRockLevel = 118.0;     // bare rock above this height
constexpr double kRangeNoise = 0.02;     // metres of measurement noise

// SplitMix64: a good 64-bit mix, so neighbouring indices give unrelated values.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Uniform numbers in [0, 1) drawn one after another from one point's hash.
class Draws {
 public:
  explicit Draws(std::uint64_t state) : state_(state) {}
  double next() {
    state_ = mix(state_);
    return static_cast<double>(state_ >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

std::uint8_t channel(double value) {
  return static_cast<std::uint8_t>(std::clamp(value, 0.0, 255.0));
}

struct Building {
  double x0, y0, x1, y1;  // footprint
  double base, top;
  bool red_roof;
};

Building building(int block) {
  Draws draws(mix(0xb1d1u + static_cast<std::uint64_t>(block)));
  const double cx = kTownOrigin + (block % kTownBlocks + 0.5) * kBlockPitch;
  const double cy = kTownOrigin + (block / kTownBlocks + 0.5) * kBlockPitch;
  const double half_w = 6 + 6 * draws.next();
  const double half_d = 6 + 6 * draws.next();
  Building b{cx - half_w, cy - half_d, cx + half_w, cy + half_d, 0, 0, draws.next() < 0.6};
  b.base = Landscape::groundHeight(cx, cy) - 1.0;  // foundations reach below the slope
  b.top = b.base + 7 + 35 * draws.next() * draws.next();
  return b;
}

LandscapePoint buildingPoint(Draws& draws) {
  const Building b = building(static_cast<int>(draws.next() * kTownBlocks * kTownBlocks));
  LandscapePoint p{};
  if (draws.next() < kRoofShare) {
    p.xyz = {b.x0 + (b.x1 - b.x0) * draws.next(), b.y0 + (b.y1 - b.y0) * draws.next(), b.top};
    const double tile = 20 * draws.next();
    p.rgb = b.red_roof ? std::array{channel(165 + tile), channel(58 + tile / 2), channel(42)}
                       : std::array{channel(100 + tile), channel(102 + tile), channel(112 + tile)};
  } else {  // a wall: walk the perimeter
    const double w = b.x1 - b.x0, d = b.y1 - b.y0;
    double s = (2 * w + 2 * d) * draws.next();
    const double z = b.base + (b.top - b.base) * draws.next();
    if (s < w)
      p.xyz = {b.x0 + s, b.y0, z};
    else if ((s -= w) < d)
      p.xyz = {b.x1, b.y0 + s, z};
    else if ((s -= d) < w)
      p.xyz = {b.x1 - s, b.y1, z};
    else
      p.xyz = {b.x0, b.y1 - (s - w), z};
    const bool window = std::fmod(z - b.base, 3.5) > 1.2 && std::fmod(s, 4.0) < 1.6;
    p.rgb = window ? std::array{channel(60), channel(80), channel(100)}
                   : std::array{channel(205 - 15 * draws.next()), channel(192), channel(160)};
  }
  return p;
}

LandscapePoint groundPoint(Draws& draws) {
  LandscapePoint p{};
  const double x = kLandscapeSize * draws.next();
  const double y = kLandscapeSize * draws.next();
  const double h = Landscape::groundHeight(x, y);
  const double shade = 25 * draws.next();
  const double town_end = kTownOrigin + kTownBlocks * kBlockPitch;
  const bool in_town = x > kTownOrigin && x < town_end && y > kTownOrigin && y < town_end;
  const bool street = in_town && (std::fmod(x - kTownOrigin, kBlockPitch) < 4 ||
                                  std::fmod(y - kTownOrigin, kBlockPitch) < 4);
  if (h < kLakeLevel) {
    p.xyz = {x, y, kLakeLevel};
    p.rgb = {channel(30 + shade / 2), channel(60 + shade), channel(95 + shade)};
  } else if (street) {
    p.xyz = {x, y, h};
    p.rgb = {channel(70 + shade), channel(70 + shade), channel(76 + shade)};
  } else if (h > kRockLevel) {
    p.xyz = {x, y, h};
    p.rgb = {channel(128 + shade), channel(122 + shade), channel(115 + shade)};
  } else {  // meadow, yellower up the slopes
    const double up = (h - kLakeLevel) / (kRockLevel - kLakeLevel);
    p.xyz = {x, y, h};
    p.rgb = {channel(55 + 90 * up + shade), channel(125 + 30 * up + shade), channel(40 + shade)};
  }
  return p;
}

}  // namespace

double Landscape::groundHeight(double x, double y) {
  return 60 + 40 * std::sin(x / 170) * std::cos(y / 130) +
         15 * std::sin(x / 37 + 1) * std::sin(y / 53) + 4 * std::sin(x / 9) * std::cos(y / 11) +
         0.03 * (x + y);
}

LandscapePoint Landscape::point(std::uint64_t index) const {
  Draws draws(mix(seed_ ^ mix(index)));
  LandscapePoint p = draws.next() < kBuildingShare ? buildingPoint(draws) : groundPoint(draws);
  for (double& v : p.xyz) v += kRangeNoise * (draws.next() - 0.5);
  const double luma = 0.3 * p.rgb[0] + 0.59 * p.rgb[1] + 0.11 * p.rgb[2];
  p.intensity =
      static_cast<std::uint16_t>(std::clamp(luma * 180 + 2000 * draws.next(), 0.0, 65535.0));
  return p;
}

}  // namespace octopoint::testing
