// Scenes of many models (renderer/scene_renderer.h, docs/city.md): one instance at the identity
// draws its model's frame word for word; two instances in one z-buffer give the nearer one's
// pixels (and culling across them passes over the hidden one's subtrees); a turned, scaled and
// moved instance is its model drawn alone by the inverse camera, worked out here in double
// precision from the transform's definition; a moved instance redraws where it moved; bad scenes
// and moves are refused.

#include "renderer/scene_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "octopoint/scene.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace scene_test {
namespace {

const ModelView& defaultModelView() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

constexpr std::int64_t kU = kPerspectiveUnit;

PerspectiveView viewOf(const PerspectiveCamera& camera) {
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  return view;
}

Framebuffer drawScene(const std::vector<SceneInstance>& instances, const PerspectiveView& view,
                      SceneDrawStats* stats = nullptr) {
  const ModelView* models[] = {&defaultModelView()};
  SceneError error = SceneError::kNone;
  SceneRenderer scene(models, instances, &error);
  EXPECT_EQ(error, SceneError::kNone);
  Framebuffer frame(view.camera.width, view.camera.height);
  frame.clear();
  EXPECT_TRUE(scene.draw(view, frame, stats));
  return frame;
}

Framebuffer drawAlone(const PerspectiveView& view) {
  PerspectiveRenderer renderer(defaultModelView());
  Framebuffer frame(view.camera.width, view.camera.height);
  frame.clear();
  EXPECT_TRUE(renderer.draw(view, {}, frame));
  return frame;
}

struct Comparison {
  std::int64_t different = 0;  // pixels whose words differ
  std::int64_t covered = 0;    // pixels either frame covers
};

Comparison compare(const Framebuffer& a, const Framebuffer& b) {
  Comparison result;
  for (std::int32_t y = 0; y < a.height(); ++y) {
    for (std::int32_t x = 0; x < a.width(); ++x) {
      result.different += a.pixelAt(x, y) != b.pixelAt(x, y);
      result.covered += a.covered(x, y) || b.covered(x, y);
    }
  }
  return result;
}

std::vector<PerspectiveCamera> sceneTestCameras() {
  return {perspectiveCameraOf({0, 0, -2 * kU}, 0, 0, 60, 320, 240),
          perspectiveCameraOf({kU, -kU / 2, -kU}, -45, -20, 90, 320, 240),
          perspectiveCameraOf({0, 28 * kU / 100, -46 * kU / 100}, 0, 28, 90, 320, 240),
          perspectiveCameraOf({kU / 16, kU / 8, 0}, 170, 30, 120, 640, 480)};
}

TEST(SceneRenderer, OneInstanceAtTheIdentityIsTheModelDrawnAloneWordForWord) {
  for (const PerspectiveCamera& camera : sceneTestCameras()) {
    const PerspectiveView view = viewOf(camera);
    const Comparison c = compare(drawScene({{0, {}}}, view), drawAlone(view));
    EXPECT_EQ(c.different, 0);
    EXPECT_GT(c.covered, 1000);
  }
}

// The model's camera that sees an instance as the scene's camera sees it, in double precision
// from the transform's definition (scene point = at + 2^scale Ry(turn) p): camera space is
// W(yaw) (at + 2^scale Ry(turn) p - eye) = 2^scale W(yaw) Ry(turn) (p - Ry(-turn) (eye - at) /
// 2^scale), and W(yaw) Ry(turn) is W(yaw - turn), checked here on the matrices.
PerspectiveCamera inverseCamera(const PerspectiveCamera& camera, const InstanceTransform& t) {
  const double a = radiansOf(t.turn);
  const Matrix turn{{{std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}}};
  PerspectiveCamera model = camera;
  model.yaw = camera.yaw - t.turn;
  const Matrix expected = multiply(worldToCamera(camera), turn), got = worldToCamera(model);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(expected[i][j], got[i][j], 1e-9);
  const double d[3] = {static_cast<double>(camera.eye.x - t.at.x),
                       static_cast<double>(camera.eye.y - t.at.y),
                       static_cast<double>(camera.eye.z - t.at.z)};
  // Ry(-turn) = Ry(turn) transposed.
  const double scale = std::ldexp(1.0, -t.scale);
  const auto row = [&](int i) {
    return std::llround((turn[0][i] * d[0] + turn[1][i] * d[1] + turn[2][i] * d[2]) * scale);
  };
  model.eye = {row(0), row(1), row(2)};
  model.near = std::max<std::int64_t>(1, std::llround(static_cast<double>(camera.near) * scale));
  return model;
}

TEST(SceneRenderer, ATransformedInstanceIsItsModelDrawnByTheInverseCamera) {
  struct Case {
    InstanceTransform transform;
    bool exact;  // the eye exact (quarter turns, and this 30 degrees): word for word
  };
  const std::vector<Case> cases = {
      {{{3 * kU, -kU / 2, 5 * kU}, Angle::fromDegrees(90), 1}, true},
      {{{-7 * kU, kU, 2 * kU}, Angle::fromDegrees(180), 0}, true},
      {{{kU / 3, 0, -kU / 5}, Angle::fromDegrees(270), -1}, true},
      {{{2 * kU, 0, 3 * kU}, Angle::fromDegrees(30), 2}, true},
      {{{-kU, kU / 7, kU / 2}, Angle::fromMilliDegrees(-123456), -2}, false}};
  for (const Case& k : cases) {
    for (const PerspectiveCamera& alone : sceneTestCameras()) {
      // The scene's eye: where the model's eye lies once the instance is placed.
      const InstanceTransform& t = k.transform;
      const double a = radiansOf(t.turn), s = std::ldexp(1.0, t.scale);
      const double e[3] = {static_cast<double>(alone.eye.x), static_cast<double>(alone.eye.y),
                           static_cast<double>(alone.eye.z)};
      PerspectiveCamera camera = alone;
      camera.eye = {t.at.x + std::llround(s * (std::cos(a) * e[0] + std::sin(a) * e[2])),
                    t.at.y + std::llround(s * e[1]),
                    t.at.z + std::llround(s * (-std::sin(a) * e[0] + std::cos(a) * e[2]))};
      camera.yaw = alone.yaw + t.turn;
      camera.near = std::max<std::int64_t>(1, std::llround(static_cast<double>(alone.near) * s));
      const PerspectiveView view = viewOf(camera);
      PerspectiveView reference = viewOf(inverseCamera(camera, t));
      // The scene's depth keys: shift 10 + max(0, scale) of scene units, 10 - min(0, scale) of
      // the model's.
      reference.depth_shift = kPerspectiveDepthShift - std::min(0, t.scale);
      const Comparison c = compare(drawScene({{0, t}}, view), drawAlone(reference));
      // Elsewhere the instance's eye (two products, each rounded) may lie a unit (2^-24 cube
      // edge) from the double-precision one: a few pixels, at most 0.1% of those covered.
      EXPECT_LE(c.different * 1000, k.exact ? 0 : c.covered) << c.different << " pixels";
      EXPECT_GT(c.covered, 1000);
    }
  }
}

// Two instances, the nearer wholly in front of the farther (its farthest depth 2.87 cube edges,
// the farther's nearest 3.27): the frame is the pixelwise nearer word of each drawn alone (the
// nearer's pixels where both cover), whatever their order in the scene, and the farther one's
// hidden subtrees are passed over.
TEST(SceneRenderer, TheNearerOfTwoInstancesHidesTheFarther) {
  const PerspectiveView view = viewOf(perspectiveCameraOf({0, 0, -2 * kU}, 0, 0, 60, 320, 240));
  const SceneInstance near{0, {{0, 0, 0}, {}, 0}};
  const SceneInstance far{0, {{kU, 0, 5 * kU}, Angle::fromDegrees(40), 1}};
  // Alone, with the two-instance scene's depth shift (its largest scale, 1, makes it): the far
  // one's copy parked behind the eye, outside the frustum.
  SceneInstance parked = far;
  parked.transform.at = {0, 0, -100 * kU};
  SceneDrawStats both_stats, near_stats, far_stats;
  const Framebuffer both = drawScene({far, near}, view, &both_stats);
  const Framebuffer swapped = drawScene({near, far}, view);
  const Framebuffer a = drawScene({near, parked}, view, &near_stats);
  const Framebuffer b = drawScene({far}, view, &far_stats);
  EXPECT_EQ(compare(both, swapped).different, 0);
  EXPECT_EQ(near_stats.instances_drawn, 1u);
  std::int64_t overlap = 0, different = 0, far_shows = 0;
  for (std::int32_t y = 0; y < 240; ++y) {
    for (std::int32_t x = 0; x < 320; ++x) {
      different += both.pixelAt(x, y) != std::min(a.pixelAt(x, y), b.pixelAt(x, y));
      if (a.covered(x, y) && b.covered(x, y)) {
        ++overlap;
        different += both.pixelAt(x, y) != a.pixelAt(x, y);
      }
      far_shows += !a.covered(x, y) && b.covered(x, y);
    }
  }
  EXPECT_EQ(different, 0);
  EXPECT_GT(overlap, 1000);
  EXPECT_GT(far_shows, 100);
  EXPECT_EQ(both_stats.instances_drawn, 2u);
  EXPECT_GT(both_stats.points.hidden_subtrees, 10u);
  EXPECT_LT(both_stats.points.leaves, near_stats.points.leaves + far_stats.points.leaves);
}

// An instance moved between frames is drawn where it moved: the frame of the scene made with it
// there, word for word, and not the frame before the move.
TEST(SceneRenderer, AMovedInstanceRedrawsWhereItMoved) {
  const PerspectiveView view = viewOf(perspectiveCameraOf({0, 0, -3 * kU}, 10, 0, 60, 320, 240));
  const SceneInstance crate{0, {{-kU, 0, 0}, Angle::fromDegrees(20), 0}};
  const SceneInstance crane{0, {{kU, 0, kU}, {}, 0}};
  const ModelView* models[] = {&defaultModelView()};
  SceneError error;
  const std::vector<SceneInstance> list = {crate, crane};
  SceneRenderer scene(models, list, &error);
  ASSERT_EQ(error, SceneError::kNone);
  Framebuffer before(320, 240), after(320, 240);
  before.clear();
  ASSERT_TRUE(scene.draw(view, before));
  const InstanceTransform moved{{-kU / 2, kU / 4, kU / 2}, Angle::fromDegrees(75), 0};
  ASSERT_EQ(scene.place(0, moved), SceneError::kNone);
  after.clear();
  ASSERT_TRUE(scene.draw(view, after));
  EXPECT_EQ(compare(after, drawScene({{0, moved}, crane}, view)).different, 0);
  EXPECT_GT(compare(after, before).different, 1000);
}

TEST(SceneRenderer, RefusesBadScenesAndMoves) {
  const ModelView* models[] = {&defaultModelView()};
  const auto made = [&](std::vector<SceneInstance> instances) {
    SceneError error;
    SceneRenderer scene(models, instances, &error);
    return error;
  };
  EXPECT_EQ(made({}), SceneError::kNoInstances);
  EXPECT_EQ(made({{1, {}}}), SceneError::kBadModelIndex);
  EXPECT_EQ(made({{0, {{}, {}, 9}}}), SceneError::kBadScale);
  EXPECT_EQ(made({{0, {{}, {}, -9}}}), SceneError::kBadScale);
  EXPECT_EQ(made({{0, {{0, kMaxSceneCoordinate + 1, 0}, {}, 0}}}), SceneError::kCoordinateTooLarge);
  EXPECT_EQ(made({{0, {{0, 0, -kMaxSceneCoordinate}, {}, 8}}}), SceneError::kNone);
  {
    SceneError error;
    const std::vector<SceneInstance> none;
    SceneRenderer scene({}, none, &error);
    EXPECT_EQ(error, SceneError::kNoModels);
    Framebuffer frame(8, 8);
    EXPECT_FALSE(scene.draw(viewOf(perspectiveCameraOf({}, 0, 0, 60, 8, 8)), frame));
  }
  SceneError error;
  const std::vector<SceneInstance> list = {{0, {{}, {}, 1}}};
  SceneRenderer scene(models, list, &error);
  EXPECT_EQ(scene.place(1, {}), SceneError::kBadInstanceIndex);
  EXPECT_EQ(scene.place(0, {{}, {}, 2}), SceneError::kScaleAboveScene);
  EXPECT_EQ(scene.place(0, {{kMaxSceneCoordinate * 2, 0, 0}, {}, 0}),
            SceneError::kCoordinateTooLarge);
  EXPECT_EQ(scene.instance(0).transform.scale, 1);  // left where it was
  EXPECT_EQ(scene.place(0, {{kU, 0, 0}, {}, -3}), SceneError::kNone);
  EXPECT_EQ(scene.instance(0).transform.at.x, kU);
}

// Instances farther than the camera reaches (kMaxEyeDistance of their own cube edges), or outside
// the frustum, are counted and not drawn; a far instance at a large scale is still drawn.
TEST(SceneRenderer, PassesOverInstancesOutOfViewOrBeyondReach) {
  const PerspectiveView view = viewOf(perspectiveCameraOf({0, 0, -2 * kU}, 0, 0, 60, 320, 240));
  SceneDrawStats stats;
  const Framebuffer frame =
      drawScene({{0, {{0, 0, 0}, {}, 0}},
                 {0, {{0, 0, 300 * kU}, {}, 0}},  // 302 edges away: beyond reach
                 {0, {{0, 0, 300 * kU}, {}, 3}},  // 38 of its own edges: drawn
                 {0, {{0, 0, -10 * kU}, {}, 0}},  // behind the eye
                 {0, {{40 * kU, 0, 0}, {}, 0}}},  // far to the right
                view, &stats);
  // The far one lies behind the first: hidden by it, it is not set up (counted as occluded).
  EXPECT_EQ(stats.instances_drawn + stats.occluded, 2u);
  EXPECT_EQ(stats.beyond_reach, 1u);
  EXPECT_EQ(stats.outside_frustum, 2u);
}

}  // namespace
}  // namespace scene_test
}  // namespace octopoint
