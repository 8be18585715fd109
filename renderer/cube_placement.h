#pragma once
// The cube's placement block of format versions 4 and 5 (octopoint/model.h, CubePlacement) as
// bytes: what the `.oct` and chunked readers share. Internal to the model readers.

#include <cstdint>

#include "octopoint/model.h"

namespace octopoint {

// Reads the format::kCubePlacementBytes bytes at `p` into `cube`; false when they are no valid
// placement (validCubePlacement) or a reserved byte is not 0.
[[nodiscard]] bool readCubePlacement(const std::uint8_t* p, CubePlacement* cube);

}  // namespace octopoint
