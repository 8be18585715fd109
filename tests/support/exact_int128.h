#pragma once
// Int128: exact 128-bit signed integers, the reference arithmetic of the fixed-point tests. The
// compiler's __int128 where it has one (x86-64); on 32-bit targets such as the ARMv5 device build
// (docs/device.md), which have none, a small two's complement class with the same operators.
// Tests only: the library itself never needs more than 64 bits.

#include <compare>
#include <concepts>
#include <cstdint>

namespace octopoint::test {

#if defined(__SIZEOF_INT128__)

__extension__ typedef __int128 Int128;

#else

class Int128 {
 public:
  constexpr Int128() = default;
  template <std::integral T>
  constexpr Int128(T value)  // NOLINT: implicit, like a built-in integer promotion
      : low_(static_cast<std::uint64_t>(value)) {  // modulo 2^64: two's complement for negatives
    if constexpr (std::signed_integral<T>) {
      if (value < 0) high_ = -1;
    }
  }
  template <std::integral T>
  constexpr explicit operator T() const {
    return static_cast<T>(low_);
  }

  friend constexpr Int128 operator+(Int128 a, Int128 b) {
    Int128 sum;
    sum.low_ = a.low_ + b.low_;
    sum.high_ =
        static_cast<std::int64_t>(static_cast<std::uint64_t>(a.high_) +
                                  static_cast<std::uint64_t>(b.high_) + (sum.low_ < a.low_));
    return sum;
  }
  friend constexpr Int128 operator-(Int128 a) { return ~a + Int128(1); }
  friend constexpr Int128 operator-(Int128 a, Int128 b) { return a + -b; }
  friend constexpr Int128 operator~(Int128 a) {
    Int128 result;
    result.high_ = ~a.high_;
    result.low_ = ~a.low_;
    return result;
  }
  // The low 128 bits of the product (two's complement makes that right for signed operands too).
  friend constexpr Int128 operator*(Int128 a, Int128 b) {
    Int128 product = multiplyWide(a.low_, b.low_);
    product.high_ = static_cast<std::int64_t>(static_cast<std::uint64_t>(product.high_) +
                                              a.low_ * static_cast<std::uint64_t>(b.high_) +
                                              static_cast<std::uint64_t>(a.high_) * b.low_);
    return product;
  }
  friend constexpr Int128 operator<<(Int128 a, int shift) {  // 0 <= shift < 128
    if (shift == 0) return a;
    Int128 result;
    const auto high = static_cast<std::uint64_t>(a.high_);
    if (shift >= 64) {
      result.high_ = static_cast<std::int64_t>(a.low_ << (shift - 64));
    } else {
      result.high_ = static_cast<std::int64_t>((high << shift) | (a.low_ >> (64 - shift)));
      result.low_ = a.low_ << shift;
    }
    return result;
  }
  // Truncating division and remainder, like the built-in types.
  friend constexpr Int128 operator/(Int128 a, Int128 b) {
    Int128 quotient, remainder;
    divide(a, b, &quotient, &remainder);
    return quotient;
  }
  friend constexpr Int128 operator%(Int128 a, Int128 b) {
    Int128 quotient, remainder;
    divide(a, b, &quotient, &remainder);
    return remainder;
  }

  friend constexpr bool operator==(Int128, Int128) = default;
  friend constexpr std::strong_ordering operator<=>(Int128 a, Int128 b) {
    if (a.high_ != b.high_) return a.high_ <=> b.high_;
    return a.low_ <=> b.low_;
  }

  constexpr Int128& operator+=(Int128 b) { return *this = *this + b; }
  constexpr Int128& operator%=(Int128 b) { return *this = *this % b; }
  constexpr Int128& operator--() { return *this = *this - Int128(1); }

 private:
  static constexpr Int128 multiplyWide(std::uint64_t a, std::uint64_t b) {
    const std::uint64_t a_low = a & 0xffffffffu, a_high = a >> 32;
    const std::uint64_t b_low = b & 0xffffffffu, b_high = b >> 32;
    const std::uint64_t low_low = a_low * b_low;
    const std::uint64_t middle = (low_low >> 32) + (a_high * b_low & 0xffffffffu) + a_low * b_high;
    Int128 product;
    product.low_ = (middle << 32) | (low_low & 0xffffffffu);
    product.high_ =
        static_cast<std::int64_t>(a_high * b_high + (a_high * b_low >> 32) + (middle >> 32));
    return product;
  }

  constexpr bool negative() const { return high_ < 0; }
  constexpr bool bit(int i) const {
    return i >= 64 ? (static_cast<std::uint64_t>(high_) >> (i - 64)) & 1u : (low_ >> i) & 1u;
  }

  // Restoring long division of the magnitudes, one bit at a time, signs applied afterwards.
  static constexpr void divide(Int128 a, Int128 b, Int128* quotient, Int128* remainder) {
    const Int128 numerator = a.negative() ? -a : a;
    const Int128 divisor = b.negative() ? -b : b;
    Int128 q, r;
    int top = 127;  // skip the numerator's leading zeros: the reference values stay near 2^94
    while (top >= 0 && !numerator.bit(top)) --top;
    for (int i = top; i >= 0; --i) {
      r = r << 1;
      if (numerator.bit(i)) r.low_ |= 1u;
      if (r >= divisor) {
        r = r - divisor;
        q = q + (Int128(1) << i);
      }
    }
    *quotient = a.negative() != b.negative() ? -q : q;
    *remainder = a.negative() ? -r : r;
  }

  std::int64_t high_ = 0;
  std::uint64_t low_ = 0;
};

#endif

}  // namespace octopoint::test
