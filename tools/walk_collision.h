#pragma once
// The tools' side of collision (docs/perspective.md, "Collision"): --collide, --eye-radius and
// --eye-height in the scan's own units, turned into the integer body of renderer/collision_move.h;
// and a camera path's eyes moved with collision, frame to frame. Host side: doubles in, the
// integer walk does the rest.

#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "octopoint/model.h"
#include "renderer/collision.h"
#include "renderer/collision_move.h"
#include "tools/scan_eye.h"

namespace octopoint {

// The eye's radius when --eye-radius is not given: 1/128 of the cube's edge (Q.24).
inline constexpr std::int64_t kDefaultEyeRadius = kPerspectiveUnit / 128;

struct CollisionOptions {
  bool collide = false;              // --collide
  std::optional<double> eye_radius;  // --eye-radius, scan units
  std::optional<double> eye_height;  // --eye-height, scan units: gravity
  bool any() const { return collide || eye_radius || eye_height; }
};

// Reads --collide, --eye-radius or --eye-height; false for any other option.
bool parseCollisionOption(cli::ArgumentReader& args, CollisionOptions& options);

// The body those options describe for a model whose cube lies at `cube`: a cli::Error, one line,
// for a radius outside 1/2^24 .. 1 cube edge or an eye height not above the radius or past one
// cube edge.
WalkBody walkBodyOf(const ScanCube& cube, const CollisionOptions& options);

// The path's eyes (scan units) walked with collision through the model's finest level: the first
// eye as given (with gravity, settled at eye height over the ground under it), each next one moved
// from the last toward its own; `stopped` counts the frames whose eye something stopped or turned.
struct CollidedEyes {
  std::vector<ScanPoint> eyes;
  int stopped = 0;
};
CollidedEyes collideEyes(const ModelView& model, const ScanCube& cube, const WalkBody& body,
                         const std::vector<ScanPoint>& eyes, const std::string& option);
// The same through any world: a scene's instances (renderer/scene_collision.h), `cube` the
// scene's units (sceneUnits).
CollidedEyes collideEyes(const CollisionWorld& world, const ScanCube& cube, const WalkBody& body,
                         const std::vector<ScanPoint>& eyes, const std::string& option);

// A scene's units as a cube: one scene edge, centred on the origin, so that its points are the
// scene's coordinates in scene edges.
inline constexpr ScanCube kSceneUnits{{-0.5, -0.5, -0.5}, 1.0, false};

// The line --collide prints: the body (in the cube's units) and how often the eye was stopped.
std::string collisionSummary(const ScanCube& cube, const WalkBody& body, int stopped,
                             std::size_t frames);

}  // namespace octopoint
