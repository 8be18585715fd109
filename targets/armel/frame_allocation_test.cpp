// A frame allocates nothing: once the model view, the framebuffer and the RGB buffer exist, a frame
// (camera set-up, clear, decode with any variant, palette to RGB) makes no heap allocation. The
// global operator new of this binary counts every allocation (targets/armel/allocation_counter.h),
// so the test also sees allocations hidden in the standard library. Runs on the host and on the
// device (qemu-arm).
#include <gtest/gtest.h>

#include <vector>

#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "octopoint/render.h"
#include "octopoint/rgb_renderer.h"
#include "octopoint/smooth.h"
#include "octopoint/styles.h"
#include "renderer/level_of_detail.h"
#include "renderer/scene_renderer.h"
#include "targets/armel/allocation_counter.h"
#include "tests/support/dual_resolution_fixture.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

// Proves the counter is live in this binary (static linking included): a vector allocates.
TEST(FrameAllocation, TheCounterSeesAnAllocation) {
  const long before = heapAllocationCount();
  std::vector<int> values(1000, 7);
  asm volatile("" : : "r"(values.data()) : "memory");  // the vector escapes: GCC may not elide it
  const long after = heapAllocationCount();
  EXPECT_EQ(after - before, 1);
}

TEST(FrameAllocation, NoVariantAllocatesDuringAFrame) {
  // Set-up: allowed to allocate.
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  Camera camera;
  Framebuffer frame(camera.width, camera.height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width * camera.height) * 3);
  FrameSetup setup;

  for (const VariantInfo& info : allVariants()) {
    for (int level_index = 0; level_index < model->levelCount(); ++level_index) {
      const LevelView& level = model->level(level_index);
      for (int yaw_degrees : {0, 30}) {
        camera.yaw = Angle::fromDegrees(yaw_degrees);
        // The frame: from the camera to the RGB image.
        const long before = heapAllocationCount();
        const CameraError camera_error =
            buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup);
        frame.clear();
        const bool complete = renderLevel(info.variant, level, setup, frame);
        const bool resolved = resolveToRgb(frame, *model, Rgb{}, rgb);
        const long allocations = heapAllocationCount() - before;

        ASSERT_EQ(camera_error, CameraError::kNone);
        EXPECT_TRUE(complete) << info.name;
        EXPECT_TRUE(resolved);
        EXPECT_EQ(allocations, 0) << info.name << " at depth " << level.depth << ", yaw "
                                  << yaw_degrees << " degrees";
      }
    }
  }
}

// Depth by projected size and footprint splats: choosing the level, building the set-up and
// drawing with splats (zoom 4: a depth-8 voxel is 3.75 pixels wide) allocate nothing either.
TEST(FrameAllocation, DepthAutoAndSplatFramesAllocateNothing) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  Camera camera;
  Framebuffer frame(camera.width, camera.height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width * camera.height) * 3);
  FrameSetup setup;
  int splatting = 0;
  for (const VariantInfo& info : allVariants()) {
    for (const int zoom : {1, 4}) {
      camera.zoom = Q16::fromRaw(zoom * Q16::kOneRaw);
      camera.yaw = Angle::fromDegrees(30);
      const long before = heapAllocationCount();
      const LevelView* level = autoLevel(*model, camera);
      const CameraError camera_error =
          level == nullptr ? CameraError::kOverflow
                           : buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup);
      frame.clear();
      const bool complete =
          camera_error == CameraError::kNone && renderLevel(info.variant, *level, setup, frame);
      const bool resolved = resolveToRgb(frame, *model, Rgb{}, rgb);
      const long allocations = heapAllocationCount() - before;
      ASSERT_EQ(camera_error, CameraError::kNone);
      EXPECT_TRUE(complete) << info.name;
      EXPECT_TRUE(resolved);
      EXPECT_EQ(allocations, 0) << info.name << " at zoom " << zoom;
      splatting += drawsSplats(info.variant) && setup.splat.active() ? 1 : 0;
    }
  }
  EXPECT_GE(splatting, 2);  // the splat path ran
}

// Smooth splats (octopoint/smooth.h): once its buffers exist, a blended frame (set-up, clear,
// box pass, blend, RGB) allocates nothing, whatever the size of its splats.
TEST(FrameAllocation, SmoothFramesAllocateNothing) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  Camera camera;
  Framebuffer frame(camera.width, camera.height);
  SmoothSplats smooth(camera.width, camera.height);
  const PaletteRgb palette = paletteOf(*model);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width * camera.height) * 3);
  FrameSetup setup;
  const LevelView& level = model->finestLevel();
  int blended = 0;
  for (const VariantInfo& info : allVariants()) {
    if (!drawsSplats(info.variant)) continue;
    for (const int zoom : {1, 4, 16}) {
      camera.zoom = Q16::fromRaw(zoom * Q16::kOneRaw);
      camera.yaw = Angle::fromDegrees(30);
      const long before = heapAllocationCount();
      const CameraError camera_error =
          buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup);
      frame.clear();
      const bool complete = camera_error == CameraError::kNone &&
                            renderSmooth(info.variant, level, setup, frame, smooth, palette);
      const bool resolved = smooth.resolveToRgb(frame, palette, Rgb{}, rgb);
      const long allocations = heapAllocationCount() - before;
      ASSERT_EQ(camera_error, CameraError::kNone);
      EXPECT_TRUE(complete) << info.name;
      EXPECT_TRUE(resolved);
      EXPECT_EQ(allocations, 0) << info.name << " at zoom " << zoom;
      blended += setup.splat.active() ? 1 : 0;
    }
  }
  EXPECT_GE(blended, 3);
}

// The interactive renderer's threads after the window was resized and zoomed in (H at depth auto
// with splats, L one depth coarser): once each buffer has been reallocated at the new size (at
// most once each, RendererStatus::buffers_allocated), coarse and fine frames allocate nothing, in
// any thread.
TEST(FrameAllocation, DualResolutionFramesAllocateNothingOnceAResizeSettles) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  ManualClock clock;
  DualResolutionRenderer renderer(*model, clock, InteractiveConfig{});
  dual_resolution_testing::Round round(renderer, clock);
  ViewEvent resize;
  resize.kind = ViewEventKind::kResize;
  resize.width = 400;
  resize.height = 300;
  renderer.handle(resize);
  for (int step = 0; step < 4; ++step) renderer.handle({0, ViewEventKind::kZoomIn});
  constexpr std::uint64_t kBuffers = 6;  // four frames and two hole fillers
  for (int i = 0; i < 20 && renderer.status().buffers_allocated < kBuffers; ++i) round.play();
  ASSERT_EQ(renderer.status().buffers_allocated, kBuffers);

  const long before = heapAllocationCount();
  for (int i = 0; i < 5; ++i) round.play();
  const long allocations = heapAllocationCount() - before;
  ASSERT_FALSE(round.failed());
  EXPECT_GE(renderer.status().coarse_shown, 15u);
  EXPECT_EQ(allocations, 0) << "in 5 turns of the view (15 coarse frames or more, 5 fine ones)";
}

// Walk mode (octopoint-view's Tab): the perspective renderer of each thread makes its occlusion
// tiles at the first frame of a size; then walking allocates nothing.
TEST(FrameAllocation, WalkModeFramesAllocateNothingOnceASizeIsDrawn) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  ManualClock clock;
  InteractiveConfig config;
  config.initial_view.walk = true;
  config.initial_view.walker.eye = {0, -(std::int64_t{1} << 22), -(std::int64_t{1} << 23)};
  DualResolutionRenderer renderer(*model, clock, config);
  dual_resolution_testing::Round round(renderer, clock);  // steps right, then the fine frame
  for (int i = 0; i < 2; ++i) round.play();

  const long before = heapAllocationCount();
  for (int i = 0; i < 5; ++i) round.play();
  const long allocations = heapAllocationCount() - before;
  ASSERT_FALSE(round.failed());
  EXPECT_TRUE(renderer.status().latest.view.walk);
  EXPECT_GE(renderer.status().coarse_shown, 15u);
  EXPECT_EQ(allocations, 0) << "in 5 walks (15 coarse frames or more, 5 fine ones)";
}

// A scene of many models (renderer/scene_renderer.h, docs/city.md): its instances, sort slots and
// indexes are sized when it is made, its occlusion tiles at the first frame of a size; then frames
// from any eye, and instances moved between them, allocate nothing.
TEST(FrameAllocation, SceneFramesAllocateNothingOnceASizeIsDrawn) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  const std::int64_t edge = kPerspectiveUnit;
  std::vector<SceneInstance> instances;
  for (int i = 0; i < 64; ++i) {
    instances.push_back(
        {0, {{(i % 8 - 4) * edge, 0, (i / 8) * edge}, Angle::fromTurns16(i * 999), i % 3 - 1}});
  }
  const ModelView* models[] = {&*model};
  SceneError error;
  SceneRenderer scene(models, instances, &error);
  ASSERT_EQ(error, SceneError::kNone);
  PerspectiveCamera camera;
  camera.eye = {edge / 2, -edge / 4, -3 * edge};
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  ASSERT_TRUE(scene.draw(view, frame));

  SceneDrawStats stats;
  const long before = heapAllocationCount();
  for (int i = 0; i < 4; ++i) {
    camera.eye.z += edge;
    camera.yaw = Angle::fromDegrees(10 * i);
    ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
    ASSERT_EQ(scene.place(static_cast<std::size_t>(i), {{i * edge, 0, 2 * edge}, {}, 0}),
              SceneError::kNone);
    frame.clear();
    ASSERT_TRUE(scene.draw(view, frame, &stats));
  }
  const long allocations = heapAllocationCount() - before;
  EXPECT_GT(stats.instances_drawn, 10u);
  EXPECT_EQ(allocations, 0) << "in 4 frames of 64 instances";
}

// The one-call path (octopoint/rgb_renderer.h) allocates its frame on the first draw and again
// only when the camera's size changes: frame after frame at one size, nothing.
TEST(FrameAllocation, RgbRendererAllocatesOnlyWhenTheSizeChanges) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  Camera camera;
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width * camera.height) * 3);
  RgbRenderer renderer;
  DrawOptions options;
  options.fill_holes = true;
  long before = heapAllocationCount();
  ASSERT_EQ(renderer.draw(*model, camera, rgb, options), DrawError::kNone);
  EXPECT_GT(heapAllocationCount() - before, 0);  // the first draw sizes the frame
  for (int yaw_degrees : {10, 20, 30}) {
    camera.yaw = Angle::fromDegrees(yaw_degrees);
    before = heapAllocationCount();
    ASSERT_EQ(renderer.draw(*model, camera, rgb, options), DrawError::kNone);
    EXPECT_EQ(heapAllocationCount() - before, 0) << "yaw " << yaw_degrees;
  }
}

// A progressive model (octopoint/progressive.h) holding part of a chunked file: asking what
// to fetch, drawing (with and without a point budget), and asking whether the view is complete
// allocate nothing; only taking bytes may.
TEST(FrameAllocation, ProgressiveFramesAllocateNothing) {
  const std::vector<std::uint8_t> image =
      fuzzing::chunkedImage(*models::defaultModel(), {5, 6, 7, 8}, {1024, 1500});
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(
      std::span(image).first(image.size() / 2), nullptr);  // half the file
  ASSERT_TRUE(model.has_value());
  Camera camera;
  Framebuffer frame(camera.width, camera.height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width * camera.height) * 3);
  std::array<FetchItem, 64> wanted{};
  int coarser = 0;
  for (const VariantInfo& info : allVariants()) {
    if (!isFixedPoint(info.variant)) continue;
    for (const int zoom : {1, 4}) {
      camera.zoom = Q16::fromRaw(zoom * Q16::kOneRaw);
      camera.yaw = Angle::fromDegrees(30);
      ProgressiveDrawStats stats;
      const long before = heapAllocationCount();
      const std::size_t count = model->fetchPriority(camera, true, wanted);
      frame.clear();
      const bool drawn = model->draw(camera, info.variant, frame, &stats);
      model->setPointBudget(stats.points / 2);  // some chunks one depth coarser
      ProgressiveDrawStats budget_stats;
      const bool drawn_within_budget = model->draw(camera, info.variant, frame, &budget_stats);
      model->setPointBudget(0);
      const bool complete = model->viewComplete(camera);
      const bool resolved = resolveToRgb(frame, model->baseModel(), Rgb{}, rgb);
      const long allocations = heapAllocationCount() - before;
      EXPECT_TRUE(drawn);
      EXPECT_TRUE(resolved);
      EXPECT_TRUE(drawn_within_budget);
      EXPECT_GT(budget_stats.over_budget_chunks, 0u) << info.name << " at zoom " << zoom;
      EXPECT_FALSE(complete);
      EXPECT_GT(count, 0u);
      EXPECT_EQ(allocations, 0) << info.name << " at zoom " << zoom;
      coarser += stats.coarser_pieces;
    }
  }
  EXPECT_GT(coarser, 0);  // regions were drawn from coarser chunks
}

}  // namespace
}  // namespace octopoint

namespace octopoint {
namespace {

// Every style (octopoint/styles.h): clearing a frame that carries normals, decoding into it,
// the per-frame tables (beginFrame) and the styling pass allocate nothing; the styler's tables are
// members, built when the options are set.
TEST(FrameAllocation, StyledFramesAllocateNothing) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  ASSERT_TRUE(model->hasNormals());
  Camera camera;
  camera.yaw = Angle::fromDegrees(30);
  Framebuffer frame(camera.width, camera.height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width * camera.height) * 3);
  FrameStyler styler(*model);
  const LevelView* level = autoLevel(*model, camera);
  ASSERT_NE(level, nullptr);
  FrameSetup setup;
  for (const StyleInfo& info : allStyles()) {
    StyleOptions options;
    options.style = info.style;
    ASSERT_EQ(styler.setOptions(options), StyleError::kNone) << info.name;
    const long before = heapAllocationCount();
    const CameraError camera_error =
        buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup);
    frame.clear(styler.payload());
    const bool complete = renderLevel(defaultVariant(), *level, setup, frame);
    styler.beginFrame(setup);
    const StyleError style_error = styler.resolve(frame, rgb);
    const long allocations = heapAllocationCount() - before;
    ASSERT_EQ(camera_error, CameraError::kNone);
    EXPECT_TRUE(complete) << info.name;
    EXPECT_EQ(style_error, StyleError::kNone) << info.name;
    EXPECT_EQ(allocations, 0) << info.name;
  }
}

}  // namespace
}  // namespace octopoint
