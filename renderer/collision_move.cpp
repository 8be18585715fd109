#include "renderer/collision_move.h"

#include <algorithm>

namespace octopoint {
namespace {

// Steps are made within this distance of the cube's centre: past the camera's reach, and every
// product below (a difference times a sub-step count) within 64 bits.
constexpr std::int64_t kFarthestEye = std::int64_t{1} << 36;
// A blocked axis is moved to the largest free share of its component in 1/64ths (Q.6).
constexpr int kShareBits = 6;

std::int64_t absolute(std::int64_t v) { return v < 0 ? -v : v; }

class Mover {
 public:
  Mover(const CollisionWorld& world, const WalkBody& body) : world_(world), body_(body) {}

  bool free(const ModelPoint& p) const { return !world_.meets({p, body_.radius}); }

  // One sub-step by `d` (each axis at most the radius) from the free `p`.
  ModelPoint slide(ModelPoint p, const ModelPoint& d, bool& blocked) const {
    const ModelPoint whole{p.x + d.x, p.y + d.y, p.z + d.z};
    if (free(whole)) return whole;
    blocked = true;
    // Axes by falling size of the component: the one into the surface is dropped (or shortened)
    // and the others are kept.
    std::int64_t ModelPoint::*axes[3] = {&ModelPoint::x, &ModelPoint::y, &ModelPoint::z};
    std::sort(std::begin(axes), std::end(axes),
              [&d](auto a, auto b) { return absolute(d.*a) > absolute(d.*b); });
    for (auto axis : axes) p.*axis += freeShare(p, axis, d.*axis);
    return p;
  }

  // How far along `axis` from the free `p`, up to `component`, the eye stays free: the whole, or
  // the largest free multiple of component / 64 (0 at worst).
  std::int64_t freeShare(const ModelPoint& p, std::int64_t ModelPoint::*axis,
                         std::int64_t component) const {
    if (component == 0) return 0;
    ModelPoint q = p;
    q.*axis += component;
    if (free(q)) return component;
    int low = 0, high = 1 << kShareBits;  // free at low, blocked at high (Q.6 shares)
    while (high - low > 1) {
      const int mid = (low + high) / 2;
      q.*axis = p.*axis + component * mid / (1 << kShareBits);
      (free(q) ? low : high) = mid;
    }
    return component * low / (1 << kShareBits);
  }

  // Up or down to `target_y` in sub-steps of at most the radius, stopping where it would meet.
  ModelPoint vertical(ModelPoint p, std::int64_t target_y) const {
    while (p.y != target_y) {
      const std::int64_t step = std::clamp(target_y - p.y, -body_.radius, body_.radius);
      const std::int64_t moved = freeShare(p, &ModelPoint::y, step);
      p.y += moved;
      if (moved != step) break;
    }
    return p;
  }

  // With gravity: where the eye stands at eye height over the ground under it (groundUnder).
  std::optional<std::int64_t> standingY(const ModelPoint& eye) const {
    const std::int64_t foot_offset = body_.eye_height - body_.radius;
    ModelPoint foot{eye.x, eye.y + foot_offset, eye.z};
    // Up: a foot in occupied space (a step up) is lifted, a radius at a time, at most to the eye.
    for (std::int64_t lifted = 0; !free(foot); foot.y -= body_.radius, lifted += body_.radius) {
      if (lifted >= foot_offset) return std::nullopt;
    }
    // Down: the foot falls, at most the eye height, until it rests on something.
    for (std::int64_t dropped = 0; dropped < body_.eye_height;) {
      const std::int64_t step = std::min(body_.radius, body_.eye_height - dropped);
      const std::int64_t moved = freeShare(foot, &ModelPoint::y, step);
      foot.y += moved;
      dropped += moved;
      if (moved != step) return foot.y - foot_offset;
    }
    return std::nullopt;  // nothing within reach: no ground
  }

  ModelPoint grounded(const ModelPoint& p, bool& found) const {
    const std::optional<std::int64_t> standing = standingY(p);
    found = standing.has_value();
    return standing ? vertical(p, *standing) : p;
  }

 private:
  const CollisionWorld& world_;
  const WalkBody& body_;
};

ModelPoint clampedEye(const ModelPoint& p) {
  return {std::clamp(p.x, -kFarthestEye, kFarthestEye),
          std::clamp(p.y, -kFarthestEye, kFarthestEye),
          std::clamp(p.z, -kFarthestEye, kFarthestEye)};
}

}  // namespace

std::optional<std::int64_t> groundUnder(std::span<const CollisionInstance> world,
                                        const WalkBody& body, const ModelPoint& eye) {
  return groundUnder(CollisionInstances(world), body, eye);
}

CollisionMove moveWithCollision(std::span<const CollisionInstance> world, const WalkBody& body,
                                const ModelPoint& from, const ModelPoint& to) {
  return moveWithCollision(CollisionInstances(world), body, from, to);
}

std::optional<std::int64_t> groundUnder(const CollisionWorld& world, const WalkBody& body,
                                        const ModelPoint& eye) {
  if (body.radius < 1 || body.radius > kMaxCollisionRadius || body.eye_height <= body.radius ||
      body.eye_height > kMaxCollisionRadius) {
    return std::nullopt;
  }
  return Mover(world, body).standingY(eye);
}

CollisionMove moveWithCollision(const CollisionWorld& world, const WalkBody& body,
                                const ModelPoint& from, const ModelPoint& to) {
  const bool gravity = body.eye_height != 0;
  const bool body_valid =
      body.radius >= 1 && body.radius <= kMaxCollisionRadius &&
      (!gravity || (body.eye_height > body.radius && body.eye_height <= kMaxCollisionRadius));
  const Mover mover(world, body);
  const ModelPoint start = clampedEye(from), end = clampedEye(to);
  if (!body_valid || !mover.free(start)) return {end, false, false};
  const ModelPoint delta{end.x - start.x, end.y - start.y, end.z - start.z};
  // Sub-steps of at most the radius in the sum of the axes (so in length too): every difference
  // is below 2^37, so the count is below 2^39 and each share's product below 2^53.
  const std::int64_t length = absolute(delta.x) + absolute(delta.y) + absolute(delta.z);
  const std::int64_t needed = std::max<std::int64_t>(1, (length + body.radius - 1) / body.radius);
  const std::int64_t substeps = std::min(needed, kMaxCollisionSubsteps);
  CollisionMove move{start, needed > substeps, false};
  ModelPoint done{0, 0, 0};  // the share of delta the sub-steps so far were meant to move
  for (std::int64_t k = 1; k <= substeps; ++k) {
    const ModelPoint share{delta.x * k / needed, delta.y * k / needed, delta.z * k / needed};
    const ModelPoint d{share.x - done.x, share.y - done.y, share.z - done.z};
    done = share;
    move.eye = mover.slide(move.eye, d, move.blocked);
    if (gravity) move.eye = mover.grounded(move.eye, move.grounded);
  }
  return move;
}

}  // namespace octopoint
