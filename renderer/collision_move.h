#pragma once
// Moving with collision (docs/perspective.md, "Collision"): a step of the eye from A toward B that
// stops short of occupied space and slides along it, in sub-steps no longer than the eye's radius
// so that no wall, however thin, is stepped over; and, where asked, the eye kept at eye height
// above the ground. Integer only; Q.24 cube edges of the world the instances stand in
// (renderer/collision.h); y points down.

#include <cstdint>
#include <optional>
#include <span>

#include "renderer/collision.h"

namespace octopoint {

struct WalkBody {
  std::int64_t radius = kPerspectiveUnit / 128;  // Q.24: the eye's sphere, 1 .. kMaxCollisionRadius
  // Q.24: with gravity, the eye's height above the ground (groundUnder); 0: no gravity. At most
  // kMaxCollisionRadius, above the radius.
  std::int64_t eye_height = 0;
};

// With gravity, where a free eye stands: the y of the eye (y points down) whose foot, a sphere
// of the eye's radius eye_height - radius below the eye's centre, rests on occupied space, found
// by lifting the foot out of what it meets (a radius at a time, at most to the eye: a step up)
// and letting it fall at most the eye height (sub-steps of the radius, resting within 1/64
// radius of what stops it). nullopt without gravity, or with nothing within reach below (off the
// table's edge, high above the floor). The foot stands under the eye's centre, so a wall the eye
// passes beside is not ground (a vertical column as wide as the sphere climbed such walls), and
// it does not fall through the gaps of a scan narrower than the eye.
std::optional<std::int64_t> groundUnder(const CollisionWorld& world, const WalkBody& body,
                                        const ModelPoint& eye);
std::optional<std::int64_t> groundUnder(std::span<const CollisionInstance> world,
                                        const WalkBody& body, const ModelPoint& eye);

// A step is cut into at most this many sub-steps; a longer step stops after them (blocked).
inline constexpr std::int64_t kMaxCollisionSubsteps = std::int64_t{1} << 16;

struct CollisionMove {
  ModelPoint eye;
  bool blocked = false;   // something stopped or turned the step (or it was too long)
  bool grounded = false;  // gravity found ground under the eye at the step's end
};

// The eye moved from `from` toward `to`. Each sub-step moves by the next share of to - from (no
// longer than the radius, in the sum of its axes); where that meets occupied space, the sub-step
// is made one axis at a time, largest component first, each axis as far as it stays free (to
// 1/64 of its component), so a step into a wall slides along it. With gravity, after each
// sub-step the eye moves up or down (itself with collision) to eye height above the ground, when
// there is ground within reach; with none it keeps its height. An eye whose sphere already meets
// occupied space (placed there by hand) moves to `to` freely, so that it can walk out. A body
// with a radius outside 1 .. kMaxCollisionRadius, or a nonzero eye height outside radius + 1 ..
// kMaxCollisionRadius, moves freely too.
CollisionMove moveWithCollision(const CollisionWorld& world, const WalkBody& body,
                                const ModelPoint& from, const ModelPoint& to);
// The same among a few instances (CollisionInstances).
CollisionMove moveWithCollision(std::span<const CollisionInstance> world, const WalkBody& body,
                                const ModelPoint& from, const ModelPoint& to);

}  // namespace octopoint
