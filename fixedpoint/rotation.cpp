// Rotation matrices in Q1.30 from the integer sine table.
#include <cassert>
#include <cstddef>
#include <cstdint>

#include "fixedpoint/trig.h"
#include "octopoint/fixed.h"

namespace octopoint {
namespace {

constexpr int32_t kOneQ30 = int32_t{1} << 30;

}  // namespace

Rotation identityRotation() {
  return Rotation{{{{kOneQ30, 0, 0}, {0, kOneQ30, 0}, {0, 0, kOneQ30}}}};
}

Rotation multiplyRotations(const Rotation& lhs, const Rotation& rhs) {
  Rotation product{};
  for (std::size_t row = 0; row < 3; ++row) {
    for (std::size_t col = 0; col < 3; ++col) {
      int64_t sum_q60 = 0;  // Q2.60 products; three of them stay below 2^63
      for (std::size_t k = 0; k < 3; ++k) {
        sum_q60 += int64_t{lhs.m_q30[row][k]} * rhs.m_q30[k][col];
      }
      // Q2.60 -> Q1.30, rounded; for rotations |entry| stays near 1 << 30, far inside int32.
      const int64_t entry_q30 = roundShiftRight(sum_q60, 30);
      assert(entry_q30 >= INT32_MIN && entry_q30 <= INT32_MAX);
      product.m_q30[row][col] = static_cast<int32_t>(entry_q30);
    }
  }
  return product;
}

Rotation rotationFromYawPitchRoll(Angle yaw, Angle pitch, Angle roll) {
  const int32_t cos_yaw = cosQ30(yaw);  // all Q1.30
  const int32_t sin_yaw = sinQ30(yaw);
  const int32_t cos_pitch = cosQ30(pitch);
  const int32_t sin_pitch = sinQ30(pitch);
  const int32_t cos_roll = cosQ30(roll);
  const int32_t sin_roll = sinQ30(roll);

  const Rotation about_y{{{{cos_yaw, 0, sin_yaw}, {0, kOneQ30, 0}, {-sin_yaw, 0, cos_yaw}}}};
  const Rotation about_x{
      {{{kOneQ30, 0, 0}, {0, cos_pitch, -sin_pitch}, {0, sin_pitch, cos_pitch}}}};
  const Rotation about_z{{{{cos_roll, -sin_roll, 0}, {sin_roll, cos_roll, 0}, {0, 0, kOneQ30}}}};
  return multiplyRotations(about_z, multiplyRotations(about_x, about_y));
}

}  // namespace octopoint
