// How a held key moves a walking eye (renderer/walk_motion.h).

#include "renderer/walk_motion.h"

#include <algorithm>

#include "fixedpoint/trig.h"

namespace octopoint {
namespace {

constexpr std::int64_t kEyeLimit = kMaxEyeDistance * kPerspectiveUnit;  // Q.24, each axis

// `distance` (Q.24) times a Q1.30 sine or cosine, rounded.
std::int64_t along(std::int64_t distance, std::int32_t sine_q30) {
  // The distance is at most 4 * kEyeLimit (2^33): the product fits.
  return mulShiftRoundQuick(distance, sine_q30, 30).value_or(0);
}

std::int64_t clampEye(std::int64_t coordinate) {
  return std::clamp(coordinate, -kEyeLimit, kEyeLimit);
}

}  // namespace

std::int64_t walkDistance(std::int64_t held_us, std::int64_t speed) {
  return std::min(held_us / 1'000'000 * speed + held_us % 1'000'000 * speed / 1'000'000,
                  4 * kEyeLimit);
}

ModelPoint walkedEye(const ModelPoint& eye, Angle yaw, WalkStep step, std::int64_t distance) {
  const std::int32_t sine = sinQ30(yaw), cosine = cosQ30(yaw);
  // Forward is (sin yaw, 0, cos yaw), right (cos yaw, 0, -sin yaw), up -y.
  std::int64_t dx = 0, dy = 0, dz = 0;
  switch (step) {
    case WalkStep::kForward:
      dx = along(distance, sine), dz = along(distance, cosine);
      break;
    case WalkStep::kBack:
      dx = -along(distance, sine), dz = -along(distance, cosine);
      break;
    case WalkStep::kRight:
      dx = along(distance, cosine), dz = -along(distance, sine);
      break;
    case WalkStep::kLeft:
      dx = -along(distance, cosine), dz = along(distance, sine);
      break;
    case WalkStep::kUp:
      dy = -distance;
      break;
    case WalkStep::kDown:
      dy = distance;
      break;
  }
  return withinReach({eye.x + dx, eye.y + dy, eye.z + dz});
}

ModelPoint withinReach(const ModelPoint& eye) {
  return {clampEye(eye.x), clampEye(eye.y), clampEye(eye.z)};
}

Angle turnedPitch(Angle pitch, std::int32_t turn) {
  // In 64 bits: any turn the page passes (an int32) adds without overflow.
  constexpr std::int64_t kQuarter = Angle::kUnitsPerTurn / 4;
  const std::int64_t units = pitch.turns16();
  const std::int64_t signed_units =
      units > Angle::kUnitsPerTurn / 2 ? units - Angle::kUnitsPerTurn : units;
  return Angle::fromTurns16(
      static_cast<std::int32_t>(std::clamp(signed_units + turn, -kQuarter, kQuarter)));
}

}  // namespace octopoint
