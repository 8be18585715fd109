#pragma once
// Values read out of a file's bytes: LAS, LAZ and COPC store them little-endian, like every host
// octopoint builds for.

#include <bit>
#include <cstdint>
#include <cstring>

namespace octopoint::prepare {

template <typename T>
T readLittle(const std::uint8_t* bytes) {
  static_assert(std::endian::native == std::endian::little);
  T value;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

}  // namespace octopoint::prepare
