// Walk mode through a scene of many models (octopoint-view --city): the render threads draw the
// scene's walk frames with SceneRenderer (fine: as octopoint-render --city --eye draws them), the
// eye collides with the scene's instances, and there is no orbit view to switch to. Real threads,
// the real model and renderers, scripted events on a manual clock.
#include <vector>

#include "interactive/scene_walk.h"
#include "renderer/perspective.h"
#include "tests/support/dual_resolution_fixture.h"

namespace octopoint::dual_resolution_testing {
namespace {

constexpr std::int64_t kEdge = std::int64_t{1} << 24;  // one scene edge, Q.24

// The default model three times: at the origin (its table under the eye), and two scene edges to
// each side, the right one turned a quarter.
std::vector<SceneInstance> threeTables() {
  return {{0, {{0, 0, 0}, Angle{}, 0}},
          {0, {{-2 * kEdge, 0, 0}, Angle{}, 0}},
          {0, {{2 * kEdge, 0, 0}, Angle::fromDegrees(90), 0}}};
}

// Above the middle table, looking down at it: sinking lands on it.
InteractiveConfig sceneConfig(std::int64_t radius) {
  InteractiveConfig config;
  config.initial_view.walker.eye = {kEdge / 20, -kEdge / 5, -kEdge * 2 / 5};
  config.initial_view.walker.pitch = Angle::fromDegrees(-20);
  config.fov = Angle::fromDegrees(70);
  config.walk_radius = radius;
  return config;
}

// The frame SceneRenderer draws of `walker`, as octopoint-render --city --eye draws it (with
// `visible`, only those instances, as --cells draws a cell's set).
std::uint32_t sceneFrameChecksum(std::span<const ModelView* const> models,
                                 std::span<const SceneInstance> instances,
                                 const InteractiveConfig& config, const WalkEye& walker,
                                 std::span<const std::uint32_t> visible = {}) {
  const PerspectiveView view = walkViewOf(config, walker);
  SceneError error;
  SceneRenderer renderer(models, instances, &error);
  EXPECT_EQ(error, SceneError::kNone);
  if (!visible.empty()) renderer.setVisibleSet(visible);
  Framebuffer frame(config.width, config.height);
  frame.clear();
  EXPECT_TRUE(renderer.draw(view, frame));
  return frameChecksum(frame);
}

TEST_F(DualResolution, ASceneWalksItsFramesAreTheSceneRenderersAndItHasNoOrbitView) {
  const ModelView* models[] = {&*model_};
  const std::vector<SceneInstance> instances = threeTables();
  SceneError error;
  SceneWalk walk(models, instances, &error);
  ASSERT_EQ(error, SceneError::kNone);
  InteractiveConfig config = walk.configure(sceneConfig(0));
  config.initial_view.walker.yaw = Angle::fromDegrees(-60);  // the left table in view too
  DualResolutionRenderer renderer(SceneWalk::noOrbitView(), clock_, config);
  EXPECT_TRUE(renderer.status().walk);
  EXPECT_FALSE(renderer.status().walk_collision);                                    // no radius
  ScriptedTimeline timeline({at(0, ViewEventKind::kPress, NavigationKey::kPitchUp),  // forward
                             at(500, ViewEventKind::kRelease, NavigationKey::kPitchUp),
                             at(600, ViewEventKind::kToggleWalk)},
                            1000, clock_);
  playThrough(timeline, renderer, ViewEventKind::kQuit);
  EXPECT_TRUE(renderer.status().walk) << "Tab does nothing in a scene";
  const FrameInfo info = fineFrame(renderer, 1000);
  EXPECT_TRUE(info.view.walk);
  EXPECT_NE(info.view.walker.eye, config.initial_view.walker.eye);
  FrameInfo shown;
  const Framebuffer* frame = renderer.acquireLatest(&shown);
  ASSERT_NE(frame, nullptr);
  const std::uint32_t expected = sceneFrameChecksum(models, instances, config, info.view.walker);
  EXPECT_EQ(frameChecksum(*frame), expected) << "the fine frame is octopoint-render --city's";
  Framebuffer empty(config.width, config.height);
  empty.clear();
  EXPECT_NE(expected, frameChecksum(empty)) << "the view shows the scene";
}

TEST_F(DualResolution, ASceneWalkedWithCellsDrawsOnlyTheEyesCellsSet) {
  const ModelView* models[] = {&*model_};
  const std::vector<SceneInstance> instances = threeTables();
  // One cell around the three tables whose set leaves the right one (2) out.
  CellGrid grid;
  grid.instances = 3;
  grid.nx = grid.nz = grid.ny = 1;
  grid.origin_x = grid.origin_z = -4 * kEdge;
  grid.edge = 8 * kEdge;
  grid.y = {-4 * kEdge, 4 * kEdge};
  const std::vector<std::uint32_t> set = {0, 1};
  CellTableError why;
  const CellTable cells = CellTable::parse(encodeCellTable(grid, {set}), 3, &why);
  ASSERT_EQ(why, CellTableError::kNone);
  SceneError error;
  SceneWalk walk(models, instances, &error, &cells);
  ASSERT_EQ(error, SceneError::kNone);
  InteractiveConfig config = walk.configure(sceneConfig(0));
  config.initial_view.walker.yaw = Angle::fromDegrees(60);  // the right table in view
  DualResolutionRenderer renderer(SceneWalk::noOrbitView(), clock_, config);
  const FrameInfo info = fineFrame(renderer, 0);
  FrameInfo shown;
  const Framebuffer* frame = renderer.acquireLatest(&shown);
  ASSERT_NE(frame, nullptr);
  const WalkEye& walker = info.view.walker;
  EXPECT_EQ(frameChecksum(*frame), sceneFrameChecksum(models, instances, config, walker, set));
  EXPECT_NE(frameChecksum(*frame), sceneFrameChecksum(models, instances, config, walker))
      << "the right table, left out of the cell's set, is in view";
}

TEST_F(DualResolution, InASceneSinkingOntoATableStopsThereUntilCollisionIsTurnedOff) {
  constexpr std::int64_t kRadius = kEdge / 128;
  const ModelView* models[] = {&*model_};
  const std::vector<SceneInstance> instances = threeTables();
  SceneError error;
  SceneWalk walk(models, instances, &error);
  ASSERT_EQ(error, SceneError::kNone);
  const InteractiveConfig config = walk.configure(sceneConfig(kRadius));
  DualResolutionRenderer renderer(SceneWalk::noOrbitView(), clock_, config);
  EXPECT_TRUE(renderer.status().walk_collision);
  const std::int64_t start_y = config.initial_view.walker.eye.y;
  // Sink (+y, down) for 8 s: two scene edges, far through the table without collision.
  ScriptedTimeline timeline({at(0, ViewEventKind::kPress, NavigationKey::kSink),
                             at(8000, ViewEventKind::kRelease, NavigationKey::kSink)},
                            8000, clock_);
  playThrough(timeline, renderer, ViewEventKind::kQuit);
  const ModelPoint stopped = fineFrame(renderer, 8000).view.walker.eye;
  EXPECT_FALSE(walk.collision().meets({stopped, kRadius}));
  EXPECT_LT(stopped.y, start_y + kEdge);  // stopped on the way
  EXPECT_GT(stopped.y, start_y);          // after sinking some
  EXPECT_TRUE(walk.collision().meets({{stopped.x, stopped.y + kRadius / 32, stopped.z}, kRadius}));
  renderer.handle(at(8000, ViewEventKind::kToggleCollision));
  EXPECT_FALSE(renderer.status().walk_collision);
  ScriptedTimeline through({at(8000, ViewEventKind::kPress, NavigationKey::kSink),
                            at(9000, ViewEventKind::kRelease, NavigationKey::kSink)},
                           9000, clock_);
  playThrough(through, renderer, ViewEventKind::kQuit);
  EXPECT_EQ(fineFrame(renderer, 9000).view.walker.eye.y, stopped.y + config.walk_speed);
}

}  // namespace
}  // namespace octopoint::dual_resolution_testing
