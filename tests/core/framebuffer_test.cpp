// The frame's drawn rectangle (octopoint/framebuffer.h): clear() empties only drawnRect(), so every
// writer must write inside the rectangle it declared, and a frame reused from one view to the next
// must still hold exactly what a fresh frame would.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

const ModelView& model() {
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return view;
}

// Cameras from far zoomed out to far zoomed in, turned, panned off every edge.
std::vector<Camera> camerasOf(int width, int height, int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> angle(-180, 180);
  std::uniform_int_distribution<int> zoom_eighths(1, 40);
  std::uniform_int_distribution<int> pan(-width, width);
  std::vector<Camera> cameras;
  for (int i = 0; i < count; ++i) {
    Camera camera;
    camera.width = width;
    camera.height = height;
    camera.yaw = Angle::fromDegrees(angle(random));
    camera.pitch = Angle::fromDegrees(angle(random) / 2);
    camera.zoom = Q16::fromRaw(zoom_eighths(random) * (Q16::kOneRaw / 8));
    camera.pan_x_px = i % 2 == 0 ? pan(random) : 0;
    camera.pan_y_px = i % 2 == 0 ? pan(random) / 2 : 0;
    cameras.push_back(camera);
  }
  return cameras;
}

bool inside(const PixelRect& rect, std::int32_t x, std::int32_t y) {
  return x >= rect.x_begin && x < rect.x_end && y >= rect.y_begin && y < rect.y_end;
}

// Every pixel a variant covers lies in the rectangle its plotter declared, with and without
// splats, for every stored depth.
TEST(DrawnRect, EveryVariantWritesOnlyInsideTheRectangleItDeclares) {
  int checked = 0;
  for (const Camera& camera : camerasOf(150, 110, 40, 11)) {
    for (int i = 0; i < model().levelCount(); ++i) {
      const LevelView& level = model().level(i);
      FrameSetup setup;
      if (buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup) != CameraError::kNone)
        continue;
      for (const VariantInfo& info : allVariants()) {
        Framebuffer frame(camera.width, camera.height);
        ASSERT_TRUE(frame.drawnRect().empty());
        ASSERT_TRUE(renderLevel(info.variant, level, setup, frame));
        const PixelRect rect = frame.drawnRect();
        for (std::int32_t y = 0; y < frame.height(); ++y) {
          for (std::int32_t x = 0; x < frame.width(); ++x) {
            ASSERT_TRUE(!frame.covered(x, y) || inside(rect, x, y))
                << info.name << " depth " << level.depth << " wrote (" << x << ", " << y
                << ") outside [" << rect.x_begin << ", " << rect.x_end << ") x [" << rect.y_begin
                << ", " << rect.y_end << ")";
          }
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 400);
}

// One frame drawn into again and again (zoomed in over the whole frame, then zoomed out to a
// corner, hole filling on every other view) holds what a fresh frame holds after each view.
TEST(DrawnRect, AReusedFrameHoldsWhatAFreshFrameHolds) {
  Framebuffer reused(200, 150);
  HoleFiller reused_filler(200);
  HoleFiller fresh_filler(200);
  int view = 0;
  for (const Camera& camera : camerasOf(200, 150, 60, 12)) {
    const LevelView* level = autoLevel(model(), camera);
    ASSERT_NE(level, nullptr);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup),
              CameraError::kNone);
    const bool fill = view % 2 == 1;
    Framebuffer fresh(200, 150);
    ASSERT_TRUE(renderLevel(defaultVariant(), *level, setup, fresh));
    if (fill) {
      ASSERT_FALSE(fresh_filler.fill(fresh, bridgeDepthLimit(setup)).refused);
    }
    reused.clear();
    ASSERT_TRUE(std::ranges::all_of(reused.pixels(),
                                    [](std::uint32_t word) { return word == Framebuffer::kEmpty; }))
        << "view " << view << ": clear left pixels of the previous view";
    ASSERT_TRUE(renderLevel(defaultVariant(), *level, setup, reused));
    if (fill) {
      ASSERT_FALSE(reused_filler.fill(reused, bridgeDepthLimit(setup)).refused);
    }
    ASSERT_TRUE(std::ranges::equal(reused.pixels(), fresh.pixels())) << "view " << view;
    ++view;
  }
}

TEST(DrawnRect, PlotAndRawAccessWidenIt) {
  Framebuffer frame(40, 30);
  EXPECT_TRUE(frame.drawnRect().empty());
  frame.plot(5, 7, 100, 1);
  frame.plot(50, 7, 100, 1);  // off the frame: dropped, no widening
  EXPECT_EQ(frame.drawnRect().x_begin, 5);
  EXPECT_EQ(frame.drawnRect().x_end, 6);
  EXPECT_EQ(frame.drawnRect().y_begin, 7);
  EXPECT_EQ(frame.drawnRect().y_end, 8);
  frame.pixelsToDraw({-10, 3, 20, 99});  // clipped to the frame
  EXPECT_EQ(frame.drawnRect().x_begin, 0);
  EXPECT_EQ(frame.drawnRect().y_end, 30);
  frame.clear();
  EXPECT_TRUE(frame.drawnRect().empty());
  EXPECT_FALSE(frame.covered(5, 7));
  // Raw access without bounds: anything may be written, so the next clear empties everything.
  std::uint32_t* pixel = frame.pixelData();
  pixel[39 + 29 * 40] = Framebuffer::pack(5, 5);
  EXPECT_EQ(frame.drawnRect().x_end, 40);
  frame.clear();
  EXPECT_TRUE(std::ranges::all_of(frame.pixels(),
                                  [](std::uint32_t word) { return word == Framebuffer::kEmpty; }));
}

// What the rectangle is for: a model zoomed out on a large frame declares about its own screen
// area, so clearing costs that, not the frame (docs/splats.md#cost).
TEST(DrawnRect, ZoomedOutModelDeclaresAboutItsOwnArea) {
  Camera camera;
  camera.width = 1920;
  camera.height = 1080;
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = Q16::fromRaw(Q16::kOneRaw / 4);
  const LevelView* level = autoLevel(model(), camera);
  ASSERT_NE(level, nullptr);
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup),
            CameraError::kNone);
  Framebuffer frame(camera.width, camera.height);
  ASSERT_TRUE(renderLevel(defaultVariant(), *level, setup, frame));
  const PixelRect rect = frame.drawnRect();
  const std::int64_t area = std::int64_t{rect.x_end - rect.x_begin} * (rect.y_end - rect.y_begin);
  // The cube's edge is 270 pixels; turned 30 degrees its box is about 369 x 270 (+ the splat).
  EXPECT_LE(area, 380 * 280);
  EXPECT_GE(area, 360 * 268);
}

}  // namespace
}  // namespace octopoint
