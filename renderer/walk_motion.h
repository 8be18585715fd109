#pragma once
// How a held key moves a walking eye (docs/perspective.md, "The viewer's walk mode"): the walk
// speed times the time held, exact to the unit below, along the look's yaw (level: the pitch does
// not tip the walk), at right angles to it, or along the scan's up; and how a turn tips the pitch.
// One arithmetic for octopoint-view (interactive/view_motion.cpp, which adds collision) and the
// web page (web/octopoint_web_walk.cpp), so that both walk the same eye the same way. Integer only.

#include <cstdint>

#include "octopoint/fixed.h"
#include "renderer/perspective.h"

namespace octopoint {

// What a held key walks along: forward and back along the look's yaw, left and right at right
// angles to it, up and down along the scan's up (-y of the model: the model's y points down).
enum class WalkStep : std::uint8_t { kForward, kBack, kLeft, kRight, kUp, kDown };
inline constexpr int kWalkSteps = 6;

// How far `held_us` microseconds at `speed` (Q.24 cube edges a second, at most 2^30) walk, Q.24
// cube edges: whole seconds and the rest apart so that nothing overflows; at most four times the
// camera's reach (a day's hold walks as far as a minute's).
std::int64_t walkDistance(std::int64_t held_us, std::int64_t speed);

// `eye` (Q.24 cube edges about the cube's centre) after walking `distance` (Q.24) in `step` with
// the look at `yaw`, within the camera's reach (withinReach).
ModelPoint walkedEye(const ModelPoint& eye, Angle yaw, WalkStep step, std::int64_t distance);

// `eye` with each coordinate kept within the camera's reach (kMaxEyeDistance cube edges).
ModelPoint withinReach(const ModelPoint& eye);

// A walking eye's pitch turned by `turn` (1/65536 turn), kept within straight down .. straight up.
Angle turnedPitch(Angle pitch, std::int32_t turn);

}  // namespace octopoint
