#pragma once
// floor(sqrt(value)), bit by bit: integer only (the voxel edge on screen, a blended normal's
// length).
#include <cstdint>

namespace octopoint {

inline std::uint64_t integerSquareRoot(std::uint64_t value) {
  std::uint64_t root = 0;
  std::uint64_t bit = std::uint64_t{1} << 62;
  while (bit > value) bit >>= 2;
  while (bit != 0) {
    if (value >= root + bit) {
      value -= root + bit;
      root = (root >> 1) + bit;
    } else {
      root >>= 1;
    }
    bit >>= 2;
  }
  return root;
}

}  // namespace octopoint
