#pragma once
// The two bit operations every decoder does per node: the lowest set bit of a child mask (which
// child comes next) and the number of set bits (how many subtrees to step over). Child masks are
// one byte. Where the CPU counts zeros in one instruction (x86 tzcnt/bsf, ARMv7-M rbit + clz) the
// lowest set bit compiles to it; a Cortex-M0+ (ARMv6-M) has no such instruction and GCC would call
// libgcc's __ctzsi2 (about 20 instructions), so there it is one load from a 256-byte table in
// flash (docs/device.md). The count is a table load unless the target has a popcount instruction
// (below).

#include <array>
#include <bit>
#include <cstdint>

namespace octopoint {

#if defined(__ARM_ARCH_6M__)
inline constexpr bool kBitScanByTable = true;
#else
inline constexpr bool kBitScanByTable = false;
#endif

// Counting set bits is rarer in a base instruction set than finding one: x86-64 without -mpopcnt
// (the default build), ARMv5 (the armel device) and every Cortex-M call libgcc's __popcountsi2 or
// __popcountdi2 for std::popcount, a function call and about 15 instructions, which the chunk
// validator and the stream walkers pay once per node. Only where the compiler has a popcount
// instruction (__POPCNT__) is it used; elsewhere a byte's count is one load from a 256-byte table.
#if defined(__POPCNT__)
inline constexpr bool kBitCountByTable = false;
#else
inline constexpr bool kBitCountByTable = true;
#endif

inline constexpr std::array<std::uint8_t, 256> kLowestSetBit = [] {
  std::array<std::uint8_t, 256> table{};
  for (unsigned mask = 1; mask < 256; ++mask)
    table[mask] = static_cast<std::uint8_t>(std::countr_zero(mask));
  return table;
}();

inline constexpr std::array<std::uint8_t, 256> kSetBitCount = [] {
  std::array<std::uint8_t, 256> table{};
  for (unsigned mask = 0; mask < 256; ++mask)
    table[mask] = static_cast<std::uint8_t>(std::popcount(mask));
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
  if constexpr (kBitCountByTable) {
    return kSetBitCount[mask];
  } else {
    return std::popcount(mask);
  }
}

}  // namespace octopoint
