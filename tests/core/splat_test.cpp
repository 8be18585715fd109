// Footprint splats and depth by projected size (octopoint/camera.h,
// renderer/level_of_detail.h): dense synthetic surfaces leave no hole inside their exact
// silhouette at every zoom 0.25..8 and size 1x1..4096x4096; splats clip per pixel to the frame
// they are given (bands of a frame concatenate to the whole frame, bit for bit; under ASan no write
// lands outside); the depth rule at its boundaries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "octopoint/fixed.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"
#include "tests/support/synthetic_levels.h"

namespace octopoint {
namespace {

using testing_support::Square;
using testing_support::SyntheticLevel;

#if defined(__arm__)
constexpr int kFinestDepth = 6;  // under qemu: the same checks, smaller
#else
constexpr int kFinestDepth = 8;
#endif
constexpr double kSphereRadius = 0.35;    // cube units
constexpr double kBoundaryMargin = 0.01;  // pixels: centres this close to the edge are not judged
const Square kSquare{{0.8, 0.6, 0.0}, {-0.36, 0.48, 0.8}, 0.6};  // orthonormal u, v

// Every depth 1..kFinestDepth of both surfaces, built once.
struct Surfaces {
  std::vector<SyntheticLevel> sphere, square;
  std::vector<int> depths;
  Surfaces() {
    for (int depth = 1; depth <= kFinestDepth; ++depth) {
      sphere.push_back(testing_support::sphereLevel(kSphereRadius, depth));
      square.push_back(testing_support::squareLevel(kSquare, depth));
      depths.push_back(depth);
    }
  }
};
const Surfaces& surfaces() {
  static const Surfaces built;
  return built;
}

Camera cameraOf(int width, int height, double zoom, int yaw, int pitch) {
  return testing_support::viewOf(width, height, zoom, yaw, pitch);
}

// The exact screen projection the renderer approximates: s = R q * edge + (w/2, h/2), with R the
// renderer's own rotation (Q1.30, exact in a double) and q in cube units.
struct Projection {
  double r[2][3];
  double edge_px, centre_x, centre_y;
  explicit Projection(const Camera& camera) {
    const Rotation rotation = rotationFromYawPitchRoll(camera.yaw, camera.pitch, camera.roll);
    for (int a = 0; a < 2; ++a) {
      for (int j = 0; j < 3; ++j) r[a][j] = std::ldexp(rotation.m_q30[a][j], -30);
    }
    edge_px = std::ldexp(camera.zoom.raw(), -16) * std::min(camera.width, camera.height);
    centre_x = camera.width / 2.0;
    centre_y = camera.height / 2.0;
  }
  // Screen vector (pixels) of a cube-unit direction.
  std::array<double, 2> of(const std::array<double, 3>& q) const {
    return {edge_px * (r[0][0] * q[0] + r[0][1] * q[1] + r[0][2] * q[2]),
            edge_px * (r[1][0] * q[0] + r[1][1] * q[1] + r[1][2] * q[2])};
  }
};

// Signed distance (pixels) from a pixel centre into the silhouette: > 0 inside.
using Silhouette = std::function<double(double x, double y)>;

Silhouette sphereSilhouette(const Projection& p) {
  const double radius_px = kSphereRadius * p.edge_px;  // a rotated sphere is still a disc
  return [=](double x, double y) { return radius_px - std::hypot(x - p.centre_x, y - p.centre_y); };
}

// The square projects to a parallelogram centred on the screen centre, spanned by a * U + b * V
// with |a|, |b| <= side / 2 (U, V the projected u, v): inside when both |a|, |b| are, and the
// distance to its nearest edge line is the margin.
Silhouette squareSilhouette(const Projection& p) {
  const std::array<double, 2> u = p.of(kSquare.u), v = p.of(kSquare.v);
  const double det = u[0] * v[1] - u[1] * v[0];
  const double half = kSquare.side / 2;
  return [=](double x, double y) {
    const double dx = x - p.centre_x, dy = y - p.centre_y;
    const double a = (dx * v[1] - dy * v[0]) / det, b = (u[0] * dy - u[1] * dx) / det;
    // Distance to the edges b = +-half (lines along U) and a = +-half (along V), in pixels.
    const double to_b = (half - std::fabs(b)) * std::fabs(det) / std::hypot(u[0], u[1]);
    const double to_a = (half - std::fabs(a)) * std::fabs(det) / std::hypot(v[0], v[1]);
    return std::min(to_a, to_b);
  };
}

struct Coverage {
  long judged = 0;  // pixel centres inside the silhouette by more than the margin
  long holes = 0;
  int depth = 0;
};

Coverage drawAndCount(Variant variant, const std::vector<SyntheticLevel>& levels,
                      const Camera& camera, const Silhouette& inside, Framebuffer& frame) {
  Coverage result;
  const std::optional<int> depth = autoDepth(surfaces().depths, camera);
  EXPECT_TRUE(depth.has_value());
  if (!depth) return result;
  result.depth = *depth;
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, *depth, kDefaultFractionBits, &setup), CameraError::kNone);
  frame.clear();
  EXPECT_TRUE(
      renderLevel(variant, levels[static_cast<std::size_t>(*depth - 1)].view(), setup, frame));
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      if (inside(x + 0.5, y + 0.5) <= kBoundaryMargin) continue;
      ++result.judged;
      if (!frame.covered(x, y)) ++result.holes;
    }
  }
  return result;
}

struct Size {
  int width, height;
};

void expectNoHoles(const std::vector<Size>& sizes, const std::vector<std::pair<int, int>>& angles,
                   const std::vector<Variant>& variants) {
  const double zooms[] = {0.25, 0.5, 1, 2, 4, 8};
  long judged = 0;
  for (const Size size : sizes) {
    Framebuffer frame(size.width, size.height);
    for (const double zoom : zooms) {
      for (const auto& [yaw, pitch] : angles) {
        const Camera camera = cameraOf(size.width, size.height, zoom, yaw, pitch);
        const Projection projection(camera);
        for (const Variant variant : variants) {
          for (const bool sphere : {true, false}) {
            const Coverage c = drawAndCount(
                variant, sphere ? surfaces().sphere : surfaces().square, camera,
                sphere ? sphereSilhouette(projection) : squareSilhouette(projection), frame);
            judged += c.judged;
            EXPECT_EQ(c.holes, 0) << (sphere ? "sphere " : "square ") << size.width << "x"
                                  << size.height << " zoom " << zoom << " yaw " << yaw << " pitch "
                                  << pitch << " depth " << c.depth << ": " << c.holes << " of "
                                  << c.judged << " pixels empty";
          }
        }
      }
    }
  }
  EXPECT_GT(judged, 0);
}

std::vector<Variant> splattingVariants() {
  std::vector<Variant> variants = {Variant::kFixedFast};
  if (simdDecoderAvailable()) variants.push_back(Variant::kFixedSimd);
  return variants;
}

TEST(Splats, DenseSphereAndSquareLeaveNoHoleInsideTheirSilhouetteAtEveryZoomOnSmallScreens) {
#if defined(__arm__)  // under qemu, with soft-float silhouettes: fewer sizes and angles
  expectNoHoles({{1, 1}, {17, 13}, {64, 48}}, {{0, 0}, {35, 20}}, splattingVariants());
#else
  expectNoHoles({{1, 1}, {2, 3}, {17, 13}, {176, 208}, {320, 240}},
                {{0, 0}, {30, 0}, {35, 20}, {135, 60}}, splattingVariants());
#endif
}

TEST(Splats, DenseSphereAndSquareLeaveNoHoleInsideTheirSilhouetteAtEveryZoomOnLargeScreens) {
#if defined(__arm__)
  expectNoHoles({{176, 208}}, {{30, 0}}, {defaultVariant()});
#else
  expectNoHoles({{640, 480}, {1280, 960}, {1920, 1080}}, {{30, 0}, {135, 60}}, {defaultVariant()});
  expectNoHoles({{4096, 4096}}, {{35, 20}}, {defaultVariant()});
#endif
}

// The same check breaks when the splat does: one pixel per leaf past zoom 1 leaves holes.
TEST(Splats, OnePixelPerLeafLeavesHolesWhereSplatsDoNot) {
  const Camera camera = cameraOf(320, 240, 4, 30, 0);
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, kFinestDepth, kDefaultFractionBits, &setup),
            CameraError::kNone);
  ASSERT_TRUE(setup.splat.active());
  setup.splat = SplatFootprint{};
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  ASSERT_TRUE(renderLevel(Variant::kFixedFast, surfaces().sphere.back().view(), setup, frame));
  const Silhouette inside = sphereSilhouette(Projection(camera));
  long holes = 0;
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x)
      holes += inside(x + 0.5, y + 0.5) > 0 && !frame.covered(x, y) ? 1 : 0;
  }
  EXPECT_GT(holes, 1000);
}

// A band of rows [y0, y0 + B) is the whole frame's set-up with root.y shifted up by y0 << F and
// height B (how band rendering draws): with splats clipped per pixel to the band's own buffer, the
// bands put together are the whole frame, bit for bit. Pans put splats across every edge; under
// ASan a splat write outside a band's buffer fails the run.
TEST(Splats, BandsOfAFrameConcatenateToTheWholeFrame) {
  const SyntheticLevel& level = surfaces().sphere.back();
  for (const Variant variant : splattingVariants()) {
    for (const double zoom : {3.0, 8.0, 20.0}) {
      for (const int pan : {0, 37, -90}) {
        Camera camera = cameraOf(160, 120, zoom, 30, 15);
        camera.pan_x_px = pan;
        camera.pan_y_px = -pan / 2;
        FrameSetup whole;
        ASSERT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &whole),
                  CameraError::kNone);
        ASSERT_TRUE(whole.splat.active());
        Framebuffer frame(camera.width, camera.height);
        frame.clear();
        ASSERT_TRUE(renderLevel(variant, level.view(), whole, frame));
        for (const int band_rows : {1, 7, 32}) {
          for (int y0 = 0; y0 < camera.height; y0 += band_rows) {
            const int rows = std::min(band_rows, camera.height - y0);
            FrameSetup band = whole;
            band.root.y -= y0 << band.fraction_bits;
            band.height = rows;
            Framebuffer part(camera.width, rows);
            part.clear();
            ASSERT_TRUE(renderLevel(variant, level.view(), band, part));
            const auto expected =
                frame.pixels().subspan(static_cast<std::size_t>(y0) * camera.width,
                                       static_cast<std::size_t>(rows) * camera.width);
            ASSERT_TRUE(std::ranges::equal(part.pixels(), expected))
                << "zoom " << zoom << " pan " << pan << " band " << y0 << "+" << rows;
          }
        }
      }
    }
  }
}

std::optional<int> autoDepthOf(std::vector<int> depths, const Camera& camera) {
  return autoDepth(depths, camera);
}

// The rule (renderer/level_of_detail.h) at its boundaries. Frontal on a 256 x 256 frame at zoom 1
// a depth-8 voxel's edge is exactly one pixel: depth 8 is drawn, one pixel per leaf; a zoom one
// unit of Q16.16 larger (2^-16) makes the edge longer than a pixel, so depth 9 is drawn, or depth
// 8 with splats when it is the finest.
TEST(DepthByProjectedSize, EdgeOfExactlyOnePixelIsDrawnWithoutSplats) {
  Camera camera = cameraOf(256, 256, 1, 0, 0);
  EXPECT_EQ(autoDepthOf({6, 7, 8, 9, 10}, camera), 8);
  EXPECT_FALSE(leafFootprint(camera, 8, kDefaultFractionBits)->active());
  EXPECT_EQ(leafFootprint(camera, 8, kDefaultFractionBits)->extent_x, 1 << kDefaultFractionBits);
  camera.zoom = Q16::fromRaw(Q16::kOneRaw + 1);  // edge 1 + 2^-16 pixel
  EXPECT_EQ(autoDepthOf({6, 7, 8, 9, 10}, camera), 9);
  EXPECT_EQ(autoDepthOf({6, 7, 8}, camera), 8);
  camera.zoom = Q16::fromRaw(Q16::kOneRaw + 2);
  const SplatFootprint finest = *leafFootprint(camera, 8, kDefaultFractionBits);
  EXPECT_TRUE(finest.active());
  EXPECT_EQ(finest.columns, 2);
  EXPECT_EQ(finest.rows, 2);
  camera.zoom = Q16::fromRaw(Q16::kOneRaw / 2);  // a depth-7 voxel is one pixel
  EXPECT_EQ(autoDepthOf({6, 7, 8, 9, 10}, camera), 7);
  camera.zoom = Q16::fromRaw(Q16::kOneRaw / 2 + 1);
  EXPECT_EQ(autoDepthOf({6, 7, 8, 9, 10}, camera), 8);
  // The shorter side decides: 256 x 1000 is a 256-pixel cube at zoom 1, as is 1000 x 256.
  camera = cameraOf(256, 1000, 1, 0, 0);
  EXPECT_EQ(autoDepthOf({6, 7, 8, 9, 10}, camera), 8);
  camera = cameraOf(1000, 257, 1, 0, 0);
  EXPECT_EQ(autoDepthOf({6, 7, 8, 9, 10}, camera), 9);
}

// Turned, the rule looks at the voxel's edge, not at its footprint: a depth whose edge is at most a
// pixel is drawn even where its turned footprint is wider than a pixel, then with footprint splats.
TEST(DepthByProjectedSize, TurnedViewsDrawTheDepthOfTheEdgeWithSplats) {
  Camera camera = cameraOf(320, 240, 0.25, 30, 0);  // a 60-pixel cube
  // e(d) = 60 / 2^d: 0.94 pixel at depth 6 (footprint 0.94 * (cos 30 + sin 30) = 1.28 pixels).
  EXPECT_EQ(autoDepthOf({1, 2, 3, 4, 5, 6, 7, 8}, camera), 6);
  EXPECT_EQ(autoDepthOf({1, 2, 3, 4, 5}, camera), 5);
  EXPECT_EQ(autoDepthOf({7, 8, 9}, camera), 7);
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, 6, kDefaultFractionBits, &setup), CameraError::kNone);
  EXPECT_GT(setup.splat.extent_x, 1 << kDefaultFractionBits);
  EXPECT_EQ(setup.splat.columns, 2);
  EXPECT_EQ(setup.splat.rows, 1);
  // Turned about two axes the footprint is widest, up to sqrt(3) edges: still two pixels per axis.
  camera = cameraOf(256, 256, 1, 45, 35);
  EXPECT_EQ(autoDepthOf({6, 7, 8, 9, 10}, camera), 8);
  ASSERT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kNone);
  EXPECT_EQ(setup.splat.columns, 2);
  EXPECT_EQ(setup.splat.rows, 2);
  camera.zoom = Q16::fromRaw(8 * Q16::kOneRaw);
  EXPECT_EQ(autoDepthOf({7, 8}, camera), 8);
  camera = cameraOf(320, 240, 8, 30, 0);
  ASSERT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kNone);
  // 1920 / 256 = 7.5 pixels per voxel; x spans 7.5 * (cos 30 + sin 30) = 10.2, y 7.5.
  EXPECT_EQ(setup.splat.columns, 11);
  EXPECT_EQ(setup.splat.rows, 8);
}

TEST(DepthByProjectedSize, TheNeededDepthDoesNotDependOnTheRotation) {
  EXPECT_EQ(neededDepth(cameraOf(1280, 960, 1, 0, 0)), 10);  // 960 / 1024 pixels per voxel
  EXPECT_EQ(neededDepth(cameraOf(1280, 960, 1, 30, 0)), 10);
  EXPECT_EQ(neededDepth(cameraOf(1280, 960, 1, 45, 35)), 10);
  EXPECT_EQ(neededDepth(cameraOf(1280, 960, 1.07, 30, 0)), 11);  // 1027 pixels: 1.003 per voxel
  EXPECT_EQ(neededDepth(cameraOf(320, 240, 1, 0, 0)), 8);
  EXPECT_EQ(neededDepth(cameraOf(176, 208, 0.25, 0, 0)), 6);
}

TEST(DepthByProjectedSize, RefusedCamerasPickNothing) {
  Camera camera = cameraOf(8192, 8192, 1, 0, 0);
  camera.zoom = Q16::fromRaw(0x7FFF'FFFF);
  EXPECT_FALSE(autoDepthOf({6, 7, 8}, camera).has_value());
  camera.width = 0;
  EXPECT_FALSE(neededDepth(camera).has_value());
}

TEST(DefaultVariant, IsTheFastestThisCpuRuns) {
  EXPECT_EQ(defaultVariant(), simdDecoderAvailable() ? Variant::kFixedSimd : Variant::kFixedFast);
  EXPECT_TRUE(drawsSplats(defaultVariant()));
}

}  // namespace
}  // namespace octopoint
