#pragma once
// Synthetic scans with known answers, made in memory (no files, no real data).

#include <cstdint>
#include <random>

#include "codegen/scan_loader.h"

namespace octopoint::testing {

// A sphere surface of `count` points, radius 1 at the origin, coloured by octant (8 colours).
prepare::Scan colouredSphere(std::size_t count, std::uint32_t seed = 1);

// Points drawn uniformly inside the unit cube, each with a random colour.
prepare::Scan randomCloud(std::size_t count, std::uint32_t seed);

// A face-like height field seen from the front: z = depth of a bumpy surface, colour by height.
prepare::Scan faceLikeHeightField(int samples_per_side);

}  // namespace octopoint::testing
