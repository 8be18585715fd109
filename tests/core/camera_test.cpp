// The camera's displacement vectors, and the cameras it must refuse.
#include "octopoint/camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lab/reference_rotation.h"

namespace octopoint {
namespace {

FrameSetup setupFor(const Camera& camera, int depth) {
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, depth, kDefaultFractionBits, &setup), CameraError::kNone);
  return setup;
}

TEST(Camera, IdentityVectorsAreHalfChildEdgesInScreenPixels) {
  Camera camera;
  camera.width = camera.height = 256;
  const FrameSetup setup = setupFor(camera, 8);
  EXPECT_EQ(setup.root.x, 128 << 15);
  EXPECT_EQ(setup.root.y, 128 << 15);
  // Level 0: children 64 pixels from the centre; level 7 (leaf parents): half a pixel.
  EXPECT_EQ(setup.child_offset[0][7].x, 64 << 15);
  EXPECT_EQ(setup.child_offset[0][0].z, -(64 << 15));
  EXPECT_EQ(setup.child_offset[7][5].x, 1 << 14);
  EXPECT_EQ(setup.child_offset[7][5].y, -(1 << 14));
  EXPECT_EQ(setup.child_offset[7][5].z, 1 << 14);
}

TEST(Camera, VectorsMatchTheExactRotationWithinHalfAnUlp) {
  Camera camera;
  camera.yaw = Angle::fromDegrees(30);
  camera.pitch = Angle::fromDegrees(-20);
  camera.roll = Angle::fromDegrees(10);
  camera.zoom = Q16::fromRaw(3 * Q16::kOneRaw / 2);
  const FrameSetup setup = setupFor(camera, 8);
  const Matrix3d r = referenceRotation(camera.yaw, camera.pitch, camera.roll);
  for (int level = 0; level < 8; ++level) {
    for (int k = 0; k < 8; ++k) {
      const double sign[3] = {k & 4 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 1 ? 1.0 : -1.0};
      const Vec3& v =
          setup.child_offset[static_cast<std::size_t>(level)][static_cast<std::size_t>(k)];
      const std::int32_t got[3] = {v.x, v.y, v.z};
      for (int axis = 0; axis < 3; ++axis) {
        double exact = 0;
        for (int j = 0; j < 3; ++j) exact += r[axis][j] * sign[j];
        exact *= 1.5 * 240 / std::pow(2.0, level + 2) * 32768;  // in Q15 units
        // Half an ulp of rounding, plus the sine table's error (about 1e-9 relative) scaled up.
        EXPECT_NEAR(got[axis], exact, 0.5 + 1e-3) << "level " << level << " child " << k;
      }
    }
  }
}

TEST(Camera, RefusesZeroAndNegativeZoom) {
  Camera camera;
  FrameSetup setup;
  camera.zoom = Q16::fromRaw(0);
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kBadZoom);
  camera.zoom = Q16::fromRaw(-Q16::kOneRaw);
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kBadZoom);
}

TEST(Camera, AcceptsTheSmallestZoom) {
  Camera camera;
  camera.zoom = Q16::fromRaw(1);
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kNone);
}

TEST(Camera, RefusesAZoomWhoseCoordinatesWouldOverflow) {
  Camera camera;
  camera.width = camera.height = 4096;
  camera.zoom = Q16::fromRaw(std::numeric_limits<std::int32_t>::max());
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kOverflow);
}

TEST(Camera, RefusesBadViewportsDepthsAndFractionBits) {
  Camera camera;
  FrameSetup setup;
  camera.width = 0;
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kBadViewport);
  camera.width = kMaxViewportSide + 1;
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kBadViewport);
  camera.width = 320;
  EXPECT_EQ(buildFrameSetup(camera, 0, kDefaultFractionBits, &setup), CameraError::kBadDepth);
  EXPECT_EQ(buildFrameSetup(camera, format::kMaxDepth + 1, kDefaultFractionBits, &setup),
            CameraError::kBadDepth);
  EXPECT_EQ(buildFrameSetup(camera, 8, 0, &setup), CameraError::kBadFractionBits);
  EXPECT_EQ(buildFrameSetup(camera, 8, kMaxFractionBits + 1, &setup),
            CameraError::kBadFractionBits);
}

TEST(Camera, RefusesAPanThatWouldOverflow) {
  Camera camera;
  camera.pan_x_px = std::numeric_limits<std::int32_t>::max() / 2;
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kOverflow);
}

}  // namespace
}  // namespace octopoint
