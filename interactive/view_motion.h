#pragma once
// How held keys move the view of octopoint-view (octopoint/interactive.h): in orbit mode each key
// turns the model by its time held, in walk mode it moves the eye (with collision, stopping short
// of the model and sliding along it); a function of the held time alone, so every frame of a hold
// shows the same motion whatever the frame rate.

#include <cstdint>

#include "octopoint/interactive.h"
#include "renderer/collision_move.h"
#include "renderer/walk_motion.h"  // turnedPitch

namespace octopoint {

// Walk mode's collision, when on: what the eye collides with and its body.
struct WalkCollision {
  const CollisionWorld* world = nullptr;  // a model's or a scene's instances; nullptr: off
  WalkBody body;
};

// The eye moved by `key` held for `held_us` at `speed` (Q.24 cube edges per second).
WalkEye walked(WalkEye walker, NavigationKey key, std::int64_t held_us, std::int64_t speed,
               const WalkCollision& collision);

// The view moved by `key` held for `held_us`: turned at `degrees_per_second` in orbit mode, walked
// at `walk_speed` in walk mode.
ViewParameters moved(ViewParameters view, NavigationKey key, std::int64_t held_us,
                     std::int32_t degrees_per_second, std::int64_t walk_speed,
                     const WalkCollision& collision);

}  // namespace octopoint
