#pragma once
// The two bit operations every decoder does per node: the lowest set bit of a child mask (which
// child comes next) and the number of set bits (how many subtrees to step over). Child masks are
// one byte. Where the CPU counts zeros in one instruction (x86 tzcnt/bsf, ARMv7-M rbit + clz) they
// compile to it; a Cortex-M0+ (ARMv6-M) has no such instruction and GCC would call libgcc's
// __ctzsi2 and __popcountsi2 (about 20 instructions each), so there they are one load from a
// 256-byte table in flash (docs/device.md).

#include <array>
#include <bit>
#include <cstdint>

namespace octopoint {

#if defined(__ARM_ARCH_6M__)
inline constexpr bool kBitScanByTable = true;
#else
inline constexpr bool kBitScanByTable = false;
#endif

inline constexpr std::array<std::uint8_t, 256> kLowestSetBit = [] {
  std::array<std::uint8_t, 256> table{};
  for (unsigned mask = 1; mask < 256; ++mask) table[mask] = static_cast<std::uint8_t>(std::countr_zero(mask));
  return table;
}();

inline constexpr std::array<std::uint8_t, 256> kSetBitCount = [] {
  std::array<std::uint8_t, 256> table{};
  for (unsigned mask = 0; mask < 256; ++mask) table[mask] = static_cast<std::uint8_t>(std::popcount(mask));
  return table;
}();

// The index of the lowest set bit of a non-zero child mask (< 256).
inline std::size_t lowestChild(unsigned mask) {
  if constexpr (kBitScanByTable) {
    return kLowestSetBit[mask];
  } else {
    return static_cast<std::size_t>(std::countr_zero(mask));
  }
}

// The number of set bits of a child mask (< 256).
inline int childCount(unsigned mask) {
  if constexpr (kBitScanByTable) {
    return kSetBitCount[mask];
  } else {
    return std::popcount(mask);
  }
}

}  // namespace octopoint
