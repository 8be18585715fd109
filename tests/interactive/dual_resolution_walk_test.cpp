// Walk mode of the dual-resolution render threads (octopoint-view's Tab): held keys move the eye by
// speed times time, a drag turns it, the frames are the perspective renderer's (fine: as
// octopoint-render --eye draws them; coarse: a stored depth coarser), driven headless by scripted
// events on a manual clock. Real threads, the real model and renderer.
#include "renderer/perspective.h"
#include "renderer/perspective_depth.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/dual_resolution_fixture.h"

namespace octopoint::dual_resolution_testing {
namespace {

constexpr std::int64_t kWalkEdge = std::int64_t{1} << 24;  // one cube edge, Q.24
constexpr std::int64_t kWalkSpeed = kWalkEdge / 4;         // the default: a quarter edge a second

// The default model's table, seen from its edge: eye in the cube, looking down at the objects.
InteractiveConfig walkConfig() {
  InteractiveConfig config;
  config.initial_view.walk = true;
  config.initial_view.walker.eye = {kWalkEdge / 20, -kWalkEdge / 5, -kWalkEdge * 2 / 5};
  config.initial_view.walker.pitch = Angle::fromDegrees(-20);
  config.fov = Angle::fromDegrees(70);
  return config;
}

// The frame of `walker` as octopoint-render --eye draws it (coarser 0), or the coarse frame; with
// `fill`, as --eye --fill draws it; with kColourNormal, as --eye --style draws it.
Framebuffer walkFrame(const ModelView& model, const InteractiveConfig& config,
                      const WalkEye& walker, int coarser = 0, bool fill = false,
                      PixelPayload payload = PixelPayload::kColour) {
  const PerspectiveView view = walkViewOf(config, walker);
  Framebuffer frame(config.width, config.height);
  frame.clear(payload);
  PerspectiveRenderer renderer(model);
  PerspectiveRenderer::Options options;
  options.coarser = coarser;
  EXPECT_TRUE(renderer.draw(view, options, frame));
  if (fill) {
    const std::span<const int> depths = renderer.detailDepths();
    EXPECT_FALSE(
        HoleFiller(frame)
            .fill(frame, perspectiveBridge(
                             view, depths[depths.size() - 1 - static_cast<std::size_t>(coarser)]))
            .refused);
  }
  return frame;
}

TEST_F(DualResolution, WalkKeysMoveTheEyeBySpeedTimesTimeLevelAlongTheYaw) {
  InteractiveConfig config = walkConfig();
  config.initial_view.walker.yaw = Angle::fromDegrees(90);  // looking along +x
  DualResolutionRenderer renderer(*model_, clock_, config);
  const Point3<std::int64_t> start = config.initial_view.walker.eye;
  ScriptedTimeline timeline(
      {at(0, ViewEventKind::kPress, NavigationKey::kPitchUp),  // forward for 1 s
       at(1000, ViewEventKind::kRelease, NavigationKey::kPitchUp),
       at(1000, ViewEventKind::kPress, NavigationKey::kYawLeft),  // a step left for 0.5 s
       at(1500, ViewEventKind::kRelease, NavigationKey::kYawLeft),
       at(1500, ViewEventKind::kPress, NavigationKey::kRise),  // up for 0.25 s
       at(1750, ViewEventKind::kRelease, NavigationKey::kRise)},
      2000, clock_);
  playThrough(timeline, renderer, ViewEventKind::kQuit);
  const FrameInfo info = fineFrame(renderer, 2000);
  // Forward at yaw 90 is +x; left of it is -z (right is (cos, 0, -sin)); up is -y. The pitch of
  // -20 degrees does not tip the walk.
  EXPECT_EQ(info.view.walker.eye.x, start.x + kWalkSpeed);
  EXPECT_EQ(info.view.walker.eye.z, start.z + kWalkSpeed / 2);
  EXPECT_EQ(info.view.walker.eye.y, start.y - kWalkSpeed / 4);
  EXPECT_EQ(info.view.walker.yaw, Angle::fromDegrees(90));
  FrameInfo shown;
  const Framebuffer* frame = renderer.acquireLatest(&shown);
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(frameChecksum(*frame), frameChecksum(walkFrame(*model_, config, info.view.walker)))
      << "the fine frame is octopoint-render --eye's";
}

TEST_F(DualResolution, WhileWalkingTheCoarseFramesShowTheEyeOfTheirOwnTime) {
  const InteractiveConfig config = walkConfig();
  DualResolutionRenderer renderer(*model_, clock_, config);
  const Point3<std::int64_t> start = config.initial_view.walker.eye;
  clock_.set(0);
  renderer.handle(at(0, ViewEventKind::kPress, NavigationKey::kPitchUp));  // forward: +z at yaw 0
  std::uint64_t last_generation = 0;
  int coarse_seen = 0;
  for (std::int64_t t_ms = 10; t_ms < 600; t_ms += 10) {
    clock_.set(t_ms * 1000);
    std::this_thread::sleep_for(milliseconds(3));
    FrameInfo info;
    const Framebuffer* frame = renderer.acquireLatest(&info);
    if (frame == nullptr || info.generation == last_generation ||
        info.source != FrameSource::kCoarse)
      continue;
    last_generation = info.generation;
    ++coarse_seen;
    EXPECT_EQ(info.view.walker.eye.z, start.z + info.view_time_us * kWalkSpeed / 1'000'000);
    EXPECT_EQ(info.view.walker.eye.x, start.x);
    if (coarse_seen == 1) {
      EXPECT_EQ(frameChecksum(*frame),
                frameChecksum(walkFrame(*model_, config, info.view.walker, 1)))
          << "a coarse frame is the perspective renderer's a stored depth coarser";
    }
  }
  EXPECT_GE(coarse_seen, 1);
  renderer.handle(at(600, ViewEventKind::kRelease, NavigationKey::kPitchUp));
  const FrameInfo fine = fineFrame(renderer, 600);
  EXPECT_EQ(fine.view.walker.eye.z, start.z + 600'000 * kWalkSpeed / 1'000'000);
}

TEST_F(DualResolution, ADragTurnsTheEyeAndHoldsTheFineFrameBackUntilLetGo) {
  const InteractiveConfig config = walkConfig();
  DualResolutionRenderer renderer(*model_, clock_, config);
  ASSERT_TRUE(
      renderer.waitUntil([](const RendererStatus& s) { return s.fine_shown == 1; }, kPatience));
  clock_.set(100'000);
  renderer.handle(at(100, ViewEventKind::kPress, NavigationKey::kDrag));
  ViewEvent turn = at(100, ViewEventKind::kTurn);
  turn.turn_yaw = 1000;
  turn.turn_pitch = 30000;  // past straight up: held there
  renderer.handle(turn);
  const std::uint64_t turned = renderer.status().view_version;
  ASSERT_TRUE(renderer.waitUntil(
      [&](const RendererStatus& s) {
        return s.latest.view_version == turned && s.latest.source == FrameSource::kCoarse;
      },
      kPatience))
      << "a turn draws a coarse frame";
  EXPECT_EQ(renderer.status().latest.view.walker.yaw, Angle::fromTurns16(1000));
  EXPECT_EQ(renderer.status().latest.view.walker.pitch, Angle::fromDegrees(90));
  clock_.set(200'000);
  renderer.handle(at(200, ViewEventKind::kTick));
  std::this_thread::sleep_for(milliseconds(50));
  EXPECT_EQ(renderer.status().fine_started, 1u) << "no fine frame while the button is down";
  renderer.handle(at(200, ViewEventKind::kRelease, NavigationKey::kDrag));
  const FrameInfo fine = fineFrame(renderer, 300);
  EXPECT_EQ(fine.view.walker.pitch, Angle::fromDegrees(90));
  EXPECT_EQ(fine.view.walker.eye, config.initial_view.walker.eye) << "a drag moves nothing";
}

TEST_F(DualResolution, TabEntersWalkModeAtTheOrbitViewsEyeAndTheWheelSetsTheSpeed) {
  InteractiveConfig config;
  config.initial_view.yaw = Angle::fromDegrees(30);
  config.initial_view.zoom = Q16::fromRaw(Q16::kOneRaw * 2);
  DualResolutionRenderer renderer(*model_, clock_, config);
  ASSERT_TRUE(renderer.canWalk());
  const std::uint64_t version = renderer.status().view_version;
  renderer.handle(at(0, ViewEventKind::kPress, NavigationKey::kRise));
  renderer.handle(at(0, ViewEventKind::kRelease, NavigationKey::kRise));
  EXPECT_EQ(renderer.status().view_version, version) << "up and down mean nothing in orbit mode";

  renderer.handle(at(0, ViewEventKind::kToggleWalk));
  EXPECT_TRUE(renderer.status().walk);
  const FrameInfo entered = fineFrame(renderer, 0);
  Camera camera;
  camera.yaw = config.initial_view.yaw;
  camera.zoom = config.initial_view.zoom;
  camera.width = config.width;
  camera.height = config.height;
  PerspectiveView orbit;
  ASSERT_EQ(orbitPerspective(camera, config.fov, kDefaultFractionBits, &orbit),
            PerspectiveError::kNone);
  EXPECT_EQ(entered.view.walker.eye, orbit.camera.eye);
  EXPECT_EQ(entered.view.walker.yaw, orbit.camera.yaw);
  EXPECT_EQ(entered.view.walker.pitch, orbit.camera.pitch);
  EXPECT_EQ(entered.view.zoom, config.initial_view.zoom) << "the orbit view waits for orbit mode";

  const std::uint64_t walking = renderer.status().view_version;
  renderer.handle(at(0, ViewEventKind::kZoomIn));
  renderer.handle(at(0, ViewEventKind::kZoomIn));
  EXPECT_EQ(renderer.status().walk_speed, kWalkSpeed * 5 / 4 * 5 / 4);
  EXPECT_EQ(renderer.status().view_version, walking) << "the speed changes no frame";
  renderer.handle(at(0, ViewEventKind::kToggleWalk));
  const FrameInfo back = fineFrame(renderer, 100);
  EXPECT_FALSE(back.view.walk);
  EXPECT_EQ(back.view.yaw, config.initial_view.yaw);
  EXPECT_EQ(back.view.zoom, config.initial_view.zoom);
}

// The fill key (f) in walk mode: the fine frame is octopoint-render --eye --fill's, and differs
// from the unfilled one (the specks on the table close).
TEST_F(DualResolution, WalkModeFillsAsRenderDoes) {
  InteractiveConfig config = walkConfig();
  DualResolutionRenderer renderer(*model_, clock_, config);
  const FrameInfo plain = fineFrame(renderer, 0);
  EXPECT_FALSE(plain.view.fill);
  renderer.handle(at(0, ViewEventKind::kToggleFill));
  const FrameInfo filled = fineFrame(renderer, 100);
  EXPECT_TRUE(filled.view.fill);
  FrameInfo shown;
  const Framebuffer* frame = renderer.acquireLatest(&shown);
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(frameChecksum(*frame),
            frameChecksum(walkFrame(*model_, config, filled.view.walker, 0, true)));
  EXPECT_NE(frameChecksum(*frame), frameChecksum(walkFrame(*model_, config, filled.view.walker)));
}

// The viewer's styles in walk mode: a model with normals (config.payload kColourNormal) draws its
// walk frames in colour only, as octopoint-render --eye does (a normal-carrying frame's coarser
// depth code lets other leaves win some pixels), until kWalkNormals asks for normals; then the
// fine frame is --eye --style's, and walkView gives the view the styler needs.
TEST_F(DualResolution, WalkFramesCarryNormalsOnlyWhenAStyleAsksForThem) {
  InteractiveConfig config = walkConfig();
  config.payload = PixelPayload::kColourNormal;
  DualResolutionRenderer renderer(*model_, clock_, config);
  const FrameInfo plain = fineFrame(renderer, 0);
  FrameInfo shown;
  const Framebuffer* frame = renderer.acquireLatest(&shown);
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(frame->payload(), PixelPayload::kColour);
  EXPECT_EQ(frameChecksum(*frame), frameChecksum(walkFrame(*model_, config, plain.view.walker)));
  ViewEvent normals = at(0, ViewEventKind::kWalkNormals);
  normals.on = true;
  renderer.handle(normals);
  const FrameInfo styled = fineFrame(renderer, 100);
  EXPECT_TRUE(styled.view.walk_normals);
  frame = renderer.acquireLatest(&shown);
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(frame->payload(), PixelPayload::kColourNormal);
  EXPECT_EQ(frameChecksum(*frame), frameChecksum(walkFrame(*model_, config, styled.view.walker, 0,
                                                           false, PixelPayload::kColourNormal)));
  PerspectiveView view;
  ASSERT_TRUE(renderer.walkView(shown, &view));
  EXPECT_EQ(view.camera.eye, styled.view.walker.eye);
  EXPECT_EQ(view.camera.width, config.width);
  FrameInfo orbit = shown;
  orbit.view.walk = false;
  EXPECT_FALSE(renderer.walkView(orbit, &view));
}

// A renderer of whole views (a streamed model) has no model to walk through: Tab does nothing.
TEST_F(DualResolution, AViewDrawerCannotWalk) {
  const ViewDrawFunction nothing = [](FrameSource, const Camera&, Framebuffer&,
                                      const std::atomic<bool>*, int* depth) {
    *depth = 0;
    return true;
  };
  DualResolutionRenderer renderer(nothing, clock_, walkConfig());
  EXPECT_FALSE(renderer.canWalk());
  EXPECT_FALSE(renderer.status().walk);
  renderer.handle(at(0, ViewEventKind::kToggleWalk));
  EXPECT_FALSE(renderer.status().walk);
}

// A renderer of whole views given a walk drawer (a streamed model: tools/view_stream.h) walks: it
// starts in walk mode, hands the drawer each frame's perspective view (walkView's), and shows what
// the drawer drew; Tab goes to orbit mode and back.
TEST_F(DualResolution, AViewDrawerWithAWalkDrawerWalks) {
  const ViewDrawFunction nothing = [](FrameSource, const Camera&, Framebuffer&,
                                      const std::atomic<bool>*, int* depth) {
    *depth = 0;
    return true;
  };
  InteractiveConfig config = walkConfig();
  const ModelView& model = *model_;
  std::atomic<int> drawn{0};
  config.walk_draw = [&model, &drawn](FrameSource source, const PerspectiveView& view,
                                      Framebuffer& frame, const std::atomic<bool>* abort,
                                      int* finest_depth) {
    PerspectiveRenderer renderer(model);
    PerspectiveRenderer::Options options;
    options.coarser = source == FrameSource::kCoarse ? 1 : 0;
    if (!renderer.draw(view, options, frame, nullptr, abort)) return false;
    *finest_depth = renderer.detailDepths().back();
    drawn.fetch_add(1);
    return true;
  };
  DualResolutionRenderer renderer(nothing, clock_, config);
  EXPECT_TRUE(renderer.canWalk());
  EXPECT_TRUE(renderer.status().walk);
  const FrameInfo walked = fineFrame(renderer, 0);
  EXPECT_TRUE(walked.view.walk);
  EXPECT_GT(drawn.load(), 0);
  FrameInfo shown;
  const Framebuffer* frame = renderer.acquireLatest(&shown);
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(shown.depth, model.finestLevel().depth);
  EXPECT_EQ(frameChecksum(*frame), frameChecksum(walkFrame(model, config, walked.view.walker)));
  renderer.handle(at(100, ViewEventKind::kToggleWalk));
  EXPECT_FALSE(renderer.status().walk);
  renderer.handle(at(200, ViewEventKind::kToggleWalk));
  EXPECT_TRUE(renderer.status().walk);
}

}  // namespace
}  // namespace octopoint::dual_resolution_testing
