#pragma once
// The camera's rotation R = Rz(roll) Rx(pitch) Ry(yaw) in double precision, from the same integer
// angles: what the integer rotation (octopoint/fixed.h) approximates. For reference renders and
// tests on the host; never for the renderer itself.

#include <array>
#include <cmath>

#include "octopoint/fixed.h"

namespace octopoint {

using Matrix3d = std::array<std::array<double, 3>, 3>;

inline Matrix3d referenceRotation(Angle yaw, Angle pitch, Angle roll) {
  const double radians_per_unit = 2 * std::acos(-1.0) / Angle::kUnitsPerTurn;
  const double a = yaw.turns16() * radians_per_unit, b = pitch.turns16() * radians_per_unit,
               c = roll.turns16() * radians_per_unit;
  const Matrix3d ry = {{{std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}}};
  const Matrix3d rx = {{{1, 0, 0}, {0, std::cos(b), -std::sin(b)}, {0, std::sin(b), std::cos(b)}}};
  const Matrix3d rz = {{{std::cos(c), -std::sin(c), 0}, {std::sin(c), std::cos(c), 0}, {0, 0, 1}}};
  auto multiply = [](const Matrix3d& p, const Matrix3d& q) {
    Matrix3d m{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t k = 0; k < 3; ++k) m[i][j] += p[i][k] * q[k][j];
    return m;
  };
  return multiply(rz, multiply(rx, ry));
}

}  // namespace octopoint
