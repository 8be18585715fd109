// How held keys move the view (interactive/view_motion.h).

#include "interactive/view_motion.h"

#include "renderer/collision_move.h"
#include "renderer/perspective.h"
#include "renderer/walk_motion.h"

namespace octopoint {
namespace {

// The turn of a key held for `held_us` at `degrees_per_second`, in 1/65536 turn (int64: a key held
// for days at 360 degrees per second stays far below 2^63).
Angle turnFor(std::int64_t held_us, std::int32_t degrees_per_second) {
  const std::int64_t units =
      held_us * degrees_per_second * Angle::kUnitsPerTurn / (360 * 1'000'000);
  return Angle::fromTurns16(units);
}

}  // namespace

// Walk mode: the eye moved by a key held for `held_us`: forward and back along the look's yaw,
// level (the pitch does not tip the walk), sideways at right angles to it, up and down along -y
// and +y (the model's y points down); with collision, from where it was toward there, stopping
// short of the model and sliding along it (renderer/collision_move.h): a function of the held
// time still, so every frame of a hold shows the same walk.
WalkEye walked(WalkEye walker, NavigationKey key, std::int64_t held_us, std::int64_t speed,
               const WalkCollision& collision) {
  WalkStep step = WalkStep::kForward;
  switch (key) {
    case NavigationKey::kPitchUp:
      break;
    case NavigationKey::kPitchDown:
      step = WalkStep::kBack;
      break;
    case NavigationKey::kYawRight:
      step = WalkStep::kRight;
      break;
    case NavigationKey::kYawLeft:
      step = WalkStep::kLeft;
      break;
    case NavigationKey::kRise:
      step = WalkStep::kUp;
      break;
    case NavigationKey::kSink:
      step = WalkStep::kDown;
      break;
    case NavigationKey::kDrag:
      return walker;
  }
  const ModelPoint to = walkedEye(walker.eye, walker.yaw, step, walkDistance(held_us, speed));
  if (collision.world == nullptr) {
    walker.eye = to;
    return walker;
  }
  const ModelPoint moved = moveWithCollision(*collision.world, collision.body, walker.eye, to).eye;
  walker.eye = withinReach(moved);
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

}  // namespace octopoint
