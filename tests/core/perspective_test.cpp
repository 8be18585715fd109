// The perspective camera's integer core against a double-precision projection: conventions, the
// projection's error at every field of view and fraction format, the camera-space transform for
// eyes outside, at and deep inside the cube, the affine error bound, and refusals.

#include "renderer/perspective.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace {

PerspectiveView viewOf(const PerspectiveCamera& camera, int fraction_bits = kDefaultFractionBits) {
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, fraction_bits, &view), PerspectiveError::kNone);
  return view;
}

double pixelsOf(std::int64_t raw, int fraction_bits) { return std::ldexp(raw, -fraction_bits); }

TEST(PerspectiveCamera, LooksAlongZAndTurnsRightUpAndRollsAsDocumented) {
  PerspectiveCamera camera;
  camera.eye = {0, 0, 0};
  struct Case {
    int yaw, pitch;
    ModelPoint ahead;
  };
  const std::int64_t u = kPerspectiveUnit / 2;
  for (const Case& c : {Case{0, 0, {0, 0, u}}, Case{90, 0, {u, 0, 0}}, Case{-90, 0, {-u, 0, 0}},
                        Case{0, 90, {0, -u, 0}}, Case{0, -90, {0, u, 0}}}) {
    SCOPED_TRACE(::testing::Message() << "yaw " << c.yaw << " pitch " << c.pitch);
    camera.yaw = Angle::fromDegrees(c.yaw);
    camera.pitch = Angle::fromDegrees(c.pitch);
    const PerspectiveView view = viewOf(camera);
    const std::optional<ScreenPoint> point = project(view, toCameraSpace(view, c.ahead));
    ASSERT_TRUE(point.has_value());
    EXPECT_EQ(point->x, view.centre_x);
    EXPECT_EQ(point->y, view.centre_y);
    EXPECT_EQ(point->z, u);
  }
  // Rolled 90 degrees clockwise about the line of sight, the eye sees what was right of it below.
  camera.yaw = camera.pitch = Angle{};
  camera.roll = Angle::fromDegrees(90);
  const PerspectiveView view = viewOf(camera);
  const std::optional<ScreenPoint> right = project(view, toCameraSpace(view, {u / 4, 0, u}));
  ASSERT_TRUE(right.has_value());
  EXPECT_EQ(right->x, view.centre_x);
  EXPECT_LT(right->y, view.centre_y);
}

TEST(PerspectiveCamera, FocalLengthFollowsTheFieldOfView) {
  PerspectiveCamera camera;
  camera.height = 480;
  for (int degrees = kMinFieldOfViewDegrees; degrees <= kMaxFieldOfViewDegrees; ++degrees) {
    camera.fov = Angle::fromDegrees(degrees);
    const PerspectiveView view = viewOf(camera);
    EXPECT_NEAR(pixelsOf(view.focal_q16, 16), focalOf(camera), 1e-3) << degrees << " degrees";
  }
  camera.fov = Angle::fromDegrees(90);
  EXPECT_NEAR(pixelsOf(viewOf(camera).focal_q16, 16), 240.0, 1e-4);
}

// Every projected coordinate within half a unit in the last place plus 2^-15 pixel of the exact
// projection of the same camera-space point, near and far, on and off the screen.
TEST(PerspectiveCamera, ProjectionIsWithinHalfAnUlpOfTheExactOne) {
  std::mt19937_64 random(7);
  for (int fov : {10, 30, 60, 90, 120}) {
    for (int fraction_bits : {1, 8, 15, 24}) {
      PerspectiveCamera camera;
      camera.fov = Angle::fromDegrees(fov);
      camera.width = 1280;
      camera.height = 960;
      const PerspectiveView view = viewOf(camera, fraction_bits);
      const double ulp = std::ldexp(1.0, -fraction_bits);
      double worst = 0;
      std::uniform_real_distribution<double> log_depth(std::log(camera.near / kUnit),
                                                       std::log(200.0));
      std::uniform_real_distribution<double> spread(-1.2, 1.2);
      for (int i = 0; i < 20000; ++i) {
        const double z = std::exp(log_depth(random)) * kUnit;
        const CameraPoint point{std::llround(spread(random) * z), std::llround(spread(random) * z),
                                std::llround(z)};
        const std::optional<ScreenPoint> screen = project(view, point);
        if (!screen) continue;  // beyond what Q(32-F).F holds
        const Projected exact =
            exactProjection(camera, static_cast<double>(point.x), static_cast<double>(point.y),
                            static_cast<double>(point.z));
        worst = std::max({worst, std::abs(pixelsOf(screen->x, fraction_bits) - exact.x),
                          std::abs(pixelsOf(screen->y, fraction_bits) - exact.y)});
      }
      EXPECT_LE(worst, ulp / 2 + std::ldexp(1.0, -15)) << fov << " degrees, F = " << fraction_bits;
    }
  }
}

// The camera-space transform for eyes outside the cube, at its face and corner, and deep inside:
// within 8 units (half a unit of rounding plus the rotation's 3.5 Q30 ulp times 2^31 units).
TEST(PerspectiveCamera, CameraSpaceIsTheRotatedOffsetFromTheEye) {
  std::mt19937_64 random(11);
  const std::int64_t half = kPerspectiveUnit / 2, far = kMaxEyeDistance * kPerspectiveUnit;
  const std::array<ModelPoint, 7> eyes{{{0, 0, -2 * kPerspectiveUnit},
                                        {0, 0, -half},
                                        {half, half, half},
                                        {0, 0, 0},
                                        {123, -4567, 89},
                                        {far, -far, far},
                                        {-far, 0, 0}}};
  std::uniform_int_distribution<std::int64_t> in_cube(-half, half);
  std::uniform_int_distribution<int> angle(0, Angle::kUnitsPerTurn - 1);
  for (const ModelPoint& eye : eyes) {
    PerspectiveCamera camera;
    camera.eye = eye;
    camera.yaw = Angle::fromTurns16(angle(random));
    camera.pitch = Angle::fromTurns16(angle(random));
    camera.roll = Angle::fromTurns16(angle(random));
    const PerspectiveView view = viewOf(camera);
    const Matrix m = worldToCamera(camera);
    for (int i = 0; i < 2000; ++i) {
      const ModelPoint p{in_cube(random), in_cube(random), in_cube(random)};
      const CameraPoint c = toCameraSpace(view, p);
      const Vector3 exact = exactCameraSpace(m, eye, p);
      const std::int64_t got[3] = {c.x, c.y, c.z};
      for (int row = 0; row < 3; ++row) {
        ASSERT_LE(std::abs(static_cast<double>(got[row]) - exact[row]), 8.0)
            << "eye " << eye.x << "," << eye.y << "," << eye.z << " row " << row;
      }
    }
  }
}

// The affine map at a subtree's centre stays within affineErrorBound of the exact projection at
// the subtree's corners and inside it, and the bound is not loose by more than a few times.
TEST(PerspectiveCamera, AffineMapStaysWithinTheStatedBound) {
  std::mt19937_64 random(13);
  for (int fov : {30, 60, 90, 120}) {
    PerspectiveCamera camera;
    camera.fov = Angle::fromDegrees(fov);
    camera.width = 1280;
    camera.height = 960;
    camera.yaw = Angle::fromDegrees(20);
    camera.pitch = Angle::fromDegrees(-10);
    camera.roll = Angle::fromDegrees(5);
    constexpr int kF = kDefaultFractionBits;
    const PerspectiveView view = viewOf(camera, kF);
    const Matrix m = worldToCamera(camera);
    int checked = 0;
    for (int level = 2; level <= 12; ++level) {
      const std::int64_t half = kPerspectiveUnit >> (level + 1);  // a node of `level`
      const std::int64_t reach = rotatedCubeReach(half);
      std::uniform_real_distribution<double> depth(3.0 * reach, 40.0 * reach);
      std::uniform_real_distribution<double> spread(-0.8, 0.8);
      for (int i = 0; i < 200; ++i) {
        const double z = depth(random);
        const CameraPoint c{std::llround(spread(random) * z), std::llround(spread(random) * z),
                            std::llround(z)};
        const std::optional<std::int64_t> bound = affineErrorBound(view, c, reach);
        const std::optional<AffineProjection> affine = affineAt(view, c);
        if (!bound || !affine) continue;
        double worst = 0;
        std::uniform_int_distribution<std::int64_t> inside(-half, half);
        for (int k = 0; k < 16; ++k) {
          // The 8 corners, then random points inside the node.
          const std::int64_t d[3] = {k < 8 ? ((k & 4) ? half : -half) : inside(random),
                                     k < 8 ? ((k & 2) ? half : -half) : inside(random),
                                     k < 8 ? ((k & 1) ? half : -half) : inside(random)};
          const Vector3 dc = rotated(
              m, {static_cast<double>(d[0]), static_cast<double>(d[1]), static_cast<double>(d[2])});
          const Projected exact =
              exactProjection(camera, static_cast<double>(c.x) + dc[0],
                              static_cast<double>(c.y) + dc[1], static_cast<double>(c.z) + dc[2]);
          double x = static_cast<double>(affine->centre.x),
                 y = static_cast<double>(affine->centre.y);
          for (int a = 0; a < 3; ++a) {
            x += static_cast<double>(affine->axis[a].x) * static_cast<double>(d[a]) / kUnit;
            y += static_cast<double>(affine->axis[a].y) * static_cast<double>(d[a]) / kUnit;
          }
          worst = std::max({worst, std::abs(pixelsOf(std::llround(x), kF) - exact.x),
                            std::abs(pixelsOf(std::llround(y), kF) - exact.y)});
        }
        // Slack: the centre's and the axis vectors' rounding and the rotation's error, a few ulp.
        const double slack = 8 * std::ldexp(1.0, -kF);
        ASSERT_LE(worst, pixelsOf(*bound, kF) + slack)
            << fov << " degrees, level " << level << ", z " << z / kUnit << " edges";
        ++checked;
      }
    }
    EXPECT_GT(checked, 1500) << fov << " degrees";
  }
}

TEST(PerspectiveCamera, BoundIsRefusedWhereTheBoxReachesTheNearPlane) {
  const PerspectiveView view = viewOf(PerspectiveCamera{});
  const std::int64_t near = view.camera.near;
  EXPECT_FALSE(affineErrorBound(view, {0, 0, near + 99}, 100).has_value());
  EXPECT_TRUE(affineErrorBound(view, {0, 0, near + 100}, 100).has_value());
  EXPECT_FALSE(project(view, {0, 0, near - 1}).has_value());
  EXPECT_TRUE(project(view, {0, 0, near}).has_value());
  // Far off the axis at the near plane: beyond Q17.15, refused rather than wrapped.
  EXPECT_FALSE(project(view, {kPerspectiveUnit * 100, 0, near}).has_value());
}

TEST(PerspectiveCamera, RefusesWhatItCannotDraw) {
  PerspectiveView view;
  PerspectiveCamera camera;
  camera.width = 0;
  EXPECT_EQ(buildPerspectiveView(camera, 15, &view), PerspectiveError::kBadViewport);
  camera = {};
  camera.fov = Angle::fromDegrees(9);
  EXPECT_EQ(buildPerspectiveView(camera, 15, &view), PerspectiveError::kBadFieldOfView);
  camera.fov = Angle::fromDegrees(121);
  EXPECT_EQ(buildPerspectiveView(camera, 15, &view), PerspectiveError::kBadFieldOfView);
  camera = {};
  camera.near = 0;
  EXPECT_EQ(buildPerspectiveView(camera, 15, &view), PerspectiveError::kBadNearPlane);
  camera = {};
  camera.eye.y = kMaxEyeDistance * kPerspectiveUnit + 1;
  EXPECT_EQ(buildPerspectiveView(camera, 15, &view), PerspectiveError::kEyeTooFar);
  camera = {};
  EXPECT_EQ(buildPerspectiveView(camera, 0, &view), PerspectiveError::kBadFractionBits);
  // Straight up and straight down are views like any other.
  for (int pitch : {90, -90}) {
    camera = {};
    camera.pitch = Angle::fromDegrees(pitch);
    EXPECT_EQ(buildPerspectiveView(camera, 15, &view), PerspectiveError::kNone);
  }
}

}  // namespace
}  // namespace octopoint
