// Tests for octopoint/fixed.h and octopoint/fixed.h.
// References: exact 128-bit arithmetic (tests/support/exact_int128.h; the library itself never uses
// it) and long double, whose 64-bit mantissa holds every int32 * int32 product exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "octopoint/fixed.h"
#include "tests/support/exact_int128.h"

namespace octopoint {

// gtest prints a Fixed with its raw hex and its value (fpm style), e.g. "0x00018000 (3 in Q15)".
template <int F>
void PrintTo(const Fixed<F>& value, std::ostream* out) {
  std::ostringstream text;
  text << "0x" << std::hex << std::setw(8) << std::setfill('0')
       << static_cast<uint32_t>(value.raw()) << std::dec << " (" << std::setprecision(12)
       << static_cast<long double>(value.raw()) / (1LL << F) << " in Q" << F << ")";
  *out << text.str();
}

}  // namespace octopoint

namespace {

using octopoint::Fixed;
using octopoint::Q15;
using octopoint::Q16;
using octopoint::test::Int128;  // exact reference arithmetic (tests/support/exact_int128.h)

constexpr int64_t kInt64Min = std::numeric_limits<int64_t>::min();
constexpr int64_t kInt64Max = std::numeric_limits<int64_t>::max();
constexpr int32_t kInt32Min = std::numeric_limits<int32_t>::min();
constexpr int32_t kInt32Max = std::numeric_limits<int32_t>::max();

std::string hex64(int64_t value) {
  std::ostringstream text;
  text << "0x" << std::hex << static_cast<uint64_t>(value);
  return text.str();
}

// floor(numerator / denominator) for denominator > 0.
Int128 floorDiv(Int128 numerator, Int128 denominator) {
  Int128 quotient = numerator / denominator;
  if (numerator % denominator != 0 && numerator < 0) {
    --quotient;
  }
  return quotient;
}

// round(value / 2^shift), ties toward +infinity: floor((value + 2^(shift-1)) / 2^shift).
Int128 referenceRoundShift(Int128 value, int shift) {
  if (shift == 0) {
    return value;
  }
  return floorDiv(value + (Int128{1} << (shift - 1)), Int128{1} << shift);
}

std::optional<int64_t> narrowToInt64(Int128 value) {
  if (value < kInt64Min || value > kInt64Max) {
    return std::nullopt;
  }
  return static_cast<int64_t>(value);
}

// round(numerator * 2^shift / denominator), ties toward +infinity.
std::optional<int64_t> referenceDivShiftRound(int64_t numerator, int64_t denominator, int shift) {
  if (denominator == 0) {
    return std::nullopt;
  }
  Int128 scaled = Int128{numerator} * (Int128{1} << shift);
  Int128 divisor = denominator;
  if (divisor < 0) {
    scaled = -scaled;
    divisor = -divisor;
  }
  return narrowToInt64(floorDiv(2 * scaled + divisor, 2 * divisor));
}

// Operands that stress carries, signs and limits.
const std::vector<int64_t>& extremeOperands() {
  static const std::vector<int64_t> operands = {kInt64Min,
                                                kInt64Min + 1,
                                                -(int64_t{1} << 62),
                                                -(int64_t{1} << 32) - 1,
                                                -(int64_t{1} << 32),
                                                -(int64_t{1} << 31),
                                                -0xFFFFFFFFLL,
                                                -3,
                                                -2,
                                                -1,
                                                0,
                                                1,
                                                2,
                                                3,
                                                0xFFFFFFFFLL,
                                                int64_t{1} << 31,
                                                int64_t{1} << 32,
                                                (int64_t{1} << 32) + 1,
                                                int64_t{1} << 62,
                                                kInt64Max - 1,
                                                kInt64Max};
  return operands;
}

// A mix of full-range, mid-range and tiny random int64 values.
int64_t randomOperand(std::mt19937_64& rng) {
  const uint64_t bits = rng();
  switch (bits % 4) {
    case 0:
      return static_cast<int64_t>(rng());
    case 1:
      return static_cast<int64_t>(rng()) >> (rng() % 63);
    case 2:
      return static_cast<int64_t>(rng() % 2001) - 1000;
    default:
      return extremeOperands()[rng() % extremeOperands().size()];
  }
}

// ---------------------------------------------------------------------------------------------
// wide_math.h

TEST(RoundShiftRight, MatchesExactRoundingAtInt64LimitsForEveryShift) {
  for (int64_t value : extremeOperands()) {
    for (int shift = 0; shift <= 62; ++shift) {
      EXPECT_EQ(octopoint::roundShiftRight(value, shift), referenceRoundShift(value, shift))
          << "value " << hex64(value) << " shift " << shift;
    }
  }
}

TEST(RoundShiftRight, RoundsTiesTowardPlusInfinity) {
  EXPECT_EQ(octopoint::roundShiftRight(3, 1), 2);                         // 1.5 -> 2
  EXPECT_EQ(octopoint::roundShiftRight(-3, 1), -1);                       // -1.5 -> -1
  EXPECT_EQ(octopoint::roundShiftRight(5, 2), 1);                         // 1.25 -> 1
  EXPECT_EQ(octopoint::roundShiftRight(-5, 2), -1);                       // -1.25 -> -1
  EXPECT_EQ(octopoint::roundShiftRight(-7, 2), -2);                       // -1.75 -> -2
  EXPECT_EQ(octopoint::roundShiftRight(kInt64Max, 1), int64_t{1} << 62);  // no overflow
  EXPECT_EQ(octopoint::roundShiftRight(kInt64Max, 62), 2);
  EXPECT_EQ(octopoint::roundShiftRight(kInt64Min, 62), -2);
}

TEST(RoundShiftRight, MatchesExactRoundingForRandomValues) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 200000; ++i) {
    const int64_t value = randomOperand(rng);
    const int shift = static_cast<int>(rng() % 63);
    ASSERT_EQ(octopoint::roundShiftRight(value, shift), referenceRoundShift(value, shift))
        << "value " << hex64(value) << " shift " << shift;
  }
}

TEST(MulShiftRound, MatchesExactInt128ForExtremeOperandsAndEveryShift) {
  for (int64_t a : extremeOperands()) {
    for (int64_t b : extremeOperands()) {
      for (int shift = 0; shift <= 126; ++shift) {
        const auto expected = narrowToInt64(referenceRoundShift(Int128{a} * b, shift));
        ASSERT_EQ(octopoint::mulShiftRound(a, b, shift), expected)
            << hex64(a) << " * " << hex64(b) << " >> " << shift;
      }
    }
  }
}

TEST(MulShiftRound, MatchesExactInt128ForRandomOperands) {
  std::mt19937_64 rng(2);
  int refused = 0;
  for (int i = 0; i < 500000; ++i) {
    const int64_t a = randomOperand(rng);
    const int64_t b = randomOperand(rng);
    const int shift = static_cast<int>(rng() % 127);
    const auto expected = narrowToInt64(referenceRoundShift(Int128{a} * b, shift));
    refused += expected ? 0 : 1;
    ASSERT_EQ(octopoint::mulShiftRound(a, b, shift), expected)
        << hex64(a) << " * " << hex64(b) << " >> " << shift;
  }
  // Both outcomes must be exercised for the comparison to mean anything.
  EXPECT_GT(refused, 1000);
  EXPECT_LT(refused, 400000);
}

TEST(MulShiftRound, RefusesExactlyOneBeyondInt64) {
  // 2^63 does not fit, 2^63 - 1 and -2^63 do.
  EXPECT_EQ(octopoint::mulShiftRound(int64_t{1} << 62, 2, 0), std::nullopt);
  EXPECT_EQ(octopoint::mulShiftRound(-(int64_t{1} << 62), 2, 0), kInt64Min);
  EXPECT_EQ(octopoint::mulShiftRound(kInt64Max, 1, 0), kInt64Max);
  EXPECT_EQ(octopoint::mulShiftRound(kInt64Min, -1, 0), std::nullopt);
  EXPECT_EQ(octopoint::mulShiftRound(kInt64Min, kInt64Min, 126), 1);            // 2^126 / 2^126
  EXPECT_EQ(octopoint::mulShiftRound(kInt64Min, kInt64Min, 63), std::nullopt);  // 2^63
  EXPECT_EQ(octopoint::mulShiftRound(kInt64Min, kInt64Max, 63), -kInt64Max);
}

TEST(DivShiftRound, MatchesExactInt128ForRandomAndExtremeOperands) {
  std::mt19937_64 rng(3);
  for (int64_t n : extremeOperands()) {
    for (int64_t d : extremeOperands()) {
      for (int shift = 0; shift <= 62; ++shift) {
        ASSERT_EQ(octopoint::divShiftRound(n, d, shift), referenceDivShiftRound(n, d, shift))
            << hex64(n) << " * 2^" << shift << " / " << hex64(d);
      }
    }
  }
  for (int i = 0; i < 200000; ++i) {
    const int64_t n = randomOperand(rng);
    const int64_t d = randomOperand(rng);
    const int shift = static_cast<int>(rng() % 63);
    ASSERT_EQ(octopoint::divShiftRound(n, d, shift), referenceDivShiftRound(n, d, shift))
        << hex64(n) << " * 2^" << shift << " / " << hex64(d);
  }
}

// ---------------------------------------------------------------------------------------------
// fixed.h: properties checked at both ends of the supported fraction range and in the middle.

template <typename T>
class FixedAnyFormat : public ::testing::Test {};
using SupportedFormats = ::testing::Types<Fixed<1>, Fixed<2>, Q15, Q16, Fixed<29>, Fixed<30>>;
TYPED_TEST_SUITE(FixedAnyFormat, SupportedFormats);

TYPED_TEST(FixedAnyFormat, HasTheDeclaredScaleAndZeroDefault) {
  using F = TypeParam;
  EXPECT_EQ(F::kOneRaw, int64_t{1} << F::kFractionBits);
  EXPECT_EQ(F{}.raw(), 0);
  EXPECT_EQ(F::fromRaw(kInt32Max).raw(), kInt32Max);
  EXPECT_EQ(F::fromRaw(kInt32Min).raw(), kInt32Min);
}

TYPED_TEST(FixedAnyFormat, FromIntIsExactUpToTheLargestFittingIntegerAndRefusesOneBeyond) {
  using F = TypeParam;
  const int64_t largest = int64_t{kInt32Max} >> F::kFractionBits;
  const int64_t smallest = int64_t{kInt32Min} >> F::kFractionBits;
  ASSERT_TRUE(F::fromInt(largest));
  EXPECT_EQ(F::fromInt(largest)->raw(), largest << F::kFractionBits);
  EXPECT_EQ(F::fromInt(largest + 1), std::nullopt);
  ASSERT_TRUE(F::fromInt(smallest));
  EXPECT_EQ(F::fromInt(smallest)->raw(), kInt32Min);  // -2^(31-F) * 2^F
  EXPECT_EQ(F::fromInt(smallest - 1), std::nullopt);
  EXPECT_EQ(F::fromInt(kInt64Max), std::nullopt);
  EXPECT_EQ(F::fromInt(kInt64Min), std::nullopt);
  for (int64_t value = std::max<int64_t>(smallest, -300); value <= std::min<int64_t>(largest, 300);
       ++value) {
    const F fixed = *F::fromInt(value);
    EXPECT_EQ(fixed.raw(), value * F::kOneRaw);
    EXPECT_EQ(fixed.floorToInt(), value);
    EXPECT_EQ(fixed.roundToInt(), value);
  }
}

TYPED_TEST(FixedAnyFormat, FromRatioIsExactForRepresentableRatios) {
  using F = TypeParam;
  std::mt19937_64 rng(4);
  for (int i = 0; i < 20000; ++i) {
    const auto raw = static_cast<int32_t>(rng());
    const int64_t scale = static_cast<int64_t>(rng() % 1000) + 1;
    // raw / 2^F written as (raw * scale) / (2^F * scale), also with both signs flipped.
    const auto value = F::fromRatio(int64_t{raw} * scale, F::kOneRaw * scale);
    const auto flipped = F::fromRatio(-int64_t{raw} * scale, -F::kOneRaw * scale);
    ASSERT_TRUE(value && flipped);
    ASSERT_EQ(*value, F::fromRaw(raw));
    ASSERT_EQ(*flipped, F::fromRaw(raw));
  }
  // Powers of two down to one ulp.
  for (int k = 0; k <= F::kFractionBits; ++k) {
    EXPECT_EQ(F::fromRatio(1, int64_t{1} << k)->raw(), int64_t{1} << (F::kFractionBits - k));
    EXPECT_EQ(F::fromRatio(-1, int64_t{1} << k)->raw(), -(int64_t{1} << (F::kFractionBits - k)));
  }
}

TYPED_TEST(FixedAnyFormat, FromRatioIsWithinHalfUlpAndRoundsTiesUp) {
  using F = TypeParam;
  std::mt19937_64 rng(5);
  for (int i = 0; i < 100000; ++i) {
    const int64_t numerator = static_cast<int64_t>(rng()) >> (rng() % 64);
    int64_t denominator = static_cast<int64_t>(rng()) >> (rng() % 64);
    if (denominator == 0) {
      denominator = 7;
    }
    const auto result = F::fromRatio(numerator, denominator);
    const Int128 exact_times_d = Int128{numerator} * F::kOneRaw;  // ratio * 2^F * d
    if (!result) {
      // Refused only when the correctly rounded raw is outside int32.
      const auto expected = referenceDivShiftRound(numerator, denominator, F::kFractionBits);
      ASSERT_TRUE(!expected || *expected > kInt32Max || *expected < kInt32Min)
          << numerator << " / " << denominator;
      continue;
    }
    // |raw - n * 2^F / d| <= 1/2  <=>  |2 * (raw * d - n * 2^F)| <= |d|, exactly.
    const Int128 twice_error = 2 * (Int128{result->raw()} * denominator - exact_times_d);
    const Int128 abs_d = denominator < 0 ? -Int128{denominator} : Int128{denominator};
    const Int128 abs_twice_error = twice_error < 0 ? -twice_error : twice_error;
    ASSERT_LE(abs_twice_error, abs_d)
        << numerator << " / " << denominator << " gave " << ::testing::PrintToString(*result);
    if (abs_twice_error == abs_d) {  // a tie: must have rounded toward +infinity
      const Int128 error_sign = denominator < 0 ? -twice_error : twice_error;
      ASSERT_GT(error_sign, 0) << numerator << " / " << denominator;
    }
  }
  EXPECT_EQ(F::fromRatio(1, 0), std::nullopt);
  EXPECT_EQ(F::fromRatio(0, 0), std::nullopt);
  // Half an ulp exactly: ties go up, also for negatives.
  EXPECT_EQ(F::fromRatio(1, int64_t{F::kOneRaw} * 2)->raw(), 1);
  EXPECT_EQ(F::fromRatio(-1, int64_t{F::kOneRaw} * 2)->raw(), 0);
  EXPECT_EQ(F::fromRatio(3, int64_t{F::kOneRaw} * 2)->raw(), 2);
  EXPECT_EQ(F::fromRatio(-3, int64_t{F::kOneRaw} * 2)->raw(), -1);
}

TYPED_TEST(FixedAnyFormat, ProductsAreWithinHalfUlpVersusLongDouble) {
  if (std::numeric_limits<long double>::digits < 63) {  // ARM EABI: long double is double
    GTEST_SKIP() << "long double has no 64-bit mantissa here; MulShiftRound checks the same "
                    "products exactly against Int128";
  }
  using F = TypeParam;
  std::mt19937_64 rng(6);
  int compared = 0;
  for (int i = 0; i < 100000; ++i) {
    const F a = F::fromRaw(static_cast<int32_t>(static_cast<int64_t>(rng()) >> (32 + rng() % 32)));
    const F b = F::fromRaw(static_cast<int32_t>(static_cast<int64_t>(rng()) >> (32 + rng() % 32)));
    // Exact in long double: |a.raw * b.raw| < 2^62 fits the 64-bit mantissa.
    const long double exact_raw =
        static_cast<long double>(int64_t{a.raw()} * b.raw()) / static_cast<long double>(F::kOneRaw);
    const auto checked = F::checkedMul(a, b);
    if (exact_raw > kInt32Max + 0.5L || exact_raw < kInt32Min - 0.5L) {
      ASSERT_EQ(checked, std::nullopt)
          << ::testing::PrintToString(a) << " * " << ::testing::PrintToString(b);
      continue;
    }
    if (!checked) {  // only the rounding tie just above INT32_MAX may be refused
      ASSERT_EQ(exact_raw, kInt32Max + 0.5L);
      continue;
    }
    ++compared;
    const long double error_ulp = static_cast<long double>(checked->raw()) - exact_raw;
    ASSERT_LE(error_ulp, 0.5L) << ::testing::PrintToString(a) << " * "
                               << ::testing::PrintToString(b);
    ASSERT_GT(error_ulp, -0.5L) << "ties must round up: " << ::testing::PrintToString(a) << " * "
                                << ::testing::PrintToString(b);
    ASSERT_EQ(a * b, *checked);  // the hot-path operator agrees wherever it is allowed
  }
  EXPECT_GT(compared, 50000);
}

TYPED_TEST(FixedAnyFormat, QuotientsAreWithinHalfUlpAndDivisionByZeroIsRefused) {
  using F = TypeParam;
  std::mt19937_64 rng(7);
  for (int i = 0; i < 50000; ++i) {
    const auto a = static_cast<int32_t>(rng());
    const auto b = static_cast<int32_t>(static_cast<int64_t>(rng()) >> (32 + rng() % 32));
    const auto quotient = F::checkedDiv(F::fromRaw(a), F::fromRaw(b));
    const auto expected = referenceDivShiftRound(a, b, F::kFractionBits);
    if (!expected || *expected > kInt32Max || *expected < kInt32Min) {
      ASSERT_EQ(quotient, std::nullopt);
    } else {
      ASSERT_TRUE(quotient);
      ASSERT_EQ(quotient->raw(), *expected) << a << " / " << b;
    }
  }
  EXPECT_EQ(F::checkedDiv(F::fromRaw(1), F{}), std::nullopt);
}

TYPED_TEST(FixedAnyFormat, CheckedAddAndSubRefuseExactlyAtTheInt32Boundary) {
  using F = TypeParam;
  const F one_ulp = F::fromRaw(1);
  EXPECT_EQ(F::checkedAdd(F::fromRaw(kInt32Max - 1), one_ulp), F::fromRaw(kInt32Max));
  EXPECT_EQ(F::checkedAdd(F::fromRaw(kInt32Max), one_ulp), std::nullopt);
  EXPECT_EQ(F::checkedAdd(F::fromRaw(kInt32Min), -one_ulp), std::nullopt);
  EXPECT_EQ(F::checkedSub(F::fromRaw(kInt32Min + 1), one_ulp), F::fromRaw(kInt32Min));
  EXPECT_EQ(F::checkedSub(F::fromRaw(kInt32Min), one_ulp), std::nullopt);
  EXPECT_EQ(F::checkedSub(F{}, F::fromRaw(kInt32Min)), std::nullopt);  // -(-2^31)
  EXPECT_EQ(F::checkedSub(F::fromRaw(-1), F::fromRaw(kInt32Min)), F::fromRaw(kInt32Max));
}

// ---------------------------------------------------------------------------------------------
// fixed.h: specific values.

TEST(Fixed, SumsDifferencesAndProductsOfRepresentableValuesAreExact) {
  const Q15 three = *Q15::fromInt(3);
  const Q15 half = *Q15::fromRatio(1, 2);
  const Q15 quarter = *Q15::fromRatio(1, 4);
  EXPECT_EQ(three + half, *Q15::fromRatio(7, 2));
  EXPECT_EQ(half - three, *Q15::fromRatio(-5, 2));
  EXPECT_EQ(three * half, *Q15::fromRatio(3, 2));
  EXPECT_EQ(half * quarter, *Q15::fromRatio(1, 8));
  EXPECT_EQ(-three, *Q15::fromInt(-3));
  Q15 accumulator;
  accumulator += three;
  accumulator -= quarter;
  EXPECT_EQ(accumulator, *Q15::fromRatio(11, 4));
  // An integer times any value is exact when it fits.
  std::mt19937_64 rng(8);
  for (int i = 0; i < 10000; ++i) {
    const auto integer = static_cast<int32_t>(rng() % 201) - 100;
    const auto raw = static_cast<int32_t>(static_cast<int64_t>(rng()) >> 40);  // |raw| < 2^23
    EXPECT_EQ(*Q15::fromInt(integer) * Q15::fromRaw(raw), Q15::fromRaw(integer * raw));
  }
}

TEST(Fixed, ComparisonsOrderByValue) {
  EXPECT_LT(Q15::fromRaw(kInt32Min), Q15::fromRaw(-1));
  EXPECT_LT(Q15::fromRaw(-1), Q15{});
  EXPECT_GT(*Q15::fromInt(1), *Q15::fromRatio(1, 2));
  EXPECT_EQ(*Q15::fromRatio(2, 4), *Q15::fromRatio(1, 2));
  EXPECT_NE(Q15::fromRaw(1), Q15{});
  EXPECT_TRUE((*Q15::fromInt(2) <=> *Q15::fromInt(2)) == 0);
}

TEST(Fixed, RoundToIntRoundsTiesUpAndFloorToIntRoundsDown) {
  struct Case {
    int64_t numerator, denominator;
    int32_t expected_round, expected_floor;
  };
  const Case cases[] = {{5, 2, 3, 2},       {-5, 2, -2, -3},  {9, 4, 2, 2},   {-9, 4, -2, -3},
                        {11, 4, 3, 2},      {-11, 4, -3, -3}, {-1, 2, 0, -1}, {1, 2, 1, 0},
                        {-1, 32768, 0, -1}, {-2, 1, -2, -2},  {0, 1, 0, 0}};
  for (const Case& c : cases) {
    const Q15 value = *Q15::fromRatio(c.numerator, c.denominator);
    EXPECT_EQ(value.roundToInt(), c.expected_round) << ::testing::PrintToString(value);
    EXPECT_EQ(value.floorToInt(), c.expected_floor) << ::testing::PrintToString(value);
  }
  EXPECT_EQ(Q15::fromRaw(kInt32Max).roundToInt(), 65536);  // 65535.99997 rounds up, still fits
  EXPECT_EQ(Q15::fromRaw(kInt32Max).floorToInt(), 65535);
  EXPECT_EQ(Q15::fromRaw(kInt32Min).roundToInt(), -65536);
  EXPECT_EQ(Q15::fromRaw(kInt32Min).floorToInt(), -65536);
  EXPECT_EQ(Fixed<30>::fromRaw(kInt32Max).roundToInt(), 2);
  EXPECT_EQ(Fixed<1>::fromRaw(-3).roundToInt(), -1);  // -1.5 -> -1
  EXPECT_EQ(Fixed<1>::fromRaw(-3).floorToInt(), -2);
}

TEST(Fixed, CheckedMulRefusesExactlyAtTheBoundaryIncludingRoundingUpToIt) {
  const Q15 two = *Q15::fromInt(2);
  EXPECT_EQ(Q15::checkedMul(two, Q15::fromRaw((1 << 30) - 1)), Q15::fromRaw(kInt32Max - 1));
  EXPECT_EQ(Q15::checkedMul(two, Q15::fromRaw(1 << 30)), std::nullopt);
  EXPECT_EQ(Q15::checkedMul(two, Q15::fromRaw(-(1 << 30))), Q15::fromRaw(kInt32Min));
  EXPECT_EQ(Q15::checkedMul(two, Q15::fromRaw(-(1 << 30) - 1)), std::nullopt);
  // raw product 2^46 - 2^14 = (2^31 - 1/2) * 2^15: the tie rounds up to 2^31, which is refused;
  // a smaller first factor gives 2^31 - 2.49997 ulp, which rounds down to 2^31 - 2.
  const Q15 a = Q15::fromRaw(1073758208);  // 2^14 * 65537
  const Q15 b = Q15::fromRaw(65535);       // (2^32 - 1) / 65537
  EXPECT_EQ(Q15::checkedMul(a, b), std::nullopt);
  EXPECT_EQ(Q15::checkedMul(Q15::fromRaw(1073758207), b), Q15::fromRaw(kInt32Max - 1));
  // 1.5 * (2^32 - 1) / 3 ulp = 2^31 - 1/2 ulp: the tie rounds up out of range;
  // -(2^31 - 1/2) ulp rounds up to -2^31 + 1, which fits.
  const Q15 three_halves = *Q15::fromRatio(3, 2);
  EXPECT_EQ(Q15::checkedMul(three_halves, Q15::fromRaw(1431655765)), std::nullopt);
  EXPECT_EQ(Q15::checkedMul(three_halves, Q15::fromRaw(-1431655765)), Q15::fromRaw(kInt32Min + 1));
  // Q1.30: -2 is the smallest value; (-2) * (-1) = 2 does not fit, (-2) * 0.5 = -1 does.
  using Q30 = Fixed<30>;
  EXPECT_EQ(Q30::checkedMul(Q30::fromRaw(kInt32Min), *Q30::fromInt(-1)), std::nullopt);
  EXPECT_EQ(Q30::checkedMul(Q30::fromRaw(kInt32Min), *Q30::fromRatio(1, 2)), *Q30::fromInt(-1));
  EXPECT_EQ(Q30::checkedMul(*Q30::fromInt(-1), *Q30::fromInt(-1)), *Q30::fromInt(1));
}

TEST(Fixed, CheckedDivRefusesExactlyAtTheBoundary) {
  const Q15 half = *Q15::fromRatio(1, 2);
  EXPECT_EQ(Q15::checkedDiv(Q15::fromRaw((1 << 30) - 1), half), Q15::fromRaw(kInt32Max - 1));
  EXPECT_EQ(Q15::checkedDiv(Q15::fromRaw(1 << 30), half), std::nullopt);
  EXPECT_EQ(Q15::checkedDiv(Q15::fromRaw(-(1 << 30)), half), Q15::fromRaw(kInt32Min));
  EXPECT_EQ(Q15::checkedDiv(Q15::fromRaw(-(1 << 30) - 1), half), std::nullopt);
  EXPECT_EQ(Q15::checkedDiv(Q15::fromRaw(kInt32Min), *Q15::fromInt(-1)), std::nullopt);
  EXPECT_EQ(Q15::checkedDiv(*Q15::fromInt(1), *Q15::fromInt(3)), Q15::fromRaw(10923));  // 10922.67
  EXPECT_EQ(Q15::checkedDiv(*Q15::fromInt(-1), *Q15::fromInt(3)), Q15::fromRaw(-10923));
}

TEST(Fixed, FractionBitsAtBothEndsOfTheRangeRoundCorrectly) {
  EXPECT_EQ(Fixed<30>::fromRatio(1, 3)->raw(), 357913941);  // 2^30 / 3 = 357913941.33
  EXPECT_EQ(Fixed<30>::fromRatio(2, 3)->raw(), 715827883);  // .67 rounds up
  EXPECT_EQ(Fixed<1>::fromRatio(1, 3)->raw(), 1);           // 2/3 -> 1 (0.5)
  EXPECT_EQ(Fixed<1>::fromRatio(1, 4)->raw(), 1);           // tie 1/2 ulp -> up
  EXPECT_EQ(Fixed<1>::fromRatio(-1, 4)->raw(), 0);          // tie -1/2 ulp -> up
  EXPECT_EQ(Fixed<1>::fromInt((1 << 30) - 1)->raw(), kInt32Max - 1);
  EXPECT_EQ(Fixed<1>::fromInt(1 << 30), std::nullopt);
  EXPECT_EQ(Fixed<1>::fromInt(-(1 << 30))->raw(), kInt32Min);
}

TEST(Fixed, ConvertWideningIsExactAndRefusesValuesThatDoNotFit) {
  EXPECT_EQ(Q15::fromRaw(12345).convert<16>(), Q16::fromRaw(24690));
  EXPECT_EQ(Q15::fromInt(32767)->convert<16>(), Q16::fromInt(32767));
  EXPECT_EQ(Q15::fromInt(32768)->convert<16>(), std::nullopt);
  EXPECT_EQ(Q15::fromInt(-32768)->convert<16>(), Q16::fromInt(-32768));
  EXPECT_EQ(Q15::fromInt(-32769)->convert<16>(), std::nullopt);
  EXPECT_EQ(Fixed<1>::fromInt(1)->convert<30>(), Fixed<30>::fromInt(1));
  EXPECT_EQ(Fixed<1>::fromRaw(-4).convert<30>(), Fixed<30>::fromRaw(kInt32Min));  // -2
  EXPECT_EQ(Fixed<1>::fromInt(2)->convert<30>(), std::nullopt);
  EXPECT_EQ(Fixed<1>::fromRaw(-5).convert<30>(), std::nullopt);  // -2.5
  EXPECT_EQ(Q15::fromRaw(-7).convert<15>(), Q15::fromRaw(-7));
}

TEST(Fixed, ConvertNarrowingRoundsToNearestWithTiesUp) {
  EXPECT_EQ(Q16::fromRaw(3).convert<15>(), Q15::fromRaw(2));    // 1.5 ulp -> 2
  EXPECT_EQ(Q16::fromRaw(-3).convert<15>(), Q15::fromRaw(-1));  // -1.5 ulp -> -1
  EXPECT_EQ(Q16::fromRaw(kInt32Max).convert<15>(), Q15::fromRaw(1 << 30));
  EXPECT_EQ(Q16::fromRaw(kInt32Min).convert<15>(), Q15::fromRaw(-(1 << 30)));
  // Q1.30 -> Q30.1: 0.75 -> 1.5 ulp -> 2 ulp = 1.0; -0.75 -> -1.5 ulp -> -1 ulp = -0.5.
  EXPECT_EQ(Fixed<30>::fromRatio(3, 4)->convert<1>(), Fixed<1>::fromInt(1));
  EXPECT_EQ(Fixed<30>::fromRatio(-3, 4)->convert<1>(), Fixed<1>::fromRatio(-1, 2));
  EXPECT_EQ(Fixed<30>::fromRaw(kInt32Max).convert<1>(), Fixed<1>::fromInt(2));
  // A round trip through a wider format is the identity.
  std::mt19937_64 rng(9);
  for (int i = 0; i < 10000; ++i) {
    const Q15 value = Q15::fromRaw(static_cast<int32_t>(static_cast<int64_t>(rng()) >> 33));
    EXPECT_EQ(value.convert<16>()->convert<15>(), value);
  }
}

TEST(Fixed, WorksInConstantExpressions) {
  constexpr Q15 kThreeHalves = *Q15::fromRatio(3, 2);
  static_assert(kThreeHalves.raw() == 49152);
  static_assert((kThreeHalves * kThreeHalves).raw() == 73728);  // 2.25
  static_assert(!Q15::fromInt(65536));
  static_assert(!std::is_constructible_v<Q15, double>);
  static_assert(!std::is_constructible_v<Q15, float>);
  static_assert(!std::is_constructible_v<Q15, int>);
  static_assert(!std::is_convertible_v<Q15, double>);
  static_assert(!std::is_convertible_v<Q15, int>);
  SUCCEED();
}

}  // namespace

namespace octopoint {
namespace {

// longDivide (what a Cortex-M divides with, having no 64-bit divide instruction) gives the
// hardware's quotient and remainder: at the extremes and on a million random pairs of every
// width, so that the perspective frames of the bare-metal builds are the desktop's.
TEST(LongDivide, QuotientAndRemainderAreTheHardwares) {
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t edges[] = {
      0, 1, 2, 3, 7, 0xFFFF'FFFF, 0x1'0000'0000, kMax / 2, kMax / 2 + 1, kMax - 1, kMax};
  for (const std::uint64_t n : edges) {
    for (const std::uint64_t d : edges) {
      if (d == 0) continue;
      const UnsignedDivision division = longDivide(n, d);
      EXPECT_EQ(division.quotient, n / d) << n << " / " << d;
      EXPECT_EQ(division.remainder, n % d) << n << " % " << d;
    }
  }
  std::mt19937_64 random(2026);
  for (int i = 0; i < 1'000'000; ++i) {
    const std::uint64_t n = random() >> (random() % 64);
    const std::uint64_t d = std::max<std::uint64_t>(1, random() >> (random() % 64));
    const UnsignedDivision division = longDivide(n, d);
    ASSERT_EQ(division.quotient, n / d) << n << " / " << d;
    ASSERT_EQ(division.remainder, n % d) << n << " % " << d;
  }
}

// longDivideNarrow (a Cortex-M's division by a divisor below 2^32) likewise: the extremes (a high
// word below, equal to and above the divisor; the doubled remainder carrying out of its word) and
// a million random pairs.
TEST(LongDivide, NarrowQuotientAndRemainderAreTheHardwares) {
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t numerators[] = {
      0,        1,        0xFFFF'FFFF, 0x1'0000'0000,         0x1'FFFF'FFFF,
      kMax / 2, kMax - 1, kMax,        0xFFFF'FFFE'0000'0001, 0x8000'0000'0000'0000};
  const std::uint32_t divisors[] = {1,           2,           3,           7,          0x7FFF'FFFF,
                                    0x8000'0000, 0x8000'0001, 0xFFFF'FFFE, 0xFFFF'FFFF};
  for (const std::uint64_t n : numerators) {
    for (const std::uint32_t d : divisors) {
      const UnsignedDivision division = longDivideNarrow(n, d);
      EXPECT_EQ(division.quotient, n / d) << n << " / " << d;
      EXPECT_EQ(division.remainder, n % d) << n << " % " << d;
    }
  }
  std::mt19937_64 random(2027);
  for (int i = 0; i < 1'000'000; ++i) {
    const std::uint64_t n = random() >> (random() % 64);
    const auto d =
        std::max<std::uint32_t>(1, static_cast<std::uint32_t>(random() >> 32) >> (random() % 32));
    const UnsignedDivision division = longDivideNarrow(n, d);
    ASSERT_EQ(division.quotient, n / d) << n << " / " << d;
    ASSERT_EQ(division.remainder, n % d) << n << " % " << d;
  }
}

}  // namespace
}  // namespace octopoint
