#pragma once
// Airborne-like scans (docs/splats.md, "Samples coarser than the voxel"): a flat ground of
// kAirborneGroundLength x kAirborneGroundWidth metres with raised blocks (roofs), sampled from
// above at a spacing of its own, either on scan lines of a regular grid (spacing s along and
// across, as a lidar's lines are) or irregularly (uniform random positions at the same mean
// spacing). The ground lies in the scan's x-y plane, heights toward the viewer (-z), so the
// identity camera looks straight down on it. Seeded and deterministic (a SplitMix64 generator,
// the same on every standard library); made in memory, nothing large is committed.

#include <cstdint>

#include "codegen/scan_loader.h"

namespace octopoint::testing {

inline constexpr double kAirborneGroundLength = 225.0;  // metres along x: the model cube's edge
inline constexpr double kAirborneGroundWidth = 100.0;   // metres along y

enum class AirborneSampling : std::uint8_t {
  kGrid,       // points at (i s, j s): scan lines s apart, samples s apart along them
  kIrregular,  // length x width / s^2 points at uniform random positions
};

// About 22,500 points at 1 m spacing. `seed` moves the grid's origin by a fraction of s and
// draws the irregular positions.
prepare::Scan airborneScan(AirborneSampling sampling, double spacing_metres, std::uint64_t seed);

// The height of the ground or a roof at (x, y), metres (0 on the ground).
double airborneHeight(double x, double y);

}  // namespace octopoint::testing
