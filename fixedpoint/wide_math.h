// Exact 64-bit integer helpers for fixed-point code: rounding shifts, products through a 128-bit
// intermediate, and rounded division by a power-of-two-scaled divisor.
//
// Portability: the 128-bit intermediate is built from 32-bit halves (no compiler 128-bit
// extension), so this header compiles unchanged for 32-bit ARM without an FPU. Everything is
// constexpr, so the same code builds the sine table at compile time (trig.cpp).
//
// Rounding rule everywhere: round to nearest, ties toward +infinity, i.e. floor(x + 1/2).
// Shifts of negative values rely on C++20 two's complement semantics (>> is arithmetic).
#pragma once

#include <cassert>
#include <cstdint>
#include <optional>

namespace octopoint {

// An unsigned 128-bit value as two 64-bit halves: value = high * 2^64 + low.
struct UInt128 {
  uint64_t high = 0;
  uint64_t low = 0;
};

// Full 64x64 -> 128-bit unsigned product from four 32x32 -> 64-bit partial products.
constexpr UInt128 mulWideUnsigned(uint64_t a, uint64_t b) {
  constexpr uint64_t kLowMask = 0xFFFFFFFFu;
  const uint64_t a_low = a & kLowMask;
  const uint64_t a_high = a >> 32;
  const uint64_t b_low = b & kLowMask;
  const uint64_t b_high = b >> 32;

  const uint64_t low_low = a_low * b_low;      // weight 2^0
  const uint64_t low_high = a_low * b_high;    // weight 2^32
  const uint64_t high_low = a_high * b_low;    // weight 2^32
  const uint64_t high_high = a_high * b_high;  // weight 2^64

  // Sum the three contributions to bits 32..63; each is < 2^32, so the sum is < 3 * 2^32 and
  // cannot overflow: its upper half is the carry into the high word.
  const uint64_t middle = (low_low >> 32) + (low_high & kLowMask) + (high_low & kLowMask);
  UInt128 result;
  result.low = (middle << 32) | (low_low & kLowMask);
  result.high = high_high + (low_high >> 32) + (high_low >> 32) + (middle >> 32);
  return result;
}

// round(value / 2^shift), ties toward +infinity, for shift in [0, 62].
// Never overflows: value = q * 2^shift + r with 0 <= r < 2^shift, and the result is q plus one
// when r >= 2^(shift-1), i.e. when bit (shift - 1) of value is set. No addition near INT64_MAX.
constexpr int64_t roundShiftRight(int64_t value, int shift) {
  assert(shift >= 0 && shift <= 62);
  if (shift == 0) {
    return value;
  }
  return (value >> shift) + ((value >> (shift - 1)) & 1);
}

// Exactly round(a * b / 2^shift), ties toward +infinity, for shift in [0, 126];
// std::nullopt when the result does not fit int64_t.
constexpr std::optional<int64_t> mulShiftRound(int64_t a, int64_t b, int shift) {
  assert(shift >= 0 && shift <= 126);
  // Magnitudes as uint64 (well defined for INT64_MIN: 0 - 2^63 mod 2^64 = 2^63).
  const uint64_t a_magnitude =
      a < 0 ? uint64_t{0} - static_cast<uint64_t>(a) : static_cast<uint64_t>(a);
  const uint64_t b_magnitude =
      b < 0 ? uint64_t{0} - static_cast<uint64_t>(b) : static_cast<uint64_t>(b);
  UInt128 product = mulWideUnsigned(a_magnitude, b_magnitude);  // |a*b| <= 2^126

  // Two's complement negation in 128 bits (the product is at most 2^126, so no sign overflow).
  if ((a < 0) != (b < 0)) {
    product.low = ~product.low + 1;
    product.high = ~product.high + (product.low == 0 ? uint64_t{1} : uint64_t{0});
  }

  // Add half of the divisor, 2^(shift-1): |a*b| + 2^125 < 2^127, so no overflow.
  if (shift > 0) {
    if (shift - 1 < 64) {
      const uint64_t half = uint64_t{1} << (shift - 1);
      const uint64_t new_low = product.low + half;
      product.high += new_low < product.low ? uint64_t{1} : uint64_t{0};
      product.low = new_low;
    } else {
      product.high += uint64_t{1} << (shift - 1 - 64);
    }
  }

  // Arithmetic shift right of the signed 128-bit value: floor((a*b + 2^(shift-1)) / 2^shift).
  const int64_t signed_high = static_cast<int64_t>(product.high);
  int64_t result_high = signed_high;
  uint64_t result_low = product.low;
  if (shift >= 64) {
    result_low = static_cast<uint64_t>(signed_high >> (shift - 64));
    result_high = signed_high >> 63;
  } else if (shift > 0) {
    result_low = (product.low >> shift) | (product.high << (64 - shift));
    result_high = signed_high >> shift;
  }

  // It fits int64 when the high word is the sign extension of the low word.
  const int64_t result = static_cast<int64_t>(result_low);
  if (result_high != (result < 0 ? -1 : 0)) {
    return std::nullopt;
  }
  return result;
}

// Exactly round(numerator * 2^shift / denominator), ties toward +infinity, for shift in [0, 62];
// std::nullopt when denominator is 0 or the result does not fit int64_t.
// Restoring long division, one quotient bit per shift step: costs `shift` iterations, so keep it
// off hot paths (it is for setup: ratios, checked division).
constexpr std::optional<int64_t> divShiftRound(int64_t numerator, int64_t denominator, int shift) {
  assert(shift >= 0 && shift <= 62);
  if (denominator == 0) {
    return std::nullopt;
  }
  const bool negative = (numerator < 0) != (denominator < 0);
  const uint64_t n = numerator < 0 ? uint64_t{0} - static_cast<uint64_t>(numerator)
                                   : static_cast<uint64_t>(numerator);
  const uint64_t d = denominator < 0 ? uint64_t{0} - static_cast<uint64_t>(denominator)
                                     : static_cast<uint64_t>(denominator);
  constexpr uint64_t kTwoTo63 = uint64_t{1} << 63;

  // Invariant: n * 2^step / d = quotient + remainder / d, with remainder < d <= 2^63, so
  // 2 * remainder < 2^64 never wraps.
  uint64_t quotient = n / d;  // <= 2^63
  uint64_t remainder = n % d;
  for (int step = 0; step < shift; ++step) {
    if (quotient >= kTwoTo63) {
      return std::nullopt;  // the magnitude would reach 2^64 after doubling: no int64 holds it
    }
    remainder <<= 1;
    quotient <<= 1;
    if (remainder >= d) {
      remainder -= d;
      quotient += 1;
    }
  }

  // Round the magnitude x = quotient + remainder / d.
  // Positive result: floor(x + 1/2) adds one when remainder / d >= 1/2.
  // Negative result: floor(-x + 1/2) = -ceil(x - 1/2) adds one to x only when remainder / d > 1/2.
  const uint64_t twice_remainder = remainder << 1;
  const bool round_up = negative ? twice_remainder > d : twice_remainder >= d;
  const uint64_t magnitude = quotient + (round_up ? uint64_t{1} : uint64_t{0});  // <= 2^63 + 1

  if (negative) {
    if (magnitude > kTwoTo63) {
      return std::nullopt;
    }
    return static_cast<int64_t>(uint64_t{0} -
                                magnitude);  // 2^63 becomes INT64_MIN, modular by C++20
  }
  if (magnitude >= kTwoTo63) {
    return std::nullopt;
  }
  return static_cast<int64_t>(magnitude);
}

}  // namespace octopoint
