#pragma once
// Little-endian integers appended to a byte buffer, as the model writers lay out their files.

#include <cstdint>
#include <vector>

#include "octopoint/model.h"

namespace octopoint::prepare {

inline void putU16(std::vector<std::uint8_t>& out, std::uint32_t value) {
  out.push_back(static_cast<std::uint8_t>(value));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
}

inline void putU32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  putU16(out, value & 0xFFFFu);
  putU16(out, value >> 16);
}

inline void putU64(std::vector<std::uint8_t>& out, std::uint64_t value) {
  putU32(out, static_cast<std::uint32_t>(value));
  putU32(out, static_cast<std::uint32_t>(value >> 32));
}

// The cube's placement block of format versions 4 and 5 (octopoint/model.h).
inline void putCubePlacement(std::vector<std::uint8_t>& out, const CubePlacement& cube) {
  for (std::uint64_t corner : cube.corner_bits) putU64(out, corner);
  putU64(out, cube.edge_bits);
  out.push_back(cube.scan_axes);
  out.insert(out.end(), format::kCubePlacementBytes - 33, std::uint8_t{0});  // reserved
}

}  // namespace octopoint::prepare
