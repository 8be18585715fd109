#include "tools/walk_collision.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "cli/error.h"
#include "cli/real_numbers.h"
#include "cli/text.h"

namespace octopoint {
namespace {

// Scan units as Q.24 cube edges, rounded; 0 for what is below half a unit.
std::int64_t lengthOf(const ScanCube& cube, double length) {
  return std::llround(length / cube.edge * static_cast<double>(kPerspectiveUnit));
}

}  // namespace

bool parseCollisionOption(cli::ArgumentReader& args, CollisionOptions& options) {
  if (args.is("--collide")) {
    args.noValue();
    options.collide = true;
  } else if (args.is("--eye-radius")) {
    options.eye_radius = cli::parseReal(args.name(), args.value(), 1e-300, 1e13);
  } else if (args.is("--eye-height")) {
    options.eye_height = cli::parseReal(args.name(), args.value(), 1e-300, 1e13);
  } else {
    return false;
  }
  return true;
}

WalkBody walkBodyOf(const ScanCube& cube, const CollisionOptions& options) {
  WalkBody body;
  body.radius = kDefaultEyeRadius;
  const auto edges = [&cube](double length) { return cli::realText(length / cube.edge); };
  if (options.eye_radius) {
    body.radius = lengthOf(cube, *options.eye_radius);
    if (body.radius < 1 || body.radius > kMaxCollisionRadius) {
      throw cli::Error("--eye-radius: " + cli::realText(*options.eye_radius) + " scan units is " +
                       edges(*options.eye_radius) + " cube edges (of " + cli::realText(cube.edge) +
                       "); the eye's radius is 2^-24 to 1 cube edge");
    }
  }
  if (options.eye_height) {
    body.eye_height = lengthOf(cube, *options.eye_height);
    if (body.eye_height <= body.radius || body.eye_height > kMaxCollisionRadius) {
      throw cli::Error("--eye-height: " + cli::realText(*options.eye_height) + " scan units is " +
                       edges(*options.eye_height) +
                       " cube edges; it must be above the eye's radius (" +
                       cli::realText(static_cast<double>(body.radius) /
                                     static_cast<double>(kPerspectiveUnit) * cube.edge) +
                       " scan units) and at most one cube edge (" + cli::realText(cube.edge) + ")");
    }
  }
  return body;
}

CollidedEyes collideEyes(const ModelView& model, const ScanCube& cube, const WalkBody& body,
                         const std::vector<ScanPoint>& eyes, const std::string& option) {
  const std::optional<CollisionModel> collision = CollisionModel::of(model);
  if (!collision) throw cli::Error(option + ": the model's finest level is too large to walk");
  const CollisionInstance instance{&*collision, {}};
  return collideEyes(CollisionInstances({&instance, 1}), cube, body, eyes, option);
}

CollidedEyes collideEyes(const CollisionWorld& world, const ScanCube& cube, const WalkBody& body,
                         const std::vector<ScanPoint>& eyes, const std::string& option) {
  CollidedEyes result;
  if (eyes.empty()) return result;
  ModelPoint eye = modelPointOf(cube, eyes.front(), option);
  for (const ScanPoint& next : eyes) {
    const CollisionMove move =
        moveWithCollision(world, body, eye, modelPointOf(cube, next, option));
    eye = move.eye;
    result.stopped += move.blocked ? 1 : 0;
    result.eyes.push_back(scanPointOf(cube, eye));
  }
  return result;
}

std::string collisionSummary(const ScanCube& cube, const WalkBody& body, int stopped,
                             std::size_t frames) {
  const double unit = cube.edge / static_cast<double>(kPerspectiveUnit);
  char line[160];
  char height[64] = "";
  if (body.eye_height != 0) {
    std::snprintf(height, sizeof height, ", eye height %.3g",
                  static_cast<double>(body.eye_height) * unit);
  }
  std::snprintf(line, sizeof line,
                "collision: eye radius %.3g%s, stopped or turned in %d of %zu frames",
                static_cast<double>(body.radius) * unit, height, stopped, frames);
  return line;
}

}  // namespace octopoint
