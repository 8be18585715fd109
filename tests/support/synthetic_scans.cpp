#include "tests/support/synthetic_scans.h"

#include <algorithm>
#include <cmath>

namespace octopoint::testing {

prepare::Scan colouredSphere(std::size_t count, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  prepare::Scan scan;
  scan.shading = prepare::ScanShading::kColour;
  for (std::size_t i = 0; i < count; ++i) {
    float p[3] = {normal(random), normal(random), normal(random)};
    const float length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (length < 1e-6f) continue;
    scan.positions.push_back({p[0] / length, p[1] / length, p[2] / length});
    const int octant = (p[0] > 0) << 2 | (p[1] > 0) << 1 | (p[2] > 0);
    scan.colours.push_back({static_cast<std::uint8_t>(octant & 4 ? 230 : 40),
                            static_cast<std::uint8_t>(octant & 2 ? 230 : 40),
                            static_cast<std::uint8_t>(octant & 1 ? 230 : 40)});
  }
  scan.points_in_file = scan.positions.size();
  return scan;
}

prepare::Scan randomCloud(std::size_t count, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> byte(0, 255);
  prepare::Scan scan;
  scan.shading = prepare::ScanShading::kColour;
  for (std::size_t i = 0; i < count; ++i) {
    scan.positions.push_back({unit(random), unit(random), unit(random)});
    scan.colours.push_back({static_cast<std::uint8_t>(byte(random)),
                            static_cast<std::uint8_t>(byte(random)),
                            static_cast<std::uint8_t>(byte(random))});
  }
  scan.points_in_file = count;
  return scan;
}

prepare::Scan faceLikeHeightField(int samples_per_side) {
  prepare::Scan scan;
  scan.shading = prepare::ScanShading::kColour;
  for (int row = 0; row < samples_per_side; ++row) {
    for (int column = 0; column < samples_per_side; ++column) {
      const float x =
          -1.0f + 2.0f * static_cast<float>(column) / static_cast<float>(samples_per_side - 1);
      const float y =
          -1.0f + 2.0f * static_cast<float>(row) / static_cast<float>(samples_per_side - 1);
      if (x * x + 0.6f * y * y > 1.0f) continue;  // an oval outline
      const float nose = 0.35f * std::exp(-(x * x + y * y) * 12.0f);
      const float eyes =
          -0.08f * (std::exp(-((x - 0.35f) * (x - 0.35f) + (y + 0.3f) * (y + 0.3f)) * 40.0f) +
                    std::exp(-((x + 0.35f) * (x + 0.35f) + (y + 0.3f) * (y + 0.3f)) * 40.0f));
      const float z = 0.5f * (x * x + y * y) - nose - eyes;  // nearer (smaller z) at the nose
      scan.positions.push_back({x, y, z});
      const auto shade = static_cast<std::uint8_t>(std::clamp(200.0f - 200.0f * z, 0.0f, 255.0f));
      scan.colours.push_back(
          {shade, static_cast<std::uint8_t>(shade * 3 / 4), static_cast<std::uint8_t>(shade / 2)});
    }
  }
  scan.points_in_file = scan.positions.size();
  return scan;
}

}  // namespace octopoint::testing
