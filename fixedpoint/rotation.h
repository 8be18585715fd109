// 3x3 rotation matrices in Q1.30 built from integer angles.
//
// Frame (camera / computer-vision convention): x right, y down, z away from the viewer.
//   yaw   = rotation about y: Ry(a) = [[c, 0, s], [0, 1, 0], [-s, 0, c]]
//   pitch = rotation about x: Rx(a) = [[1, 0, 0], [0, c, -s], [0, s, c]]
//   roll  = rotation about z: Rz(a) = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
// and R = Rz(roll) * Rx(pitch) * Ry(yaw): yaw is applied first, roll last (v' = R v).
// Example: yaw of +90 degrees maps x = (1, 0, 0) to (0, 0, -1), i.e. x to -z, and z to +x.
#pragma once

#include <array>
#include <cstdint>

#include "fixedpoint/angle.h"

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
