// How held keys move the view (interactive/view_motion.h).

#include "interactive/view_motion.h"

#include <algorithm>

#include "fixedpoint/trig.h"
#include "renderer/collision_move.h"
#include "renderer/perspective.h"

namespace octopoint {
namespace {

// The turn of a key held for `held_us` at `degrees_per_second`, in 1/65536 turn (int64: a key held
// for days at 360 degrees per second stays far below 2^63).
Angle turnFor(std::int64_t held_us, std::int32_t degrees_per_second) {
  const std::int64_t units =
      held_us * degrees_per_second * Angle::kUnitsPerTurn / (360 * 1'000'000);
  return Angle::fromTurns16(units);
}

// How far the eye walks in `held_us` at `speed` (Q.24 cube edges per second): exact to the unit
// below, whole seconds and the rest apart so that nothing overflows (speed <= 2^30).
std::int64_t walkDistance(std::int64_t held_us, std::int64_t speed) {
  return held_us / 1'000'000 * speed + held_us % 1'000'000 * speed / 1'000'000;
}

// `distance` (Q.24) times a Q1.30 sine.
std::int64_t along(std::int64_t distance, std::int32_t sine_q30) {
  // The eye stays within kMaxEyeDistance cube edges: the product's result fits.
  return mulShiftRoundQuick(distance, sine_q30, 30).value_or(0);
}

// Keeps the eye where the camera holds it (renderer/perspective.h).
std::int64_t clampEye(std::int64_t coordinate) {
  constexpr std::int64_t kLimit = kMaxEyeDistance * kPerspectiveUnit;
  return std::clamp(coordinate, -kLimit, kLimit);
}

}  // namespace

// Walk mode: the eye moved by a key held for `held_us`: forward and back along the look's yaw,
// level (the pitch does not tip the walk), sideways at right angles to it, up and down along -y
// and +y (the model's y points down); with collision, from where it was toward there, stopping
// short of the model and sliding along it (renderer/collision_move.h): a function of the held
// time still, so every frame of a hold shows the same walk.
WalkEye walked(WalkEye walker, NavigationKey key, std::int64_t held_us, std::int64_t speed,
               const WalkCollision& collision) {
  // Clamped: the eye cannot leave the camera's reach, so a day's hold gives the same.
  const std::int64_t distance =
      std::min(walkDistance(held_us, speed), 4 * kMaxEyeDistance * kPerspectiveUnit);
  const std::int32_t sine = sinQ30(walker.yaw), cosine = cosQ30(walker.yaw);
  // Forward is (sin yaw, 0, cos yaw), right (cos yaw, 0, -sin yaw).
  std::int64_t dx = 0, dy = 0, dz = 0;
  switch (key) {
    case NavigationKey::kPitchUp:
      dx = along(distance, sine), dz = along(distance, cosine);
      break;
    case NavigationKey::kPitchDown:
      dx = -along(distance, sine), dz = -along(distance, cosine);
      break;
    case NavigationKey::kYawRight:
      dx = along(distance, cosine), dz = -along(distance, sine);
      break;
    case NavigationKey::kYawLeft:
      dx = -along(distance, cosine), dz = along(distance, sine);
      break;
    case NavigationKey::kRise:
      dy = -distance;
      break;
    case NavigationKey::kSink:
      dy = distance;
      break;
    case NavigationKey::kDrag:
      break;
  }
  const ModelPoint to{clampEye(walker.eye.x + dx), clampEye(walker.eye.y + dy),
                      clampEye(walker.eye.z + dz)};
  if (collision.model == nullptr) {
    walker.eye = to;
    return walker;
  }
  const CollisionInstance instance{collision.model, {}};
  const ModelPoint moved = moveWithCollision({&instance, 1}, collision.body, walker.eye, to).eye;
  walker.eye = {clampEye(moved.x), clampEye(moved.y), clampEye(moved.z)};
  return walker;
}

ViewParameters moved(ViewParameters view, NavigationKey key, std::int64_t held_us,
                     std::int32_t degrees_per_second, std::int64_t walk_speed,
                     const WalkCollision& collision) {
  if (view.walk) {
    view.walker = walked(view.walker, key, held_us, walk_speed, collision);
    return view;
  }
  const Angle turn = turnFor(held_us, degrees_per_second);
  switch (key) {
    case NavigationKey::kYawLeft:
      view.yaw = view.yaw - turn;
      break;
    case NavigationKey::kYawRight:
      view.yaw = view.yaw + turn;
      break;
    case NavigationKey::kPitchUp:
      view.pitch = view.pitch - turn;
      break;
    case NavigationKey::kPitchDown:
      view.pitch = view.pitch + turn;
      break;
    case NavigationKey::kRise:
    case NavigationKey::kSink:
    case NavigationKey::kDrag:
      break;
  }
  return view;
}

// Walk mode's pitch stays within straight down .. straight up.
Angle turnedPitch(Angle pitch, std::int32_t turn) {
  constexpr std::int32_t kQuarter = Angle::kUnitsPerTurn / 4;
  const std::int32_t units = pitch.turns16();
  const std::int32_t signed_units =
      units > Angle::kUnitsPerTurn / 2 ? units - Angle::kUnitsPerTurn : units;
  return Angle::fromTurns16(std::clamp(signed_units + turn, -kQuarter, kQuarter));
}

}  // namespace octopoint
