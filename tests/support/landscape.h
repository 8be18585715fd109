#pragma once
// A procedural landscape to make scans of any size from: rolling hills with meadows, rock on the
// heights, a town of box buildings with red or grey roofs on a street grid, a lake. Point i is a
// pure function of (seed, i), so a scan of 10^8 points is written point by point in constant
// memory, and the same count always gives the same file.

#include <array>
#include <cstdint>

namespace octopoint::testing {

struct LandscapePoint {
  std::array<double, 3> xyz;  // metres, east/north/up, inside [0, kLandscapeSize]^2 x [0, ~200]
  std::array<std::uint8_t, 3> rgb;
  std::uint16_t intensity;  // a return strength: bright surfaces return more
};

inline constexpr double kLandscapeSize = 1000.0;

class Landscape {
 public:
  explicit Landscape(std::uint64_t seed = 1) : seed_(seed) {}
  LandscapePoint point(std::uint64_t index) const;
  // The ground height at (x, y), metres.
  static double groundHeight(double x, double y);

 private:
  std::uint64_t seed_;
};

}  // namespace octopoint::testing
