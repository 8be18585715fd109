// The web page's walk mode (web/octopoint_web.h, "Walk mode"), compiled natively and driven as
// web/octopoint_walk.js drives it: keys held for a time move the eye by exactly the speed times the
// time, along the look's yaw, sideways and up, as octopoint-view's walk mode moves it; a drag turns
// it with the pitch kept within +-90 degrees; the wheel's steps set the speed; Tab's entry puts the
// eye where octopoint-render --perspective does; and the frame is the perspective renderer's of the
// eye (detail by distance, culled, resolved on octopoint-render's background), as
// octopoint-render --eye draws it.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "fixedpoint/trig.h"
#include "octopoint/models.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
#include "web/octopoint_web.h"
#include "web/web_canvas.h"

namespace octopoint {
namespace {

constexpr std::int64_t kWalkUnit = kPerspectiveUnit;  // Q.24: one cube edge

struct WalkState {
  ModelPoint eye;
  std::int32_t yaw, pitch, roll, fov;
  std::int64_t speed;
};

WalkState walkState() {
  const std::uint32_t* w = octopoint_web_walk_state();
  const auto wide = [](std::uint32_t low, std::uint32_t high) {
    return static_cast<std::int64_t>(std::uint64_t{high} << 32 | low);
  };
  return {{wide(w[0], w[1]), wide(w[2], w[3]), wide(w[4], w[5])},
          std::int32_t(w[6]),
          std::int32_t(w[7]),
          std::int32_t(w[8]),
          std::int32_t(w[9]),
          wide(w[10], w[11])};
}

// Places the eye at `eye` (Q.24) looking yaw, pitch (thousandths of a degree), fov 60 degrees.
int placeWalker(const ModelPoint& eye, std::int32_t yaw, std::int32_t pitch) {
  const auto low = [](std::int64_t v) { return std::int32_t(std::uint32_t(std::uint64_t(v))); };
  const auto high = [](std::int64_t v) { return std::int32_t(std::uint64_t(v) >> 32); };
  return octopoint_web_walk_place(low(eye.x), high(eye.x), low(eye.y), high(eye.y), low(eye.z),
                                  high(eye.z), yaw, pitch, 0, 60000);
}

class WebWalk : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(octopoint_web_create(), 0);
    // The default speed again (earlier tests may have stepped it): 4/5 then 5/4 is not the same.
    while (walkState().speed > (std::int64_t{1} << 22)) octopoint_web_walk_faster(0);
    while (walkState().speed < (std::int64_t{1} << 22)) octopoint_web_walk_faster(1);
  }
};

TEST_F(WebWalk, KnowsWhereTheEmbeddedModelsCubeLies) {
  const std::uint32_t* words = octopoint_web_walk_cube();
  ASSERT_NE(words, nullptr);
  const CubePlacement& cube = web::embeddedModel()->cubePlacement();
  EXPECT_EQ(words[6] | std::uint64_t{words[7]} << 32, cube.edge_bits);
  EXPECT_EQ(words[2] | std::uint64_t{words[3]} << 32, cube.corner_bits[1]);
  EXPECT_EQ(words[8], 1u);  // the default model is y-up
}

TEST_F(WebWalk, KeysHeldMoveTheEyeBySpeedTimesTimeAlongTheLook) {
  ASSERT_EQ(placeWalker({0, 0, -kWalkUnit}, 30000, 20000), 0);
  const Angle yaw = Angle::fromMilliDegrees(30000);
  // A quarter cube edge a second: w held 1 s walks a quarter edge along the yaw, level.
  ASSERT_EQ(octopoint_web_walk_move(0, 1'000'000), 0);
  const std::int64_t quarter = kWalkUnit / 4;
  const auto along = [](std::int64_t d, std::int32_t q30) {
    return mulShiftRoundQuick(d, q30, 30).value_or(0);
  };
  WalkState now = walkState();
  EXPECT_EQ(now.eye.x, along(quarter, sinQ30(yaw)));
  EXPECT_EQ(now.eye.y, 0);
  EXPECT_EQ(now.eye.z, -kWalkUnit + along(quarter, cosQ30(yaw)));
  // Back 1 s: where it stood.
  ASSERT_EQ(octopoint_web_walk_move(1, 1'000'000), 0);
  EXPECT_EQ(walkState().eye, (ModelPoint{0, 0, -kWalkUnit}));
  // Right 0.5 s: an eighth of an edge at right angles to the yaw; up 0.25 s: -y.
  ASSERT_EQ(octopoint_web_walk_move(3, 500'000), 0);
  ASSERT_EQ(octopoint_web_walk_move(4, 250'000), 0);
  now = walkState();
  EXPECT_EQ(now.eye.x, along(quarter / 2, cosQ30(yaw)));
  EXPECT_EQ(now.eye.y, -quarter / 4);
  EXPECT_EQ(now.eye.z, -kWalkUnit - along(quarter / 2, sinQ30(yaw)));
  // A draw with keys held shows the eye moved by them, and keeps nothing of it.
  ASSERT_EQ(octopoint_web_walk_draw(64, 48, 1, 0, 0, 0, 0, 0, 2'000'000), 0);
  EXPECT_EQ(walkState().eye.y, -quarter / 4 + quarter * 2);
  ASSERT_EQ(octopoint_web_walk_move(2, 0), 0);  // publishes the kept eye
  EXPECT_EQ(walkState().eye, now.eye);
  EXPECT_EQ(octopoint_web_walk_move(6, 1), -1);  // no such key
}

TEST_F(WebWalk, TurnsSetTheSpeedAndEnterWhereThePerspectiveViewPutsTheEye) {
  ASSERT_EQ(placeWalker({0, 0, -kWalkUnit}, 0, 80000), 0);
  ASSERT_EQ(octopoint_web_walk_turn(1000, 2000), 0);
  EXPECT_EQ(walkState().yaw, 1000);
  EXPECT_EQ(walkState().pitch, Angle::kUnitsPerTurn / 4);  // held at straight up
  ASSERT_EQ(octopoint_web_walk_faster(1), 0);
  EXPECT_EQ(walkState().speed, (std::int64_t{1} << 22) * 5 / 4);
  for (int i = 0; i < 100; ++i) octopoint_web_walk_faster(1);
  EXPECT_EQ(walkState().speed, std::int64_t{1} << 30);  // 64 cube edges a second at most
  Camera camera;
  camera.yaw = Angle::fromMilliDegrees(30000);
  camera.pitch = Angle::fromMilliDegrees(10000);
  camera.zoom = Q16::fromRaw(3 << 15);
  camera.width = 320;
  camera.height = 240;
  PerspectiveView expected;
  ASSERT_EQ(orbitPerspective(camera, Angle::fromDegrees(60), kDefaultFractionBits, &expected),
            PerspectiveError::kNone);
  ASSERT_EQ(octopoint_web_walk_enter(30000, 10000, 0, 3 << 15, 320, 240), 0);
  EXPECT_EQ(walkState().eye, expected.camera.eye);
  EXPECT_EQ(walkState().yaw, expected.camera.yaw.turns16());
}

TEST_F(WebWalk, DrawsTheFrameOctopointRenderDrawsFromTheEye) {
  // An eye inside the cube, looking a little left and down.
  const ModelPoint eye{kWalkUnit / 10, -kWalkUnit / 5, kWalkUnit / 3};
  ASSERT_EQ(placeWalker(eye, -5000, -20000), 0);
  const int width = 160, height = 120;
  ASSERT_EQ(octopoint_web_walk_draw(width, height, 0, 0, 0, 0, 0, 0, 0), 0)
      << octopoint_web_error();
  const std::uint8_t* page = octopoint_web_pixels();
  const std::vector<std::uint8_t> drawn(page, page + width * height * 4);
  // tools/perspective_render.cpp's renderPerspective, as RGBA.
  PerspectiveCamera camera;
  camera.eye = eye;
  camera.yaw = Angle::fromMilliDegrees(-5000);
  camera.pitch = Angle::fromMilliDegrees(-20000);
  camera.fov = Angle::fromDegrees(60);
  camera.width = width;
  camera.height = height;
  const ModelView& model = *web::embeddedModel();
  camera.near = nearPlaneForDepth(model.finestLevel().depth);  // octopoint-render --eye's default
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  Framebuffer frame(width, height);
  frame.clear();
  PerspectiveRenderer renderer(model);
  PerspectiveDrawStats stats;
  ASSERT_TRUE(renderer.draw(view, {}, frame, &stats));
  std::vector<std::uint8_t> rgb(std::size_t(width) * height * 3);
  ASSERT_TRUE(resolveToRgb(frame, model, web::kBackground, rgb));
  std::vector<std::uint8_t> rgba;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    rgba.insert(rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 255});
  EXPECT_EQ(drawn, rgba);
  // The points it drew, for the overlay: octopoint-render --eye's "N points drawn".
  ASSERT_GT(stats.leaves, 0u);
  EXPECT_EQ(octopoint_web_walk_state()[12], stats.leaves);
  // A coarse frame (a key held) is another picture, of fewer points; the eye out of reach is
  // refused.
  ASSERT_EQ(octopoint_web_walk_draw(width, height, 1, 0, 0, 0, 0, 0, 0), 0);
  const std::uint8_t* coarse = octopoint_web_pixels();
  EXPECT_NE(std::vector<std::uint8_t>(coarse, coarse + width * height * 4), rgba);
  EXPECT_LT(octopoint_web_walk_state()[12], stats.leaves);
  EXPECT_EQ(placeWalker({129 * kWalkUnit, 0, 0}, 0, 0), -1);
}

}  // namespace
}  // namespace octopoint
