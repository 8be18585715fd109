// Tests for octopoint/fixed.h against the textbook matrices evaluated in long double.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <ostream>
#include <random>
#include <string>

#include "octopoint/fixed.h"

namespace octopoint {

// gtest prints a rotation as its Q1.30 rows in hex and in decimal.
void PrintTo(const Rotation& rotation, std::ostream* out) {
  for (const auto& row : rotation.m_q30) {
    *out << "\n  [";
    for (int32_t entry : row) {
      *out << " 0x" << std::hex << static_cast<uint32_t>(entry) << std::dec << " ("
           << static_cast<double>(entry) / (1 << 30) << ")";
    }
    *out << " ]";
  }
}

bool operator==(const Rotation& a, const Rotation& b) { return a.m_q30 == b.m_q30; }

}  // namespace octopoint

namespace {

using octopoint::Angle;
using octopoint::Rotation;
using octopoint::rotationFromYawPitchRoll;
using Matrix = std::array<std::array<long double, 3>, 3>;

// 1.0 in Q1.30, the rotation entries' format, and its scale as a long double.
constexpr int32_t kRotationOne = int32_t{1} << 30;
constexpr long double kRotationScale = 1073741824.0L;
// Documented bound (rotation.h), in Q30 ulps per entry, and for row/column dot products.
constexpr long double kEntryBoundUlp = 3.5L;
constexpr long double kOrthonormalBoundUlp = 12.2L;

long double radians(Angle angle) {
  return 2.0L * std::numbers::pi_v<long double> * angle.turns16() / 65536.0L;
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix product{};
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      for (int k = 0; k < 3; ++k) {
        product[row][col] += a[row][k] * b[k][col];
      }
    }
  }
  return product;
}

// The textbook matrices of rotation.h.
Matrix aboutY(Angle a) {
  const long double c = std::cos(radians(a)), s = std::sin(radians(a));
  return {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
}
Matrix aboutX(Angle a) {
  const long double c = std::cos(radians(a)), s = std::sin(radians(a));
  return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
}
Matrix aboutZ(Angle a) {
  const long double c = std::cos(radians(a)), s = std::sin(radians(a));
  return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}

// Largest |R_q30 - R * 2^30| over the entries, in Q30 ulps.
long double maxEntryErrorUlp(const Rotation& actual, const Matrix& exact) {
  long double worst = 0;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      worst = std::max(worst, std::fabs(actual.m_q30[row][col] - exact[row][col] * kRotationScale));
    }
  }
  return worst;
}

std::array<int64_t, 3> apply(const Rotation& rotation, std::array<int64_t, 3> v) {
  std::array<int64_t, 3> result{};
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      result[row] += rotation.m_q30[row][col] * v[col];
    }
  }
  return result;
}

TEST(Rotation, ZeroAnglesGiveTheIdentityExactly) {
  const Rotation identity = octopoint::identityRotation();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      EXPECT_EQ(identity.m_q30[row][col], row == col ? kRotationOne : 0);
    }
  }
  EXPECT_EQ(rotationFromYawPitchRoll(Angle{}, Angle{}, Angle{}), identity);
  EXPECT_EQ(rotationFromYawPitchRoll(Angle::fromDegrees(360), Angle::fromDegrees(-720),
                                     Angle::fromDegrees(1080)),
            identity);
}

TEST(Rotation, EachSingleAxisMatchesTheTextbookMatrixWithinBound) {
  long double worst = 0;
  for (int64_t units = 0; units < Angle::kUnitsPerTurn; units += 37) {
    const Angle a = Angle::fromTurns16(units);
    const Rotation yaw = rotationFromYawPitchRoll(a, Angle{}, Angle{});
    const Rotation pitch = rotationFromYawPitchRoll(Angle{}, a, Angle{});
    const Rotation roll = rotationFromYawPitchRoll(Angle{}, Angle{}, a);
    ASSERT_LE(maxEntryErrorUlp(yaw, aboutY(a)), kEntryBoundUlp)
        << units << ::testing::PrintToString(yaw);
    ASSERT_LE(maxEntryErrorUlp(pitch, aboutX(a)), kEntryBoundUlp)
        << units << ::testing::PrintToString(pitch);
    ASSERT_LE(maxEntryErrorUlp(roll, aboutZ(a)), kEntryBoundUlp)
        << units << ::testing::PrintToString(roll);
    // A single axis involves no sums, only table values: within the table's 1/2 ulp.
    worst = std::max({worst, maxEntryErrorUlp(yaw, aboutY(a)), maxEntryErrorUlp(pitch, aboutX(a)),
                      maxEntryErrorUlp(roll, aboutZ(a))});
  }
  EXPECT_LE(worst, 0.5L + 1e-6L);
}

TEST(Rotation, ComposedAnglesMatchRzRxRyWithinBound) {
  long double worst = 0;
  // A grid of 40^3 angle triples with an odd step so all quadrants and non-round units occur.
  for (int64_t yaw_units = 5; yaw_units < Angle::kUnitsPerTurn; yaw_units += 1637) {
    for (int64_t pitch_units = 11; pitch_units < Angle::kUnitsPerTurn; pitch_units += 1637) {
      for (int64_t roll_units = 3; roll_units < Angle::kUnitsPerTurn; roll_units += 1637) {
        const Angle yaw = Angle::fromTurns16(yaw_units);
        const Angle pitch = Angle::fromTurns16(pitch_units);
        const Angle roll = Angle::fromTurns16(roll_units);
        const Rotation actual = rotationFromYawPitchRoll(yaw, pitch, roll);
        const Matrix exact = multiply(aboutZ(roll), multiply(aboutX(pitch), aboutY(yaw)));
        const long double error = maxEntryErrorUlp(actual, exact);
        worst = std::max(worst, error);
        ASSERT_LE(error, kEntryBoundUlp)
            << "yaw " << yaw_units << " pitch " << pitch_units << " roll " << roll_units
            << ::testing::PrintToString(actual);
      }
    }
  }
  RecordProperty("worst_entry_error_ulp_x1000", std::to_string(static_cast<int>(worst * 1000)));
}

TEST(Rotation, RowsAndColumnsAreOrthonormalWithinBound) {
  const int64_t bound_q60 = static_cast<int64_t>(kOrthonormalBoundUlp * kRotationScale);
  for (int64_t yaw_units = 7; yaw_units < Angle::kUnitsPerTurn; yaw_units += 2711) {
    for (int64_t pitch_units = 1; pitch_units < Angle::kUnitsPerTurn; pitch_units += 2711) {
      for (int64_t roll_units = 13; roll_units < Angle::kUnitsPerTurn; roll_units += 2711) {
        const Rotation r =
            rotationFromYawPitchRoll(Angle::fromTurns16(yaw_units), Angle::fromTurns16(pitch_units),
                                     Angle::fromTurns16(roll_units));
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            int64_t rows_q60 = 0;
            int64_t columns_q60 = 0;
            for (int k = 0; k < 3; ++k) {
              rows_q60 += int64_t{r.m_q30[i][k]} * r.m_q30[j][k];
              columns_q60 += int64_t{r.m_q30[k][i]} * r.m_q30[k][j];
            }
            const int64_t expected_q60 = i == j ? int64_t{1} << 60 : 0;
            ASSERT_LE(std::abs(rows_q60 - expected_q60), bound_q60) << ::testing::PrintToString(r);
            ASSERT_LE(std::abs(columns_q60 - expected_q60), bound_q60)
                << ::testing::PrintToString(r);
          }
        }
      }
    }
  }
}

TEST(Rotation, QuarterTurnsAreExactSignedPermutations) {
  // Yaw +90: x -> -z and z -> +x (y down, z away: turning the head right).
  const Rotation yaw = rotationFromYawPitchRoll(Angle::fromDegrees(90), Angle{}, Angle{});
  EXPECT_EQ(apply(yaw, {1, 0, 0}), (std::array<int64_t, 3>{0, 0, -kRotationOne}));
  EXPECT_EQ(apply(yaw, {0, 0, 1}), (std::array<int64_t, 3>{kRotationOne, 0, 0}));
  EXPECT_EQ(apply(yaw, {0, 1, 0}), (std::array<int64_t, 3>{0, kRotationOne, 0}));
  // Pitch +90: y -> +z and z -> -y.
  const Rotation pitch = rotationFromYawPitchRoll(Angle{}, Angle::fromDegrees(90), Angle{});
  EXPECT_EQ(apply(pitch, {0, 1, 0}), (std::array<int64_t, 3>{0, 0, kRotationOne}));
  EXPECT_EQ(apply(pitch, {0, 0, 1}), (std::array<int64_t, 3>{0, -kRotationOne, 0}));
  // Roll +90: x -> +y and y -> -x.
  const Rotation roll = rotationFromYawPitchRoll(Angle{}, Angle{}, Angle::fromDegrees(90));
  EXPECT_EQ(apply(roll, {1, 0, 0}), (std::array<int64_t, 3>{0, kRotationOne, 0}));
  EXPECT_EQ(apply(roll, {0, 1, 0}), (std::array<int64_t, 3>{-kRotationOne, 0, 0}));
  // Every combination of quarter turns is the exact signed permutation of the textbook product.
  for (int yaw_q = 0; yaw_q < 4; ++yaw_q) {
    for (int pitch_q = 0; pitch_q < 4; ++pitch_q) {
      for (int roll_q = 0; roll_q < 4; ++roll_q) {
        const Angle y = Angle::fromDegrees(90 * yaw_q - 360);
        const Angle p = Angle::fromDegrees(90 * pitch_q + 720);
        const Angle r = Angle::fromDegrees(-90 * roll_q);
        const Rotation actual = rotationFromYawPitchRoll(y, p, r);
        const Matrix exact = multiply(aboutZ(r), multiply(aboutX(p), aboutY(y)));
        for (int row = 0; row < 3; ++row) {
          int nonzero = 0;
          for (int col = 0; col < 3; ++col) {
            const auto expected = static_cast<int32_t>(std::lround(exact[row][col])) * kRotationOne;
            ASSERT_EQ(actual.m_q30[row][col], expected) << ::testing::PrintToString(actual);
            nonzero += expected != 0 ? 1 : 0;
          }
          ASSERT_EQ(nonzero, 1);
        }
      }
    }
  }
}

TEST(Rotation, MultiplyRotationsRoundsEachEntryToNearestWithTiesUp) {
  std::mt19937_64 rng(10);
  for (int i = 0; i < 20000; ++i) {
    Rotation lhs{};
    Rotation rhs{};
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) {  // Q1.30 entries in [-1/2, 1/2]: sums stay in [-3/4, 3/4]
        lhs.m_q30[row][col] = static_cast<int32_t>(
            static_cast<int64_t>(rng() % (uint64_t{1} << 30 | 1)) - kRotationOne / 2);
        rhs.m_q30[row][col] = static_cast<int32_t>(
            static_cast<int64_t>(rng() % (uint64_t{1} << 30 | 1)) - kRotationOne / 2);
      }
    }
    const Rotation product = octopoint::multiplyRotations(lhs, rhs);
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) {
        int64_t sum_q60 = 0;
        for (int k = 0; k < 3; ++k) {
          sum_q60 += int64_t{lhs.m_q30[row][k]} * rhs.m_q30[k][col];
        }
        // floor(sum / 2^30 + 1/2), with floor division written out for negative sums.
        const int64_t shifted = sum_q60 + (int64_t{1} << 29);
        const int64_t expected =
            shifted >= 0 ? shifted / kRotationOne : -((-shifted + kRotationOne - 1) / kRotationOne);
        ASSERT_EQ(product.m_q30[row][col], expected)
            << ::testing::PrintToString(lhs) << ::testing::PrintToString(rhs);
      }
    }
  }
  // One ulp times one half is a tie: +1/2 ulp rounds up to 1, -1/2 ulp rounds up to 0.
  Rotation tiny{};
  tiny.m_q30[0][0] = 1;
  Rotation half{};
  half.m_q30[0][0] = kRotationOne / 2;
  EXPECT_EQ(octopoint::multiplyRotations(tiny, half).m_q30[0][0], 1);
  half.m_q30[0][0] = -kRotationOne / 2;
  EXPECT_EQ(octopoint::multiplyRotations(tiny, half).m_q30[0][0], 0);
}

TEST(Rotation, MultiplyingByTheIdentityIsExactAndComposesInApplyOrder) {
  const Rotation r = rotationFromYawPitchRoll(Angle::fromDegrees(17), Angle::fromDegrees(-33),
                                              Angle::fromMilliDegrees(123456));
  EXPECT_EQ(octopoint::multiplyRotations(r, octopoint::identityRotation()), r);
  EXPECT_EQ(octopoint::multiplyRotations(octopoint::identityRotation(), r), r);
  // Roll alone after yaw alone equals the roll * yaw composition within the documented bound.
  const Angle yaw = Angle::fromDegrees(30);
  const Angle roll = Angle::fromDegrees(50);
  const Rotation composed =
      octopoint::multiplyRotations(rotationFromYawPitchRoll(Angle{}, Angle{}, roll),
                                   rotationFromYawPitchRoll(yaw, Angle{}, Angle{}));
  EXPECT_LE(maxEntryErrorUlp(composed, multiply(aboutZ(roll), aboutY(yaw))), kEntryBoundUlp);
}

}  // namespace
