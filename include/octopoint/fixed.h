#pragma once
// octopoint/fixed.h: Fixed-point numbers, integer angles and rotations: no floating point at run
// time. The manual of the whole library is octopoint/octopoint.h.

#include <array>
#include <cassert>
#include <compare>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>

// Exact 64-bit integer helpers for fixed-point code: rounding shifts, products through a 128-bit
// intermediate, and rounded division by a power-of-two-scaled divisor.
//
// Portability: the 128-bit intermediate is built from 32-bit halves (no compiler 128-bit
// extension), so this header compiles unchanged for 32-bit ARM without an FPU. Everything is
// constexpr, so the same code builds the sine table at compile time (trig.cpp).
//
// Rounding rule everywhere: round to nearest, ties toward +infinity, i.e. floor(x + 1/2).
// Shifts of negative values rely on C++20 two's complement semantics (>> is arithmetic).

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

// n / d and n % d (d > 0) by shift and subtract: no division instruction and no call to a
// compiler helper. ARMv6-M has no divide instruction and ARMv7-M none for 64 bits, so there a
// 64-bit `/` calls libgcc's __aeabi_uldivmod, which the bare-metal images must not hold
// (docs/device.md); the quotient and remainder are exact, so every target gets the same bits.
// One step per quotient bit (bit_width(n) - bit_width(d) + 1 steps).
struct UnsignedDivision {
  uint64_t quotient = 0;
  uint64_t remainder = 0;
};
constexpr UnsignedDivision longDivide(uint64_t n, uint64_t d) {
  assert(d != 0);
  int steps = 0;
  while (d <= n && (d >> 63) == 0 && (d << 1) <= n) {  // align d's top bit under n's
    d <<= 1;
    ++steps;
  }
  uint64_t quotient = 0;
  for (int step = 0; step <= steps; ++step) {
    quotient <<= 1;
    if (n >= d) {
      n -= d;
      quotient |= 1;
    }
    d >>= 1;
  }
  return {quotient, n};
}

// longDivide's quotient and remainder for a divisor below 2^32 (d > 0), in 32-bit words: what a
// Cortex-M0+ (32-bit registers, no divide) does in a few instructions a step where longDivide's
// 64-bit shifts, compares and subtractions take about thirty (the perspective walk's f / z,
// x / z and y / z have such divisors: z < 2^33 is below 2^32 wherever the eye may see it, the
// walk's numerators are near 2^50). The high word is divided first where it is not already below
// d; then the low word's 32 bits, top first, one quotient bit a step: the remainder stays below
// d < 2^32, and doubling it may carry out of the word, which then certainly exceeds d (the
// subtraction, taken modulo 2^32, is still exact: the true difference is below d).
constexpr uint32_t divideWordInto(uint32_t word, uint32_t d, uint32_t& remainder) {
#if defined(__ARM_ARCH_6M__)
  // The same steps in Thumb-1, unrolled, the quotient's bits entering `word` at the bottom as
  // above: the word's top bit shifts out into the carry (adds), into the doubled remainder
  // (adcs), whose own carry out means it exceeds d; 4 to 6 instructions a step where GCC's loop
  // takes 12 (the loop counter and the carry's test and shift in C++).
  if (!std::is_constant_evaluated()) {
    uint32_t r = remainder;
    // Written out 32 times (not .rept: GCC sizes inline assembly by its lines, and its own
    // branches around a .rept went out of range).
#define OCTOPOINT_DIVIDE_STEP \
  "adds %[w], %[w], %[w]\n\t" \
  "adcs %[r], %[r], %[r]\n\t" \
  "bcs 1f\n\t"                \
  "cmp %[r], %[d]\n\t"        \
  "bcc 2f\n"                  \
  "1:\n\t"                    \
  "subs %[r], %[r], %[d]\n\t" \
  "adds %[w], #1\n"           \
  "2:\n\t"
#define OCTOPOINT_DIVIDE_STEPS_4 \
  OCTOPOINT_DIVIDE_STEP OCTOPOINT_DIVIDE_STEP OCTOPOINT_DIVIDE_STEP OCTOPOINT_DIVIDE_STEP
    asm(".syntax unified\n\t"  // GCC hands inline assembly to Thumb-1 in divided syntax
        OCTOPOINT_DIVIDE_STEPS_4 OCTOPOINT_DIVIDE_STEPS_4 OCTOPOINT_DIVIDE_STEPS_4
            OCTOPOINT_DIVIDE_STEPS_4 OCTOPOINT_DIVIDE_STEPS_4 OCTOPOINT_DIVIDE_STEPS_4
                OCTOPOINT_DIVIDE_STEPS_4 OCTOPOINT_DIVIDE_STEPS_4
        : [w] "+l"(word), [r] "+l"(r)
        : [d] "l"(d)
        : "cc");
#undef OCTOPOINT_DIVIDE_STEPS_4
#undef OCTOPOINT_DIVIDE_STEP
    remainder = r;
    return word;
  }
#endif
  for (int step = 0; step < 32; ++step) {
    const bool carry = (remainder >> 31) != 0;
    remainder = (remainder << 1) | (word >> 31);
    word <<= 1;  // the quotient's bits enter at the bottom as the dividend's leave at the top
    if (carry || remainder >= d) {
      remainder -= d;
      word |= 1;
    }
  }
  return word;
}
constexpr UnsignedDivision longDivideNarrow(uint64_t n, uint32_t d) {
  assert(d != 0);
  const auto high = static_cast<uint32_t>(n >> 32);
  uint32_t remainder = high;
  uint32_t quotient_high = 0;
  if (high >= d) {
    remainder = 0;
    quotient_high = divideWordInto(high, d, remainder);
  }
  const uint32_t quotient_low = divideWordInto(static_cast<uint32_t>(n), d, remainder);
  return {(uint64_t{quotient_high} << 32) | quotient_low, remainder};
}

// n / d and n % d (d > 0): the hardware's division where it has one for 64 bits (or a library
// routine the target allows), longDivideNarrow or longDivide on a Cortex-M (M profile).
constexpr UnsignedDivision divideUnsigned(uint64_t n, uint64_t d) {
#if defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'M'
  if ((d >> 32) == 0) return longDivideNarrow(n, static_cast<uint32_t>(d));
  return longDivide(n, d);
#else
  return {n / d, n % d};
#endif
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
[[nodiscard]] constexpr std::optional<int64_t> mulShiftRound(int64_t a, int64_t b, int shift) {
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
[[nodiscard]] constexpr std::optional<int64_t> divShiftRound(int64_t numerator, int64_t denominator,
                                                             int shift) {
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
  const UnsignedDivision whole = divideUnsigned(n, d);
  uint64_t quotient = whole.quotient;  // <= 2^63
  uint64_t remainder = whole.remainder;
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

// Fixed<FractionBits>: a signed binary fixed-point number, value = raw / 2^FractionBits, stored in
// int32_t and computed through int64_t intermediates. Q(32-F).F, e.g. Q15 = Fixed<15> is Q17.15.
//
// Conversions are explicit only. There is no constructor from, and no conversion to, any arithmetic
// type: `Q15 x = 1.5;` and `Q15 x = 3;` do not compile (tests/compile_fail proves it). Build values
// with fromInt, fromRatio or (rarely, for tables and codecs) fromRaw; read them with floorToInt,
// roundToInt or raw().
//
// Overflow policy (stated here on purpose, fpm style):
//  - checkedAdd / checkedSub / checkedMul / checkedDiv / fromInt / fromRatio / convert return
//    std::nullopt when the exact (rounded) result does not fit int32 raw. Use them for setup and
//    validation, where input is not under our control.
//  - The plain operators + - * and unary - are for hot paths where overflow is impossible by
//    construction (docs/design.md section 3: ranges are validated up front). They compute in int64
//    and assert() that the result fits; with NDEBUG an overflow wraps modulo 2^32 (defined
//    behaviour in C++20, but wrong), so a caller must have proved it cannot happen.
//
// Rounding: every operation that drops bits (*, checkedMul, checkedDiv, fromRatio, roundToInt,
// narrowing convert) rounds to nearest with ties toward +infinity, floor(x + 1/2), so the error is
// at most 1/2 unit in the last place (ulp = 2^-FractionBits). + and - are exact.

namespace octopoint {

template <int FractionBits>
class Fixed {
  static_assert(FractionBits >= 1 && FractionBits <= 30,
                "Fixed<FractionBits>: FractionBits must be in [1, 30]: the int32_t storage needs "
                "the sign bit and one integer bit so that 1.0 is representable, and at least one "
                "fraction bit (use a plain int32_t for integers)");

 public:
  using Raw = int32_t;
  static constexpr int kFractionBits = FractionBits;
  static constexpr Raw kOneRaw = Raw{1} << FractionBits;  // 1.0 in Q(32-F).F

  constexpr Fixed() = default;  // 0

  // No implicit (or explicit) construction from any built-in arithmetic type: deleted so that a
  // misuse names the problem instead of silently picking another overload.
  // (clang-format 14 mangles requires-clauses.)
  // clang-format off
  template <typename Arithmetic>
    requires std::is_arithmetic_v<Arithmetic>
  Fixed(Arithmetic) = delete;
  // clang-format on

  // The named raw access: raw is the value times 2^FractionBits.
  static constexpr Fixed fromRaw(int32_t raw_value) {
    Fixed result;
    result.raw_ = raw_value;
    return result;
  }
  constexpr int32_t raw() const { return raw_; }

  // The integer `value` exactly; nullopt when value * 2^F does not fit int32.
  [[nodiscard]] static constexpr std::optional<Fixed> fromInt(int64_t value) {
    constexpr int64_t kMaxInt = std::numeric_limits<int32_t>::max() >> FractionBits;
    constexpr int64_t kMinInt = std::numeric_limits<int32_t>::min() >> FractionBits;
    if (value < kMinInt || value > kMaxInt) {
      return std::nullopt;
    }
    return fromRaw(static_cast<int32_t>(value * kOneRaw));  // |value * 2^F| < 2^31
  }

  // numerator / denominator rounded to nearest (ties toward +infinity); nullopt when the
  // denominator is 0 or the result does not fit.
  [[nodiscard]] static constexpr std::optional<Fixed> fromRatio(int64_t numerator,
                                                                int64_t denominator) {
    return fromWideRaw(divShiftRound(numerator, denominator, FractionBits));
  }

  // floor(value): rounds toward -infinity (-2.5 -> -3).
  constexpr int32_t floorToInt() const { return raw_ >> FractionBits; }
  // round(value), ties toward +infinity (2.5 -> 3, -2.5 -> -2). Always fits: |raw / 2^F| < 2^30.
  constexpr int32_t roundToInt() const {
    return static_cast<int32_t>(roundShiftRight(raw_, FractionBits));
  }

  // The same value in Q(32-G).G: rounded to nearest when G < F (always fits), exact when G >= F
  // (nullopt when the value does not fit).
  template <int G>
  [[nodiscard]] constexpr std::optional<Fixed<G>> convert() const {
    if constexpr (G >= FractionBits) {
      return Fixed<G>::fromWideRaw(static_cast<int64_t>(raw_) * (int64_t{1} << (G - FractionBits)));
    } else {
      return Fixed<G>::fromWideRaw(roundShiftRight(raw_, FractionBits - G));
    }
  }

  [[nodiscard]] static constexpr std::optional<Fixed> checkedAdd(Fixed a, Fixed b) {
    return fromWideRaw(int64_t{a.raw_} + b.raw_);
  }
  [[nodiscard]] static constexpr std::optional<Fixed> checkedSub(Fixed a, Fixed b) {
    return fromWideRaw(int64_t{a.raw_} - b.raw_);
  }
  // Q.F * Q.F = Q.2F in int64 (|product| <= 2^62), rounded back to Q.F.
  [[nodiscard]] static constexpr std::optional<Fixed> checkedMul(Fixed a, Fixed b) {
    return fromWideRaw(roundShiftRight(int64_t{a.raw_} * b.raw_, FractionBits));
  }
  // a / b rounded to nearest: raw = round(a.raw * 2^F / b.raw); nullopt when b is 0.
  [[nodiscard]] static constexpr std::optional<Fixed> checkedDiv(Fixed a, Fixed b) {
    return fromWideRaw(divShiftRound(a.raw_, b.raw_, FractionBits));
  }

  // Hot-path operators: overflow must be impossible by construction (asserted, see above).
  friend constexpr Fixed operator+(Fixed a, Fixed b) {
    return fromAssertedRaw(int64_t{a.raw_} + b.raw_);
  }
  friend constexpr Fixed operator-(Fixed a, Fixed b) {
    return fromAssertedRaw(int64_t{a.raw_} - b.raw_);
  }
  friend constexpr Fixed operator*(Fixed a, Fixed b) {  // Q.2F product rounded to Q.F
    return fromAssertedRaw(roundShiftRight(int64_t{a.raw_} * b.raw_, FractionBits));
  }
  friend constexpr Fixed operator-(Fixed a) { return fromAssertedRaw(-int64_t{a.raw_}); }
  constexpr Fixed& operator+=(Fixed other) { return *this = *this + other; }
  constexpr Fixed& operator-=(Fixed other) { return *this = *this - other; }

  friend constexpr bool operator==(Fixed, Fixed) = default;
  friend constexpr std::strong_ordering operator<=>(Fixed, Fixed) = default;

 private:
  template <int>
  friend class Fixed;  // convert<G> builds a Fixed<G> from a wide raw value

  static constexpr bool fitsRaw(int64_t raw_value) {
    return raw_value >= std::numeric_limits<int32_t>::min() &&
           raw_value <= std::numeric_limits<int32_t>::max();
  }
  [[nodiscard]] static constexpr std::optional<Fixed> fromWideRaw(
      std::optional<int64_t> raw_value) {
    if (!raw_value || !fitsRaw(*raw_value)) {
      return std::nullopt;
    }
    return fromRaw(static_cast<int32_t>(*raw_value));
  }
  static constexpr Fixed fromAssertedRaw(int64_t raw_value) {
    assert(fitsRaw(raw_value) && "Fixed: overflow in a hot-path operator; use checked*()");
    return fromRaw(static_cast<int32_t>(raw_value));
  }

  int32_t raw_ = 0;
};

using Q15 = Fixed<15>;  // Q17.15: the default position format (docs/design.md section 3)
using Q16 = Fixed<16>;  // Q16.16

}  // namespace octopoint

// Angle: an integer angle in units of 1/65536 turn ("turns16"), normalised to [0, 65535], so
// arithmetic wraps like the circle does (360 degrees == 0, -90 degrees == 270 degrees).
// One unit is 360/65536 ~= 0.0055 degrees. Pure integer, no radians.

namespace octopoint {

class Angle {
 public:
  static constexpr int32_t kUnitsPerTurn = 65536;

  constexpr Angle() = default;  // 0

  // `units` / 65536 turn, reduced modulo one turn (floor modulo: -1 -> 65535).
  static constexpr Angle fromTurns16(int64_t units) {
    Angle result;
    // Two's complement & is the floor modulo by a power of two, also for negative units.
    result.turns16_ = static_cast<int32_t>(units & (kUnitsPerTurn - 1));
    return result;
  }

  // Whole degrees, rounded to the nearest unit (1 degree = 65536/360 units). A result is never
  // exactly halfway between two units (that would need 45 | degrees, which gives an exact unit).
  static constexpr Angle fromDegrees(int64_t degrees) { return fromScaledDegrees(degrees, 360); }

  // Thousandths of a degree, rounded to the nearest unit; never exactly halfway either
  // (that would need 5625 | millidegrees, which gives an exact unit).
  static constexpr Angle fromMilliDegrees(int64_t millidegrees) {
    return fromScaledDegrees(millidegrees, 360000);
  }

  // The angle in units of 1/65536 turn, in [0, 65535].
  constexpr int32_t turns16() const { return turns16_; }

  friend constexpr Angle operator+(Angle a, Angle b) {
    return fromTurns16(int64_t{a.turns16_} + b.turns16_);
  }
  friend constexpr Angle operator-(Angle a, Angle b) {
    return fromTurns16(int64_t{a.turns16_} - b.turns16_);
  }
  friend constexpr Angle operator-(Angle a) { return fromTurns16(-int64_t{a.turns16_}); }
  friend constexpr bool operator==(Angle, Angle) = default;

 private:
  // value / units_per_turn turns, rounded to nearest unit (ties toward +infinity).
  // Reduce modulo one turn first so value * 65536 cannot overflow for any int64 input: a whole
  // number of turns is a whole number of units, so the reduction does not change the rounding.
  static constexpr Angle fromScaledDegrees(int64_t value, int64_t units_per_turn) {
    int64_t reduced = value % units_per_turn;  // in (-units_per_turn, units_per_turn)
    if (reduced < 0) {
      reduced += units_per_turn;
    }
    // floor(reduced * 65536 / units_per_turn + 1/2) = floor((2 * reduced * 65536 + d) / (2 * d));
    // 2 * 360000 * 65536 < 2^36: no overflow.
    const int64_t units = (2 * reduced * kUnitsPerTurn + units_per_turn) / (2 * units_per_turn);
    return fromTurns16(units);  // 65536 (rounded up from just below a full turn) wraps to 0
  }

  int32_t turns16_ = 0;
};

}  // namespace octopoint

// 3x3 rotation matrices in Q1.30 built from integer angles.
//
// Frame (camera / computer-vision convention): x right, y down, z away from the viewer.
//   yaw   = rotation about y: Ry(a) = [[c, 0, s], [0, 1, 0], [-s, 0, c]]
//   pitch = rotation about x: Rx(a) = [[1, 0, 0], [0, c, -s], [0, s, c]]
//   roll  = rotation about z: Rz(a) = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
// and R = Rz(roll) * Rx(pitch) * Ry(yaw): yaw is applied first, roll last (v' = R v).
// Example: yaw of +90 degrees maps x = (1, 0, 0) to (0, 0, -1), i.e. x to -z, and z to +x.

namespace octopoint {

struct Rotation {
  // Row-major, Q1.30 (1.0 = 1 << 30): v'[row] = sum over col of m_q30[row][col] * v[col].
  std::array<std::array<int32_t, 3>, 3> m_q30;
};

// The identity, exactly.
Rotation identityRotation();

// lhs * rhs (apply rhs first). Precondition (asserted): every entry of the exact product is in
// [-2, 2), which holds for rotations (entries within 1 + a few ulp). Each entry is a sum of three
// Q1.30 * Q1.30 = Q2.60 products in int64 (|sum| <= 3 * 2^60 + small < 2^63), rounded to Q1.30
// once: error <= 1/2 ulp (Q30) on top of the operands' own errors. Products with exact 0 and 1 <<
// 30 entries are exact.
Rotation multiplyRotations(const Rotation& lhs, const Rotation& rhs);

// R = Rz(roll) * Rx(pitch) * Ry(yaw) in Q1.30, computed as Rz * (Rx * Ry) from sinQ30/cosQ30.
// Error bound, every entry, against the exact real matrix: |R_q30 - R * 2^30| <= 3.5 (Q30 ulp),
// i.e. about 3.3e-9. Why: table values are within 1/2 ulp; an entry of Rx * Ry is one table value
// (exact product with 1) or one product of two, error <= 1/2 + 1/2 + 1/2 rounding = 1.5 ulp; an
// entry of Rz * (Rx * Ry) is a sum of at most two products, error <= (|cr| + |sr|) * 1.5 +
// (|m1| + |m2|) * 0.5 + 0.5 rounding <= sqrt(2) * 1.5 + sqrt(2) * 0.5 + 0.5 ~= 3.33 ulp (the m are
// two components of a unit column), plus second-order terms below 1e-8 ulp. Consequently rows and
// columns are orthonormal within 2 * sqrt(3) * 3.5 + 3 * 3.5^2 / 2^30 < 12.2 ulp, i.e. |row_i .
// row_j - delta_ij| <= 12.2 * 2^-30. Quarter-turn angles (multiples of 90 degrees) give exact
// signed permutation matrices.
Rotation rotationFromYawPitchRoll(Angle yaw, Angle pitch, Angle roll);

}  // namespace octopoint
