// The perspective walk against a double-precision projection of every leaf of the default model:
// each drawn leaf within half a pixel of it, at fields of view 30 to 120 degrees, the eye outside
// the cube, at its face and deep inside; no leaf in view left out; none behind the eye drawn.

#include "renderer/perspective_walk.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace {

// Every leaf centre of `level` in model space (Q.24 cube edges), in stream order.
void collectLeaves(const std::uint8_t*& node, int level, int depth, ModelPoint centre,
                   std::vector<ModelPoint>& leaves) {
  if (level == depth) {
    leaves.push_back(centre);
    return;
  }
  const std::uint8_t mask = *node++;
  const std::int64_t step = kPerspectiveUnit >> (level + 2);
  for (unsigned k = 0; k < 8; ++k) {
    if (!(mask & (1u << k))) continue;
    const ModelPoint child{centre.x + ((k & 4) ? step : -step), centre.y + ((k & 2) ? step : -step),
                           centre.z + ((k & 1) ? step : -step)};
    collectLeaves(node, level + 1, depth, child, leaves);
  }
}

std::vector<ModelPoint> leafCentres(const LevelView& level) {
  std::vector<ModelPoint> leaves;
  const std::uint8_t* node = level.nodes.data();
  collectLeaves(node, 0, level.depth, {0, 0, 0}, leaves);
  return leaves;
}

struct WalkView {
  std::string name;
  ModelPoint eye;
  int yaw, pitch;
  std::int64_t near = PerspectiveCamera{}.near;  // Q.24
};

class PerspectiveWalkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelIssue issue;
    model_ = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    ASSERT_TRUE(model_.has_value()) << describe(issue.error);
  }
  std::optional<ModelView> model_;
};

TEST_F(PerspectiveWalkTest, EveryLeafInViewIsDrawnWithinHalfAPixelOfItsExactProjection) {
  const LevelView& level = model_->finestLevel();
  const std::vector<ModelPoint> leaves = leafCentres(level);
  const std::int64_t u = kPerspectiveUnit;
  const std::vector<WalkView> views{
      {"outside", {0, 0, -2 * u}, 0, 0},
      {"outside, turned", {u, -u / 2, -u}, -45, -20},
      {"at the cube's face", {0, 0, -u / 2}, 10, -5},
      {"deep inside", {u / 16, u / 8, 0}, 170, 30},
      {"inside, looking up", {0, u / 4, u / 8}, 0, 90},
      // The near plane the tools give this model (half a depth-8 voxel): three voxels above the
      // table, looking down at it, and deep inside (tests/core/perspective_near_test.cpp).
      {"above the table, the model's near plane",
       {u / 512, 1998848, -2064384},
       0,
       -30,
       nearPlaneForDepth(8)},
      {"deep inside, the model's near plane", {u / 16, u / 8, 0}, 170, 30, nearPlaneForDepth(8)},
      // 300 units above a leaf centre on the table, looking down, with a near plane of 1 unit:
      // raised to nearPlaneFloor, every leaf that can reach the screen stays within half a pixel.
      {"300 units above a leaf, near plane 1 unit",
       {32768 + 150, 2260992 - 300, -2064384 + 150},
       7,
       -80,
       1}};
  constexpr int kF = kDefaultFractionBits;
  for (int fov : {30, 60, 90, 120}) {
    for (const WalkView& v : views) {
      SCOPED_TRACE(v.name + ", " + std::to_string(fov) + " degrees");
      PerspectiveCamera camera;
      camera.eye = v.eye;
      camera.yaw = Angle::fromDegrees(v.yaw);
      camera.pitch = Angle::fromDegrees(v.pitch);
      camera.fov = Angle::fromDegrees(fov);
      camera.near = v.near;
      camera.width = 640;
      camera.height = 480;
      PerspectiveView view;
      ASSERT_EQ(buildPerspectiveView(camera, kF, &view), PerspectiveError::kNone);
      const PerspectiveWalkTables tables =
          perspectiveWalkTables(view, level.depth, std::int64_t{1} << (kF - 2));
      std::vector<bool> drawn(leaves.size(), false);
      double worst = 0;
      const Matrix m = worldToCamera(camera);
      auto check = [&](const PerspectiveLeaf& leaf) {
        ASSERT_LT(leaf.index, leaves.size());
        drawn[leaf.index] = true;
        const ModelPoint& p = leaves[leaf.index];
        const Vector3 c = exactCameraSpace(m, v.eye, p);
        ASSERT_GT(c[2], 0) << "leaf " << leaf.index << " behind the eye was drawn";
        const Projected exact = exactProjection(camera, c[0], c[1], c[2]);
        // A leaf whose splat (its voxel's projection, within sqrt(3) half edges of its centre)
        // lies wholly off the screen draws nothing: near the eye, far off the axis, the walk may
        // hand one over whose position is less exact (the unit's rounding times |c.x| / c.z).
        const double reach = focalOf(camera) * 0.87 * kUnit / std::ldexp(c[2], level.depth);
        if (exact.x < -reach || exact.y < -reach || exact.x > camera.width + reach ||
            exact.y > camera.height + reach) {
          return;
        }
        worst = std::max({worst, std::abs(std::ldexp(static_cast<double>(leaf.x), -kF) - exact.x),
                          std::abs(std::ldexp(static_cast<double>(leaf.y), -kF) - exact.y)});
      };
      PerspectiveWalk<decltype(check)> walk(level, view, tables, check);
      ASSERT_TRUE(walk.run());
      EXPECT_LE(worst, 0.5);
      // A leaf whose exact projection lies on the screen, a voxel in front of the near plane, was
      // handed over.
      std::size_t in_view = 0;
      for (std::size_t i = 0; i < leaves.size(); ++i) {
        const Vector3 c = exactCameraSpace(m, v.eye, leaves[i]);
        if (c[2] < static_cast<double>(view.camera.near) + kUnit / 256) continue;
        const Projected exact = exactProjection(camera, c[0], c[1], c[2]);
        if (exact.x < 0 || exact.y < 0 || exact.x >= camera.width || exact.y >= camera.height)
          continue;
        ++in_view;
        ASSERT_TRUE(drawn[i]) << "leaf " << i << " in view at " << exact.x << "," << exact.y;
      }
      if (v.name != "inside, looking up" && v.near != 1) {  // the latter sees only the table
        EXPECT_GT(in_view, 0u);                             // the view shows some of the model
      }
    }
  }
}

// The orbit camera in perspective converges to the orthographic picture of the same zoom as its
// field of view narrows: the model's centre is as large on screen in both.
TEST_F(PerspectiveWalkTest, NarrowFieldOfViewConvergesToTheOrthographicPicture) {
  const LevelView& level = model_->finestLevel();
  Camera camera;
  camera.width = 640;
  camera.height = 480;
  camera.yaw = Angle::fromDegrees(20);
  camera.pitch = Angle::fromDegrees(10);
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup), CameraError::kNone);
  Framebuffer orthographic(camera.width, camera.height);
  orthographic.clear();
  ASSERT_TRUE(renderLevel(Variant::kFixedFast, level, setup, orthographic));
  std::int64_t previous_mismatch = INT64_MAX;
  for (int fov : {60, 30, 10}) {
    PerspectiveView view;
    ASSERT_EQ(orbitPerspective(camera, Angle::fromDegrees(fov), kDefaultFractionBits, &view),
              PerspectiveError::kNone);
    Framebuffer perspective(camera.width, camera.height);
    perspective.clear();
    ASSERT_TRUE(drawPerspective(level, view, perspectiveWalkTables(view, level.depth, 1 << 13),
                                perspective));
    std::int64_t covered = 0, mismatch = 0;
    for (std::int32_t y = 0; y < camera.height; ++y) {
      for (std::int32_t x = 0; x < camera.width; ++x) {
        covered += orthographic.covered(x, y);
        mismatch += orthographic.covered(x, y) != perspective.covered(x, y);
      }
    }
    SCOPED_TRACE(std::to_string(fov) + " degrees");
    EXPECT_LT(mismatch, previous_mismatch);  // narrower is nearer the orthographic picture
    previous_mismatch = mismatch;
    // Depth varies by +-half a cube edge about the centre's distance, f / (zoom * min(W, H))
    // edges, so the picture's scale by about +-tan(fov / 2): the silhouette differs by less than
    // twice that share.
    const double tangent = std::tan(fov * kPi / 360);
    EXPECT_LT(static_cast<double>(mismatch), 2 * tangent * static_cast<double>(covered));
  }
}

// Drawn into a frame, the outside view covers pixels, and the same view drawn twice is the same.
TEST_F(PerspectiveWalkTest, DrawsTheSameFrameTwice) {
  const LevelView& level = model_->finestLevel();
  PerspectiveCamera camera;
  camera.width = 320;
  camera.height = 240;
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  const PerspectiveWalkTables tables = perspectiveWalkTables(view, level.depth, 1 << 13);
  Framebuffer first(320, 240), second(320, 240);
  first.clear();
  second.clear();
  ASSERT_TRUE(drawPerspective(level, view, tables, first));
  ASSERT_TRUE(drawPerspective(level, view, tables, second));
  int covered = 0;
  for (std::int32_t y = 0; y < 240; ++y) {
    for (std::int32_t x = 0; x < 320; ++x) {
      ASSERT_EQ(first.pixelAt(x, y), second.pixelAt(x, y));
      covered += first.covered(x, y);
    }
  }
  EXPECT_GT(covered, 1000);
}

}  // namespace
}  // namespace octopoint
