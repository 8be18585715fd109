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
#pragma once

#include <cassert>
#include <compare>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>

#include "fixedpoint/wide_math.h"

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
  static constexpr std::optional<Fixed> fromInt(int64_t value) {
    constexpr int64_t kMaxInt = std::numeric_limits<int32_t>::max() >> FractionBits;
    constexpr int64_t kMinInt = std::numeric_limits<int32_t>::min() >> FractionBits;
    if (value < kMinInt || value > kMaxInt) {
      return std::nullopt;
    }
    return fromRaw(static_cast<int32_t>(value * kOneRaw));  // |value * 2^F| < 2^31
  }

  // numerator / denominator rounded to nearest (ties toward +infinity); nullopt when the
  // denominator is 0 or the result does not fit.
  static constexpr std::optional<Fixed> fromRatio(int64_t numerator, int64_t denominator) {
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
  constexpr std::optional<Fixed<G>> convert() const {
    if constexpr (G >= FractionBits) {
      return Fixed<G>::fromWideRaw(static_cast<int64_t>(raw_) * (int64_t{1} << (G - FractionBits)));
    } else {
      return Fixed<G>::fromWideRaw(roundShiftRight(raw_, FractionBits - G));
    }
  }

  static constexpr std::optional<Fixed> checkedAdd(Fixed a, Fixed b) {
    return fromWideRaw(int64_t{a.raw_} + b.raw_);
  }
  static constexpr std::optional<Fixed> checkedSub(Fixed a, Fixed b) {
    return fromWideRaw(int64_t{a.raw_} - b.raw_);
  }
  // Q.F * Q.F = Q.2F in int64 (|product| <= 2^62), rounded back to Q.F.
  static constexpr std::optional<Fixed> checkedMul(Fixed a, Fixed b) {
    return fromWideRaw(roundShiftRight(int64_t{a.raw_} * b.raw_, FractionBits));
  }
  // a / b rounded to nearest: raw = round(a.raw * 2^F / b.raw); nullopt when b is 0.
  static constexpr std::optional<Fixed> checkedDiv(Fixed a, Fixed b) {
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
  static constexpr std::optional<Fixed> fromWideRaw(std::optional<int64_t> raw_value) {
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
