// Occlusion culling (docs/perspective.md): the coarse depth of tile maxima answers "is every pixel
// of this box nearer than that word" as the frame does; a frame drawn with culling is the frame
// drawn without it, bit for bit, in views from outside and from inside the default model (the eye
// at the table's edge, beside the objects, deep inside), with one depth and with detail by
// distance; and in the views where something is hidden, fewer points are submitted per covered
// pixel.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "renderer/occlusion_tiles.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace {

TEST(OcclusionTiles, HiddenWhereEveryPixelOfTheBoxIsNearerThanTheWord) {
  // 21 x 13 pixels: tiles of 8 x 8, the last column and row of tiles partial.
  Framebuffer frame(21, 13);
  frame.clear();
  std::vector<OcclusionTile> storage(occlusionTileCount(21, 13, 3));
  ASSERT_EQ(storage.size(), 3u * 2u);
  OcclusionTiles tiles(frame, storage, 3);
  tiles.reset();
  EXPECT_FALSE(tiles.hidden(0, 20, 0, 12, FrameView::pack(1, 0)));  // all empty
  // Cover the frame at depth key 100, but one pixel at 300.
  for (std::int32_t y = 0; y < 13; ++y) {
    for (std::int32_t x = 0; x < 21; ++x) frame.plot(x, y, x == 20 && y == 12 ? 300 : 100, 7);
  }
  // Stale tiles are not scanned until marked: the recorded maxima are still "empty".
  EXPECT_FALSE(tiles.hidden(0, 7, 0, 7, FrameView::pack(200, 0)));
  tiles.touched(0, 20, 0, 12);
  EXPECT_TRUE(tiles.hidden(0, 7, 0, 7, FrameView::pack(200, 0)));
  EXPECT_FALSE(tiles.hidden(0, 7, 0, 7, FrameView::pack(100, 0)));  // a tie is not hidden
  EXPECT_TRUE(tiles.hidden(0, 7, 0, 7, FrameView::pack(100, 8)));   // a larger word is
  // The partial corner tile holds the far pixel: a box reaching into it is not hidden at 200.
  EXPECT_TRUE(tiles.hidden(0, 15, 0, 12, FrameView::pack(200, 0)));
  EXPECT_FALSE(tiles.hidden(16, 16, 8, 8, FrameView::pack(200, 0)));
  EXPECT_TRUE(tiles.hidden(16, 16, 8, 8, FrameView::pack(301, 0)));
  // Drawn nearer and marked: found again.
  frame.plot(20, 12, 50, 7);
  tiles.touched(20, 20, 12, 12);
  EXPECT_TRUE(tiles.hidden(0, 20, 0, 12, FrameView::pack(200, 0)));
  // Reset (a frame cleared): nothing hidden.
  frame.clear();
  tiles.reset();
  EXPECT_FALSE(tiles.hidden(0, 0, 0, 0, FrameView::pack(FrameView::kMaxDepthKey, 0)));
}

struct CullView {
  std::string name;
  PerspectiveCamera camera;
  bool hides;  // a view in which culling finds something hidden
};

std::vector<CullView> cullViews() {
  const std::int64_t u = kPerspectiveUnit;
  std::vector<CullView> views;
  const auto add = [&](std::string name, ModelPoint eye, int yaw, int pitch, int fov, int width,
                       int height, bool hides) {
    views.push_back(
        {std::move(name), perspectiveCameraOf(eye, yaw, pitch, fov, width, height), hides});
  };
  add("outside", {0, 0, -2 * u}, 0, 0, 60, 320, 240, false);
  add("outside, turned", {u, -u / 2, -u}, -45, -20, 90, 320, 240, false);
  add("at the table's edge", {0, 28 * u / 100, -46 * u / 100}, 0, 28, 90, 320, 240, true);
  add("at the table's edge, 1280x960", {0, 28 * u / 100, -46 * u / 100}, 0, 28, 90, 1280, 960,
      true);
  add("beside the objects", {-u / 4, u / 5, -35 * u / 100}, 0, 25, 60, 320, 240, true);
  add("across the table, looking back", {3 * u / 10, u / 10, 45 * u / 100}, 180, 25, 90, 640, 480,
      true);
  add("deep inside", {u / 16, u / 8, 0}, 170, 30, 120, 320, 240, true);
  return views;
}

struct CulledPair {
  Framebuffer culled, plain;
  PerspectiveDrawStats culled_stats, plain_stats;
};

CulledPair drawWithAndWithoutCulling(const PerspectiveCamera& camera, int depth,
                                     int tile_shift = kOcclusionTileShift) {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  PerspectiveRenderer renderer(model);
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  CulledPair pair{
      Framebuffer(camera.width, camera.height), Framebuffer(camera.width, camera.height), {}, {}};
  pair.culled.clear();
  pair.plain.clear();
  PerspectiveRenderer::Options options;
  options.depth = depth;
  options.cull = true;
  options.tile_shift = tile_shift;
  EXPECT_TRUE(renderer.draw(view, options, pair.culled, &pair.culled_stats));
  options.cull = false;
  EXPECT_TRUE(renderer.draw(view, options, pair.plain, &pair.plain_stats));
  return pair;
}

// With tiles of 8 x 8 pixels, and of 2 x 2 (which test the bounds of what a subtree may write
// closely: a coarser tile's maximum hides a bound a pixel short).
TEST(PerspectiveCulling, FrameIsTheUnculledFrameBitForBit) {
  for (const CullView& v : cullViews()) {
    for (const int depth : {0, 8}) {  // detail by distance, and depth 8 alone
      for (const int tile_shift : {3, 1}) {
        SCOPED_TRACE(v.name + (depth == 0 ? ", by distance" : ", depth 8") + ", tiles of " +
                     std::to_string(1 << tile_shift));
        const CulledPair pair = drawWithAndWithoutCulling(v.camera, depth, tile_shift);
        std::int64_t different = 0, covered = 0;
        for (std::int32_t y = 0; y < v.camera.height; ++y) {
          for (std::int32_t x = 0; x < v.camera.width; ++x) {
            different += pair.culled.pixelAt(x, y) != pair.plain.pixelAt(x, y);
            covered += pair.plain.covered(x, y);
          }
        }
        EXPECT_EQ(different, 0);
        EXPECT_GT(covered, 1000);
        EXPECT_EQ(pair.plain_stats.hidden_subtrees, 0u);
        if (v.hides) {
          EXPECT_GT(pair.culled_stats.hidden_subtrees, 10u);
          EXPECT_LT(pair.culled_stats.leaves, pair.plain_stats.leaves);
        } else {
          EXPECT_LE(pair.culled_stats.leaves, pair.plain_stats.leaves);
        }
      }
    }
  }
}

// Points submitted per covered pixel, with and without culling, where the eye stands beside the
// objects on the table: the counter the benchmark reports. A fifth of the points are culled.
TEST(PerspectiveCulling, CullingSubmitsFewerPointsPerCoveredPixel) {
  const CullView v = cullViews()[4];
  ASSERT_EQ(v.name, "beside the objects");
  const CulledPair pair = drawWithAndWithoutCulling(v.camera, 0);
  std::uint64_t covered = 0;
  for (std::int32_t y = 0; y < v.camera.height; ++y) {
    for (std::int32_t x = 0; x < v.camera.width; ++x) covered += pair.plain.covered(x, y);
  }
  ASSERT_GT(covered, 0u);
  const std::uint64_t culled = pair.culled_stats.leaves, plain = pair.plain_stats.leaves;
  EXPECT_LT(culled * 100, plain * 85)
      << culled << " against " << plain << " on " << covered << " covered pixels";
}

}  // namespace
}  // namespace octopoint

namespace octopoint {
namespace {

// The pan moves the principal point: the frustum's sides are then asymmetric, and a subtree that
// the pan brings onto the screen must not be passed over as outside it. A 320-wide orbit view
// panned 150 pixels either way is the matching 320 columns of the 620-wide view, bit for bit.
TEST(PerspectiveFrustum, APannedFrameIsTheCropOfAWiderOne) {
  ModelIssue issue;
  const ModelView model = *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  PerspectiveRenderer renderer(model);
  const auto draw = [&](std::int32_t width, std::int32_t pan_x) {
    Camera camera;
    camera.width = width;
    camera.height = 240;
    camera.pan_x_px = pan_x;
    PerspectiveView view;
    EXPECT_EQ(orbitPerspective(camera, Angle::fromDegrees(60), kDefaultFractionBits, &view),
              PerspectiveError::kNone);
    Framebuffer frame(width, 240);
    frame.clear();
    EXPECT_TRUE(renderer.draw(view, {}, frame, nullptr));
    return frame;
  };
  const Framebuffer wide = draw(620, 0);
  for (const std::int32_t pan : {150, -150}) {
    const Framebuffer panned = draw(320, pan);
    const std::int32_t first = pan > 0 ? 0 : 300;  // the wide frame's column of panned column 0
    std::int64_t differing = 0, drawn = 0;
    for (std::int32_t y = 0; y < 240; ++y) {
      for (std::int32_t x = 0; x < 320; ++x) {
        differing += panned.pixelAt(x, y) != wide.pixelAt(first + x, y);
        drawn += panned.pixelAt(x, y) != Framebuffer::kEmpty;
      }
    }
    EXPECT_EQ(differing, 0) << "pan " << pan;
    EXPECT_GT(drawn, 10000) << "pan " << pan;
  }
}

}  // namespace
}  // namespace octopoint
