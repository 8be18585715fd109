// Walk mode's collision in the dual-resolution render threads (octopoint-view's walk mode, n):
// with an eye radius in the config, sinking for long from above the default model's table stops
// on the table instead of passing through it, every frame on the way shows an eye whose sphere
// meets nothing, and kToggleCollision lets the eye through. Real threads, the real model.
#include "renderer/collision.h"
#include "tests/support/dual_resolution_fixture.h"

namespace octopoint::dual_resolution_testing {
namespace {

constexpr std::int64_t kCollisionEdge = std::int64_t{1} << 24;  // one cube edge, Q.24

InteractiveConfig collidingWalkConfig(std::int64_t radius) {
  InteractiveConfig config;
  config.initial_view.walk = true;
  config.initial_view.walker.eye = {kCollisionEdge / 20, -kCollisionEdge / 5,
                                    -kCollisionEdge * 2 / 5};
  config.initial_view.walker.pitch = Angle::fromDegrees(-20);
  config.walk_radius = radius;
  return config;
}

TEST_F(DualResolution, WalkModeSinkingOntoTheTableStopsThereUntilCollisionIsTurnedOff) {
  constexpr std::int64_t kRadius = kCollisionEdge / 128;
  const InteractiveConfig config = collidingWalkConfig(kRadius);
  DualResolutionRenderer renderer(*model_, clock_, config);
  EXPECT_TRUE(renderer.status().walk_collision);
  const CollisionModel collision = *CollisionModel::of(*model_);
  const std::int64_t start_y = config.initial_view.walker.eye.y;
  // Sink (+y, down) for 8 s: two cube edges, far through the table without collision.
  ScriptedTimeline timeline({at(0, ViewEventKind::kPress, NavigationKey::kSink),
                             at(8000, ViewEventKind::kRelease, NavigationKey::kSink)},
                            8000, clock_);
  playThrough(timeline, renderer, ViewEventKind::kQuit);
  const ModelPoint stopped = fineFrame(renderer, 8000).view.walker.eye;
  EXPECT_FALSE(collision.meets({stopped, kRadius}));
  EXPECT_LT(stopped.y, start_y + kCollisionEdge);  // stopped on the way
  EXPECT_GT(stopped.y, start_y);                   // after sinking some
  // Touching: a little lower meets the table.
  EXPECT_TRUE(collision.meets({{stopped.x, stopped.y + kRadius / 32, stopped.z}, kRadius}));
  // Off: one second more sinks by the speed, through the table.
  renderer.handle(at(8000, ViewEventKind::kToggleCollision));
  EXPECT_FALSE(renderer.status().walk_collision);
  ScriptedTimeline through({at(8000, ViewEventKind::kPress, NavigationKey::kSink),
                            at(9000, ViewEventKind::kRelease, NavigationKey::kSink)},
                           9000, clock_);
  playThrough(through, renderer, ViewEventKind::kQuit);
  EXPECT_EQ(fineFrame(renderer, 9000).view.walker.eye.y, stopped.y + config.walk_speed);
}

TEST_F(DualResolution, WalkModeWithoutARadiusDoesNotCollide) {
  DualResolutionRenderer renderer(*model_, clock_, collidingWalkConfig(0));
  EXPECT_FALSE(renderer.status().walk_collision);
  renderer.handle(at(0, ViewEventKind::kToggleCollision));  // nothing to turn on
  EXPECT_FALSE(renderer.status().walk_collision);
}

}  // namespace
}  // namespace octopoint::dual_resolution_testing
