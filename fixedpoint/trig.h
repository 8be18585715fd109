// Integer sine and cosine of an Angle, in Q1.30 (1.0 = 1 << 30), from a quarter-wave table that is
// built at compile time with integer arithmetic only (trig.cpp). No FPU arithmetic, no libm.
#pragma once

#include <array>
#include <cstdint>

#include "octopoint/fixed.h"

namespace octopoint {

// One entry per angle unit over a quarter turn, endpoints included:
//   kQuarterSineTableQ30[k] = round(sin(2 * pi * k / 65536) * 2^30), k in [0, 16384].
// Error: every entry is the correctly rounded value, |entry - sin * 2^30| <= 1/2 ulp (Q30).
// Why: the builder evaluates sin in Q62 with an error below 2^-55 (< 2^-25 Q30 ulp), so an entry
// could only be misrounded if sin * 2^30 were within 2^-25 of a half-integer;
// tests/core/trig_test.cpp compares all 16385 entries with a 64-bit-mantissa reference sine: all
// within 1/2 ulp (the largest error is 0.499989 ulp, so no exact value lies within 1e-5 ulp of a
// rounding tie). Exact entries: [0] = 0, [16384] = 1 << 30.
inline constexpr int kQuarterSineTableSize = Angle::kUnitsPerTurn / 4 + 1;  // 16385
extern const std::array<int32_t, kQuarterSineTableSize> kQuarterSineTableQ30;

// sin(angle) in Q1.30, from the table by quarter-wave symmetry, so:
//  - |sinQ30(a) - sin(a) * 2^30| <= 1/2 (Q30 ulp) for every angle;
//  - exact at quarter turns: 0 at 0 and 180 degrees, 1 << 30 at 90, -(1 << 30) at 270;
//  - sinQ30(-a) == -sinQ30(a) exactly; the result is always within [-(1 << 30), 1 << 30].
int32_t sinQ30(Angle angle);

// cos(angle) in Q1.30, defined as sinQ30(angle + 90 degrees), same error bound; exact identity.
int32_t cosQ30(Angle angle);

}  // namespace octopoint
