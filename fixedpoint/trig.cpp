// The quarter-wave sine table, built at compile time with integer arithmetic only, and the
// symmetric lookups sinQ30 / cosQ30.
#include "fixedpoint/trig.h"

#include <cstddef>

#include "octopoint/fixed.h"

namespace octopoint {
namespace {

constexpr int kQuarterTurnUnits = Angle::kUnitsPerTurn / 4;  // 16384
constexpr int kEighthTurnUnits = Angle::kUnitsPerTurn / 8;   // 8192

// The table builder works in unsigned Q2.62: 1.0 = 2^62, and pi/2 < 2 fits with room.
constexpr uint64_t kOneQ62 = uint64_t{1} << 62;
// round(pi * 2^62): pi in Q2.62 (the leading bits of pi/4 in Q0.64, 0xC90FDAA22168C234C4C6...).
constexpr uint64_t kPiQ62 = 0xC90FDAA22168C235u;

// round(a * b / 2^62) for Q2.62 operands below 2^63, so the Q4.124 product is below 2^126 and the
// Q2.62 result below 2^64.
constexpr uint64_t mulQ62(uint64_t a, uint64_t b) {
  UInt128 product = mulWideUnsigned(a, b);                 // Q4.124
  const uint64_t low = product.low + (uint64_t{1} << 61);  // + 1/2 ulp of Q62, with carry
  product.high += low < product.low ? uint64_t{1} : uint64_t{0};
  return (product.high << 2) | (low >> 62);
}

// sin(x) when first_power == 1, cos(x) when first_power == 0, by the Taylor series
//   sum over n = first_power, first_power + 2, ... of (-1)^((n - first_power) / 2) x^n / n!,
// for x_q62 = x in Q2.62 with 0 <= x <= pi/4. Each term is the previous one times x^2 / (n+1)(n+2),
// rounded; terms fall below 2^-64 by n = 21, and each of the ~12 terms carries at most ~1 ulp of
// rounding error, so the result is within 2^-58 of the true value (the argument's own error,
// <= 0.63 ulp of Q62, moves sin/cos by no more than that since their slopes are at most 1).
// The sum is taken modulo 2^64 in unsigned arithmetic: intermediate partial sums may dip
// below zero (cos near pi/4 never does, but it costs nothing), the final value is in [0, 1].
constexpr uint64_t taylorSinOrCosQ62(uint64_t x_q62, int first_power) {
  const uint64_t x_squared_q62 = mulQ62(x_q62, x_q62);
  uint64_t term_q62 = first_power == 1 ? x_q62 : kOneQ62;  // x^n / n!, Q2.62
  uint64_t sum_q62 = 0;
  bool subtract = false;
  for (int n = first_power; term_q62 != 0; n += 2) {
    sum_q62 = subtract ? sum_q62 - term_q62 : sum_q62 + term_q62;
    subtract = !subtract;
    const auto divisor = static_cast<uint64_t>((n + 1) * (n + 2));
    term_q62 = (mulQ62(term_q62, x_squared_q62) + divisor / 2) / divisor;  // rounded to nearest
  }
  return sum_q62;
}

// round(sin(2 * pi * k / 65536) * 2^30) for k in [0, 16384]. Above an eighth of a turn use
// sin(x) = cos(pi/2 - x) so the series argument stays <= pi/4, where it converges fast.
constexpr int32_t quarterSineEntryQ30(int k) {
  const bool use_cosine = k > kEighthTurnUnits;
  const int series_units = use_cosine ? kQuarterTurnUnits - k : k;  // in [0, 8192]
  // x = 2 * pi * units / 65536 = pi * units / 2^15, in Q2.62, rounded.
  const UInt128 pi_times_units = mulWideUnsigned(kPiQ62, static_cast<uint64_t>(series_units));
  const uint64_t x_q62 =
      ((pi_times_units.high << 49) | (pi_times_units.low >> 15)) +
      ((pi_times_units.low >> 14) & 1);  // the bit below the result: round to nearest
  const uint64_t sine_q62 = taylorSinOrCosQ62(x_q62, use_cosine ? 0 : 1);  // in [0, 2^62]
  // Q2.62 -> Q1.30, rounded to nearest.
  return static_cast<int32_t>(roundShiftRight(static_cast<int64_t>(sine_q62), 62 - 30));
}

constexpr std::array<int32_t, kQuarterSineTableSize> buildQuarterSineTable() {
  std::array<int32_t, kQuarterSineTableSize> table{};
  for (int k = 0; k < kQuarterSineTableSize; ++k) {
    table[static_cast<std::size_t>(k)] = quarterSineEntryQ30(k);
  }
  return table;
}

constexpr std::array<int32_t, kQuarterSineTableSize> kBuiltTable = buildQuarterSineTable();

// Compile-time spot checks of the builder (Q1.30): the exact endpoints and sin(45 degrees).
static_assert(kBuiltTable[0] == 0);
static_assert(kBuiltTable[kQuarterTurnUnits] == int32_t{1} << 30);
static_assert(kBuiltTable[kEighthTurnUnits] == 759250125);  // round(sqrt(1/2) * 2^30)

}  // namespace

// Constant-initialised from the compile-time table: it lands in read-only data, built once.
constinit const std::array<int32_t, kQuarterSineTableSize> kQuarterSineTableQ30 = kBuiltTable;

int32_t sinQ30(Angle angle) {
  const int32_t units = angle.turns16();               // [0, 65535]
  const int32_t quadrant = units / kQuarterTurnUnits;  // 0..3
  const int32_t offset = units % kQuarterTurnUnits;    // [0, 16383]
  // Quadrants 1 and 3 run the table backwards; quadrants 2 and 3 are negative.
  const int32_t index = (quadrant & 1) != 0 ? kQuarterTurnUnits - offset : offset;
  const int32_t magnitude_q30 = kQuarterSineTableQ30[static_cast<std::size_t>(index)];
  return quadrant >= 2 ? -magnitude_q30 : magnitude_q30;
}

int32_t cosQ30(Angle angle) { return sinQ30(angle + Angle::fromTurns16(kQuarterTurnUnits)); }

}  // namespace octopoint
