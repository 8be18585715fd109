// Angle: an integer angle in units of 1/65536 turn ("turns16"), normalised to [0, 65535], so
// arithmetic wraps like the circle does (360 degrees == 0, -90 degrees == 270 degrees).
// One unit is 360/65536 ~= 0.0055 degrees. Pure integer, no radians.
#pragma once

#include <cstdint>

namespace octopoint {

class Angle {
 public:
  static constexpr int32_t kUnitsPerTurn = 65536;

  constexpr Angle() = default;  // 0

  // `units` / 65536 turn, reduced modulo one turn (floor modulo: -1 -> 65535).
  static constexpr Angle fromTurns16(int64_t units) {
    Angle result;
    // Two's complement & is the floor modulo by a power of two, also for negative units.
    result.turns16_ = static_cast<int32_t>(units & (kUnitsPerTurn - 1));
    return result;
  }

  // Whole degrees, rounded to the nearest unit (1 degree = 65536/360 units). A result is never
  // exactly halfway between two units (that would need 45 | degrees, which gives an exact unit).
  static constexpr Angle fromDegrees(int64_t degrees) { return fromScaledDegrees(degrees, 360); }

  // Thousandths of a degree, rounded to the nearest unit; never exactly halfway either
  // (that would need 5625 | millidegrees, which gives an exact unit).
  static constexpr Angle fromMilliDegrees(int64_t millidegrees) {
    return fromScaledDegrees(millidegrees, 360000);
  }

  // The angle in units of 1/65536 turn, in [0, 65535].
  constexpr int32_t turns16() const { return turns16_; }

  friend constexpr Angle operator+(Angle a, Angle b) {
    return fromTurns16(int64_t{a.turns16_} + b.turns16_);
  }
  friend constexpr Angle operator-(Angle a, Angle b) {
    return fromTurns16(int64_t{a.turns16_} - b.turns16_);
  }
  friend constexpr Angle operator-(Angle a) { return fromTurns16(-int64_t{a.turns16_}); }
  friend constexpr bool operator==(Angle, Angle) = default;

 private:
  // value / units_per_turn turns, rounded to nearest unit (ties toward +infinity).
  // Reduce modulo one turn first so value * 65536 cannot overflow for any int64 input: a whole
  // number of turns is a whole number of units, so the reduction does not change the rounding.
  static constexpr Angle fromScaledDegrees(int64_t value, int64_t units_per_turn) {
    int64_t reduced = value % units_per_turn;  // in (-units_per_turn, units_per_turn)
    if (reduced < 0) {
      reduced += units_per_turn;
    }
    // floor(reduced * 65536 / units_per_turn + 1/2) = floor((2 * reduced * 65536 + d) / (2 * d));
    // 2 * 360000 * 65536 < 2^36: no overflow.
    const int64_t units = (2 * reduced * kUnitsPerTurn + units_per_turn) / (2 * units_per_turn);
    return fromTurns16(units);  // 65536 (rounded up from just below a full turn) wraps to 0
  }

  int32_t turns16_ = 0;
};

}  // namespace octopoint
