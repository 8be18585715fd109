#pragma once
// Little-endian integers appended to a byte buffer, as the model writers lay out their files.

#include <cstdint>
#include <vector>

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

}  // namespace octopoint::prepare
