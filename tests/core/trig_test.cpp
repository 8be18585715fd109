// Tests for octopoint/fixed.h and fixedpoint/trig.h. Reference: std::sin in long double
// (64-bit mantissa, error ~1e-19, i.e. ~1e-10 of a Q30 ulp).
#include "fixedpoint/trig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "octopoint/fixed.h"
#include "tests/support/exact_int128.h"

namespace {

using octopoint::test::Int128;  // exact reference arithmetic (tests/support/exact_int128.h)

using octopoint::Angle;
using octopoint::cosQ30;
using octopoint::kQuarterSineTableQ30;
using octopoint::sinQ30;

constexpr int32_t kOneQ30 = int32_t{1} << 30;
constexpr long double kTwoTo30 = 1073741824.0L;
// The documented table / sinQ30 bound in Q30 ulps: correctly rounded, |error| <= 1/2. No margin is
// needed for the reference's own error (~1e-10 ulp): the closest any exact value comes to a
// rounding tie is 1.1e-5 ulp (measured: the largest error is 0.499989), so the reference cannot
// flip a verdict, and a misrounded entry would show an error above 1/2.
constexpr long double kMaxSineErrorUlp = 0.5L;

long double exactSineQ30(int64_t units) {
  const long double radians =
      2.0L * std::numbers::pi_v<long double> * static_cast<long double>(units) / 65536.0L;
  return std::sin(radians) * kTwoTo30;
}

long double exactCosineQ30(int64_t units) {
  const long double radians =
      2.0L * std::numbers::pi_v<long double> * static_cast<long double>(units) / 65536.0L;
  return std::cos(radians) * kTwoTo30;
}

// round(value * 65536 / units_per_turn) with ties up, reduced to [0, 65535], via exact 128-bit
// arithmetic.
int32_t referenceUnits(int64_t value, int64_t units_per_turn) {
  const Int128 scaled = Int128{value} * 65536 * 2 + units_per_turn;
  const Int128 divisor = 2 * Int128{units_per_turn};
  Int128 units = scaled / divisor;
  if (scaled % divisor != 0 && scaled < 0) {
    --units;
  }
  units %= 65536;
  if (units < 0) {
    units += 65536;
  }
  return static_cast<int32_t>(units);
}

// ---------------------------------------------------------------------------------------------
// angle.h

TEST(Angle, NormalisesUnitsModuloOneTurn) {
  EXPECT_EQ(Angle::fromTurns16(0).turns16(), 0);
  EXPECT_EQ(Angle::fromTurns16(65535).turns16(), 65535);
  EXPECT_EQ(Angle::fromTurns16(65536).turns16(), 0);
  EXPECT_EQ(Angle::fromTurns16(-1).turns16(), 65535);
  EXPECT_EQ(Angle::fromTurns16(-65536 * 3 - 5).turns16(), 65531);
  EXPECT_EQ(Angle::fromTurns16(std::numeric_limits<int64_t>::min()).turns16(), 0);
  EXPECT_EQ(Angle::fromTurns16(std::numeric_limits<int64_t>::max()).turns16(), 65535);
  EXPECT_EQ(Angle{}.turns16(), 0);
}

TEST(Angle, DegreesRoundToTheNearestUnitAndWrap) {
  EXPECT_EQ(Angle::fromDegrees(0).turns16(), 0);
  EXPECT_EQ(Angle::fromDegrees(90).turns16(), 16384);
  EXPECT_EQ(Angle::fromDegrees(180).turns16(), 32768);
  EXPECT_EQ(Angle::fromDegrees(270).turns16(), 49152);
  EXPECT_EQ(Angle::fromDegrees(360), Angle{});
  EXPECT_EQ(Angle::fromDegrees(-90).turns16(), 49152);
  EXPECT_EQ(Angle::fromDegrees(-360), Angle{});
  EXPECT_EQ(Angle::fromDegrees(-450).turns16(), 49152);
  EXPECT_EQ(Angle::fromDegrees(1).turns16(), 182);          // 182.04
  EXPECT_EQ(Angle::fromDegrees(359).turns16(), 65354);      // 65353.96
  EXPECT_EQ(Angle::fromMilliDegrees(359999).turns16(), 0);  // 65535.82 rounds to a full turn
  EXPECT_EQ(Angle::fromMilliDegrees(45000).turns16(), 8192);
  EXPECT_EQ(Angle::fromMilliDegrees(-1).turns16(), 0);      // -0.18 unit
  EXPECT_EQ(Angle::fromMilliDegrees(-3).turns16(), 65535);  // -0.55 unit
  for (int64_t degrees = -1000; degrees <= 1000; ++degrees) {
    ASSERT_EQ(Angle::fromDegrees(degrees).turns16(), referenceUnits(degrees, 360)) << degrees;
  }
  for (int64_t millidegrees = -800000; millidegrees <= 800000; millidegrees += 7) {
    ASSERT_EQ(Angle::fromMilliDegrees(millidegrees).turns16(), referenceUnits(millidegrees, 360000))
        << millidegrees;
  }
}

TEST(Angle, ExtremeDegreeInputsDoNotOverflow) {
  constexpr int64_t kMin = std::numeric_limits<int64_t>::min();
  constexpr int64_t kMax = std::numeric_limits<int64_t>::max();
  EXPECT_EQ(Angle::fromDegrees(kMax).turns16(), referenceUnits(kMax, 360));
  EXPECT_EQ(Angle::fromDegrees(kMin).turns16(), referenceUnits(kMin, 360));
  EXPECT_EQ(Angle::fromMilliDegrees(kMax).turns16(), referenceUnits(kMax, 360000));
  EXPECT_EQ(Angle::fromMilliDegrees(kMin).turns16(), referenceUnits(kMin, 360000));
}

TEST(Angle, AdditionAndSubtractionWrapAroundTheCircle) {
  EXPECT_EQ(Angle::fromDegrees(270) + Angle::fromDegrees(180), Angle::fromDegrees(90));
  EXPECT_EQ(Angle::fromDegrees(90) - Angle::fromDegrees(180), Angle::fromDegrees(270));
  EXPECT_EQ(-Angle::fromDegrees(90), Angle::fromDegrees(270));
  EXPECT_EQ(-Angle{}, Angle{});
  EXPECT_EQ(Angle::fromTurns16(65535) + Angle::fromTurns16(1), Angle{});
}

// ---------------------------------------------------------------------------------------------
// trig.h

TEST(QuarterSineTable, EveryEntryIsCorrectlyRoundedVersusLongDouble) {
  long double max_error_ulp = 0;
  for (int k = 0; k < octopoint::kQuarterSineTableSize; ++k) {
    const long double exact = exactSineQ30(k);
    const long double error = static_cast<long double>(kQuarterSineTableQ30[k]) - exact;
    max_error_ulp = std::max(max_error_ulp, std::fabs(error));
    ASSERT_LE(std::fabs(error), kMaxSineErrorUlp)
        << "entry " << k << " = 0x" << std::hex << kQuarterSineTableQ30[k] << std::dec << ", exact "
        << static_cast<double>(exact);
  }
  RecordProperty("max_error_ulp_x1e9", static_cast<int>(max_error_ulp * 1e9L));
  EXPECT_EQ(kQuarterSineTableQ30.size(), 16385u);
  EXPECT_EQ(kQuarterSineTableQ30.front(), 0);
  EXPECT_EQ(kQuarterSineTableQ30.back(), kOneQ30);
}

TEST(QuarterSineTable, IsNonDecreasing) {
  for (int k = 1; k < octopoint::kQuarterSineTableSize; ++k) {
    ASSERT_LE(kQuarterSineTableQ30[k - 1], kQuarterSineTableQ30[k]) << k;
  }
}

TEST(SinCos, AreExactAtQuarterTurnsIncludingNegativeAndWrappedDegrees) {
  struct Case {
    int64_t degrees;
    int32_t sin_q30, cos_q30;
  };
  const Case cases[] = {{0, 0, kOneQ30},     {90, kOneQ30, 0},   {180, 0, -kOneQ30},
                        {270, -kOneQ30, 0},  {360, 0, kOneQ30},  {-90, -kOneQ30, 0},
                        {-180, 0, -kOneQ30}, {-360, 0, kOneQ30}, {-450, -kOneQ30, 0},
                        {450, kOneQ30, 0},   {720, 0, kOneQ30}};
  for (const Case& c : cases) {
    EXPECT_EQ(sinQ30(Angle::fromDegrees(c.degrees)), c.sin_q30) << c.degrees << " degrees";
    EXPECT_EQ(cosQ30(Angle::fromDegrees(c.degrees)), c.cos_q30) << c.degrees << " degrees";
  }
}

TEST(SinCos, EveryAngleUnitIsWithinHalfUlpOfLongDouble) {
  for (int64_t units = 0; units < Angle::kUnitsPerTurn; ++units) {
    const Angle angle = Angle::fromTurns16(units);
    ASSERT_LE(std::fabs(sinQ30(angle) - exactSineQ30(units)), kMaxSineErrorUlp) << units;
    ASSERT_LE(std::fabs(cosQ30(angle) - exactCosineQ30(units)), kMaxSineErrorUlp) << units;
    ASSERT_LE(std::abs(sinQ30(angle)), kOneQ30) << units;
  }
}

TEST(SinCos, SquaresSumToOneWithinBoundForEveryAngleUnit) {
  // s = sin + e_s, c = cos + e_c with |e| <= 1/2 ulp: s^2 + c^2 - 1 = 2 sin e_s + 2 cos e_c + e^2,
  // so |s^2 + c^2 - 1| <= (|sin| + |cos|) + 1/2^31 <= sqrt(2) + 2^-31 Q30 ulp. In Q60 integers:
  constexpr int64_t kBoundQ60 = (int64_t{1414213563} << 30) / 1000000000 + 1;  // ~sqrt(2) * 2^30
  int64_t worst_q60 = 0;
  for (int64_t units = 0; units < Angle::kUnitsPerTurn; ++units) {
    const int64_t s = sinQ30(Angle::fromTurns16(units));
    const int64_t c = cosQ30(Angle::fromTurns16(units));
    const int64_t deviation_q60 = s * s + c * c - (int64_t{1} << 60);
    worst_q60 = std::max(worst_q60, std::abs(deviation_q60));
    ASSERT_LE(std::abs(deviation_q60), kBoundQ60) << units;
  }
  RecordProperty("worst_deviation_q60", std::to_string(worst_q60));
}

TEST(SinCos, SymmetryIdentitiesHoldExactlyForEveryAngleUnit) {
  const Angle quarter_turn = Angle::fromDegrees(90);
  const Angle half_turn = Angle::fromDegrees(180);
  for (int64_t units = 0; units < Angle::kUnitsPerTurn; ++units) {
    const Angle a = Angle::fromTurns16(units);
    ASSERT_EQ(sinQ30(-a), -sinQ30(a)) << units;
    ASSERT_EQ(cosQ30(-a), cosQ30(a)) << units;
    ASSERT_EQ(cosQ30(a), sinQ30(a + quarter_turn)) << units;
    ASSERT_EQ(sinQ30(half_turn - a), sinQ30(a)) << units;
    ASSERT_EQ(sinQ30(a + half_turn), -sinQ30(a)) << units;
  }
}

}  // namespace
