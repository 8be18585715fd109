#include "tests/support/airborne_scans.h"

#include <array>
#include <cmath>

namespace octopoint::testing {
namespace {

// SplitMix64 (Steele, Lea, Flood 2014): the same numbers everywhere, unlike std:: distributions.
class SplitMix {
 public:
  explicit SplitMix(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  std::uint64_t state_;
};

struct Block {
  double x0, y0, x1, y1, height;
};

// Buildings on the ground: a few roofs of 15 to 30 m at 4 to 12 m.
constexpr std::array<Block, 6> kBlocks = {{{20, 15, 45, 35, 6},
                                           {60, 55, 90, 80, 12},
                                           {110, 10, 128, 40, 4},
                                           {140, 60, 170, 85, 9},
                                           {185, 20, 210, 45, 7},
                                           {95, 65, 115, 90, 5}}};

void addPoint(prepare::Scan& scan, double x, double y) {
  const double height = airborneHeight(x, y);
  scan.positions.push_back(
      {static_cast<float>(x), static_cast<float>(y), static_cast<float>(-height)});
  // Asphalt grey with painted stripes every 10 m; roofs red.
  const bool stripe = std::fmod(x, 10.0) < 0.5;
  const std::array<std::uint8_t, 3> colour = height > 0 ? std::array<std::uint8_t, 3>{190, 60, 50}
                                             : stripe   ? std::array<std::uint8_t, 3>{230, 230, 210}
                                                        : std::array<std::uint8_t, 3>{90, 95, 100};
  scan.colours.push_back(colour);
}

}  // namespace

double airborneHeight(double x, double y) {
  for (const Block& block : kBlocks) {
    if (x >= block.x0 && x < block.x1 && y >= block.y0 && y < block.y1) return block.height;
  }
  return 0.0;
}

prepare::Scan airborneScan(AirborneSampling sampling, double spacing_metres, std::uint64_t seed) {
  prepare::Scan scan;
  scan.shading = prepare::ScanShading::kColour;
  SplitMix random(seed);
  if (sampling == AirborneSampling::kGrid) {
    const double start_x = random.unit() * spacing_metres;
    const double start_y = random.unit() * spacing_metres;
    for (double y = start_y; y < kAirborneGroundWidth; y += spacing_metres) {
      for (double x = start_x; x < kAirborneGroundLength; x += spacing_metres) addPoint(scan, x, y);
    }
  } else {
    const auto count = static_cast<std::size_t>(kAirborneGroundLength * kAirborneGroundWidth /
                                                (spacing_metres * spacing_metres));
    for (std::size_t i = 0; i < count; ++i) {
      const double x = random.unit() * kAirborneGroundLength;
      addPoint(scan, x, random.unit() * kAirborneGroundWidth);
    }
  }
  scan.points_in_file = scan.positions.size();
  return scan;
}

}  // namespace octopoint::testing
