// The near plane a model is seen with (nearPlaneForDepth, renderer/perspective.h): half the voxel
// edge of its finest depth, so that an eye standing just above a surface sees it at its feet.
// Drawn with the eye a few voxels above the default model's table, looking ahead and down: the
// lower part of the frame is the table, covered; with the bare camera's near plane (1/64 cube
// edge, four depth-8 voxels) it is not. And a near plane below nearPlaneFloor is raised to it
// (tests/core/perspective_walk_test.cpp checks the walk's half pixel with these near planes).

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/perspective_reference.h"

namespace octopoint::near_plane_test {
namespace {

const ModelView& tableModel() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

// The topmost (least y: y points down) occupied voxel of `level` in the column of grid cells
// (x, z), or -1: a walk of the depth-first stream.
std::int64_t topOfColumn(const LevelView& level, std::int64_t column_x, std::int64_t column_z) {
  std::int64_t top = -1;
  const std::uint8_t* node = level.nodes.data();
  struct Walker {
    const std::uint8_t*& node;
    int depth;
    std::int64_t cx, cz;
    std::int64_t& top;
    void walk(int at, std::int64_t x, std::int64_t y, std::int64_t z) {
      if (at == depth) {
        if (x == cx && z == cz && (top < 0 || y < top)) top = y;
        return;
      }
      const unsigned mask = *node++;
      for (unsigned k = 0; k < 8; ++k) {
        if (mask & (1u << k))
          walk(at + 1, 2 * x + ((k >> 2) & 1), 2 * y + ((k >> 1) & 1), 2 * z + (k & 1));
      }
    }
  };
  Walker{node, level.depth, column_x, column_z, top}.walk(0, 0, 0, 0);
  return top;
}

struct NearFrame {
  Framebuffer frame;
  PerspectiveDrawStats stats;
};

NearFrame drawWithNear(const PerspectiveCamera& camera, std::int64_t near) {
  PerspectiveCamera with_near = camera;
  with_near.near = near;
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(with_near, kDefaultFractionBits, &view), PerspectiveError::kNone);
  NearFrame drawn{Framebuffer(camera.width, camera.height), {}};
  drawn.frame.clear();
  PerspectiveRenderer renderer(tableModel());
  EXPECT_TRUE(renderer.draw(view, {}, drawn.frame, &drawn.stats));
  return drawn;
}

// The share of the frame's lowest quarter that is covered, in percent.
std::int64_t lowerQuarterCovered(const Framebuffer& frame) {
  std::int64_t covered = 0, all = 0;
  for (std::int32_t y = frame.height() * 3 / 4; y < frame.height(); ++y) {
    for (std::int32_t x = 0; x < frame.width(); ++x) {
      covered += frame.covered(x, y);
      ++all;
    }
  }
  return covered * 100 / all;
}

// The eye `voxels` depth-8 voxel edges above the table at the cell column (x, z) of depth 8,
// looking along +z and 30 degrees down.
PerspectiveCamera aboveTheTable(std::int64_t cell_x, std::int64_t cell_z, std::int64_t voxels) {
  const LevelView& level = tableModel().finestLevel();
  const std::int64_t top = topOfColumn(level, cell_x, cell_z);
  EXPECT_GE(top, 0) << "no surface in that column";
  const std::int64_t edge = kPerspectiveUnit >> level.depth;  // Q.24
  const auto centre = [&](std::int64_t cell) {
    return cell * edge + edge / 2 - kPerspectiveUnit / 2;
  };
  return perspectiveCameraOf({centre(cell_x), centre(top) - voxels * edge, centre(cell_z)}, 0, -30,
                             60, 320, 240);
}

TEST(PerspectiveNearPlane, IsHalfTheFinestVoxelEdge) {
  EXPECT_EQ(nearPlaneForDepth(1), kPerspectiveUnit / 4);
  EXPECT_EQ(nearPlaneForDepth(8), kPerspectiveUnit / 512);
  EXPECT_EQ(nearPlaneForDepth(16), std::int64_t{1} << 7);
  EXPECT_EQ(nearPlaneForDepth(17), nearPlaneForDepth(16));  // beyond what a model stores
  EXPECT_EQ(nearPlaneForDepth(0), nearPlaneForDepth(1));
}

// A near plane nearer than nearPlaneFloor is raised to it (the rounding of camera-space
// coordinates to the unit then moves a projection by at most 1/8 pixel); the bare camera's 1/64
// edge is above it at every size and field of view.
TEST(PerspectiveNearPlane, IsRaisedToWhereTheUnitsRoundingStaysBelowAnEighthPixel) {
  PerspectiveCamera camera = perspectiveCameraOf({0, 0, 0}, 0, 0, 10, 8192, 8192);
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  EXPECT_EQ(view.camera.near, PerspectiveCamera{}.near);  // the default is kept
  EXPECT_LT(nearPlaneFloor(view.focal_q16, 8192, 8192), PerspectiveCamera{}.near);
  camera = perspectiveCameraOf({0, 0, 0}, 0, 0, 60, 320, 240);
  camera.near = 1;
  ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  // f = 120 / tan(30 degrees) = 207.8 pixels: 4 * (207 + 1 + 160).
  EXPECT_EQ(view.camera.near, 4 * (207 + 1 + 160));
  camera.near = nearPlaneForDepth(8);  // far above it: kept
  ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  EXPECT_EQ(view.camera.near, nearPlaneForDepth(8));
}

TEST(PerspectiveNearPlane, TheSurfaceAtTheEyesFeetIsDrawn) {
  const LevelView& finest = tableModel().finestLevel();
  ASSERT_EQ(finest.depth, 8);
  const std::int64_t model_near = nearPlaneForDepth(finest.depth);
  // The middle of the table, two and three voxels above it.
  for (const std::int64_t voxels : {2, 3}) {
    SCOPED_TRACE(std::to_string(voxels) + " voxels above the table");
    const PerspectiveCamera camera = aboveTheTable(128, 96, voxels);
    const NearFrame model_frame = drawWithNear(camera, model_near);
    const NearFrame bare_frame = drawWithNear(camera, PerspectiveCamera{}.near);
    EXPECT_GE(lowerQuarterCovered(model_frame.frame), 95);
    EXPECT_LE(lowerQuarterCovered(bare_frame.frame), 50);
  }
}

}  // namespace
}  // namespace octopoint::near_plane_test
