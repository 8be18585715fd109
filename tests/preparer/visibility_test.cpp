// Visibility pruning against the real renderer: pruned and unpruned models of the same scan are
// prepared, serialized, validated and drawn, and their frames compared.
#include "codegen/visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "codegen/cube_fit.h"
#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "codegen/scene_views.h"
#include "codegen/voxelizer.h"
#include "octopoint/framebuffer.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"
#include "renderer/smooth_reach.h"
#include "tests/support/airborne_scans.h"
#include "tests/support/synthetic_scans.h"

namespace octopoint {
namespace {

// Depth 7 (128 voxels per cube edge) on a 160x120 frame at zoom 0.5..1: the cube spans 60..120
// pixels, so a voxel covers at most one pixel, as "depths": "auto" would choose. (At a larger zoom
// the decoder's one pixel per leaf leaves gaps in a surface, and voxels behind it win there.)
constexpr int kVisibilityDepth = 7;
constexpr int kWidth = 160;
constexpr int kHeight = 120;

// The frontal scene of docs/scenes/tabletop_frontal.json: yaw +-30 degrees, pitch +-20 degrees.
prepare::Scene frontalScene() {
  prepare::Scene scene;
  scene.yaw_deg = prepare::Range{-30, 30};
  scene.pitch_deg = prepare::Range{-20, 20};
  scene.zoom = {0.5, 1};
  scene.width = kWidth;
  scene.height = kHeight;
  return scene;
}

struct ModelPair {
  std::vector<std::uint8_t> unpruned_image;
  std::vector<std::uint8_t> pruned_image;
  ModelView unpruned() const { return *ModelView::fromBytes(unpruned_image, nullptr); }
  ModelView pruned() const { return *ModelView::fromBytes(pruned_image, nullptr); }
};

ModelPair prepareBoth(const prepare::Scan& scan, const std::vector<Camera>& cameras) {
  prepare::PrepareOptions options;
  options.name = "scene_test";
  options.depths = {kVisibilityDepth};
  ModelPair pair;
  pair.unpruned_image = prepare::serializeModel(prepare::prepareModel(scan, "scan.pcd", options));
  options.visibility_cameras = cameras;
  pair.pruned_image = prepare::serializeModel(prepare::prepareModel(scan, "scan.pcd", options));
  return pair;
}

Framebuffer draw(const ModelView& model, const Camera& camera,
                 Variant variant = Variant::kFixedBaseline) {
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, kVisibilityDepth, kDefaultFractionBits, &setup),
            CameraError::kNone);
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  EXPECT_TRUE(renderLevel(variant, model.finestLevel(), setup, frame));
  return frame;
}

struct Comparison {
  std::size_t object_pixels = 0;  // covered in the unpruned frame
  std::size_t differing = 0;      // of those, drawn differently (or not at all) by the pruned model
  std::size_t extra = 0;          // covered only in the pruned frame (must never happen)
};

Comparison compare(const ModelPair& pair, const Camera& camera,
                   Variant variant = Variant::kFixedBaseline) {
  const Framebuffer expected = draw(pair.unpruned(), camera, variant);
  const Framebuffer actual = draw(pair.pruned(), camera, variant);
  Comparison result;
  for (std::size_t i = 0; i < expected.pixels().size(); ++i) {
    const bool covered = expected.pixels()[i] != Framebuffer::kEmpty;
    const bool pruned_covered = actual.pixels()[i] != Framebuffer::kEmpty;
    if (!covered) {
      result.extra += pruned_covered;
      continue;
    }
    ++result.object_pixels;
    result.differing += expected.pixels()[i] != actual.pixels()[i];  // depth key and colour
  }
  return result;
}

TEST(VisibilityPruning, EverySampledViewDrawsPixelIdenticalToTheUnprunedModel) {
  prepare::Scene scene = frontalScene();
  scene.angle_step_deg = 10;  // few views: the identity holds for any sample, this keeps it quick
  const std::vector<Camera> cameras = prepare::sceneCameras(scene);
  ASSERT_EQ(cameras.size(), 7u * 5u * 5u);  // yaw 7, pitch 5, zoom 0.5 .. 1 in 4 steps of 1.19
  const ModelPair pair = prepareBoth(testing::faceLikeHeightField(300), cameras);
  ASSERT_LT(pair.pruned_image.size(), pair.unpruned_image.size());
  for (const Camera& camera : cameras) {
    const Comparison result = compare(pair, camera);
    ASSERT_GT(result.object_pixels, 500u);
    ASSERT_EQ(result.differing, 0u)
        << "yaw " << camera.yaw.turns16() << " pitch " << camera.pitch.turns16();
    ASSERT_EQ(result.extra, 0u);
  }
}

// The frontal scene zoomed in to 2..3, every 15 degrees: a depth-7 voxel covers 2 to 3 pixels.
std::vector<Camera> zoomedInCameras() {
  prepare::Scene scene = frontalScene();
  scene.angle_step_deg = 15;
  scene.zoom = {2, 3};
  return prepare::sceneCameras(scene);
}

// Zoomed in, a depth-7 voxel covers 2 to 3 pixels: the pruned model drawn with footprint splats
// (the default variant) is still the unpruned model's frame at every sampled view, so it is as
// hole-free; drawn one pixel per leaf (fixed_baseline), too.
TEST(VisibilityPruning, ZoomedInSampledViewsDrawTheUnprunedFrameWithSplatsAndWithout) {
  const std::vector<Camera> cameras = zoomedInCameras();
  const ModelPair pair = prepareBoth(testing::faceLikeHeightField(300), cameras);
  ASSERT_LT(pair.pruned_image.size(), pair.unpruned_image.size());
  for (const Variant variant : {defaultVariant(), Variant::kFixedBaseline}) {
    for (const Camera& camera : cameras) {
      FrameSetup setup;
      ASSERT_EQ(buildFrameSetup(camera, kVisibilityDepth, kDefaultFractionBits, &setup),
                CameraError::kNone);
      ASSERT_TRUE(setup.splat.active());
      const Comparison result = compare(pair, camera, variant);
      ASSERT_GT(result.object_pixels, 500u);
      ASSERT_EQ(result.differing, 0u)
          << "variant " << static_cast<int>(variant) << " yaw " << camera.yaw.turns16();
      ASSERT_EQ(result.extra, 0u);
    }
  }
}

// Smooth splats (octopoint/smooth.h) blend every leaf within a kernel's reach and the depth
// tolerance of a pixel's nearest surface, winner or not: the pruned model keeps those too, so its
// smooth frame at every sampled view is the unpruned model's, colour for colour. Judged by the box
// frame's winners alone it was not (the leaves just behind the surface's front were pruned).
TEST(VisibilityPruning, ZoomedInSampledViewsDrawTheUnprunedSmoothFrame) {
  const std::vector<Camera> cameras = zoomedInCameras();
  const ModelPair pair = prepareBoth(testing::faceLikeHeightField(300), cameras);
  ASSERT_LT(pair.pruned_image.size(), pair.unpruned_image.size());
  const auto smooth_rgb = [](const ModelView& model, const Camera& camera) {
    FrameSetup setup;
    EXPECT_EQ(buildFrameSetup(camera, kVisibilityDepth, kDefaultFractionBits, &setup),
              CameraError::kNone);
    Framebuffer frame(camera.width, camera.height);
    frame.clear();
    SmoothSplats smooth(setup);
    const PaletteRgb palette = paletteOf(model);
    EXPECT_TRUE(renderSmooth(defaultVariant(), model.finestLevel(), setup, frame, smooth, palette));
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width) *
                                  static_cast<std::size_t>(camera.height) * 3);
    EXPECT_TRUE(smooth.resolveToRgb(frame, palette, Rgb{0, 0, 0}, rgb));
    return rgb;
  };
  std::size_t blended_views = 0;
  for (const Camera& camera : cameras) {
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, kVisibilityDepth, kDefaultFractionBits, &setup),
              CameraError::kNone);
    blended_views += smoothReachOf(setup).blends;
    const std::vector<std::uint8_t> expected = smooth_rgb(pair.unpruned(), camera);
    const std::vector<std::uint8_t> actual = smooth_rgb(pair.pruned(), camera);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < expected.size(); i += 3)
      differing += expected[i] != actual[i] || expected[i + 1] != actual[i + 1] ||
                   expected[i + 2] != actual[i + 2];
    EXPECT_EQ(differing, 0u) << "yaw " << camera.yaw.turns16() << " pitch "
                             << camera.pitch.turns16() << " zoom " << camera.zoom.raw();
  }
  EXPECT_EQ(blended_views, cameras.size());  // every view magnifies: each one blends
}

// The airborne grid scan (tests/support/airborne_scans.h: 1 m samples on scan lines, roofs of 4
// to 12 m) at depths 6 to 9, sampled more coarsely than the 0.88 and 0.44 m voxels of depths 8 and
// 9: the renderer widens their splats by the stored reach (2 and 3 footprints). Pruned for views
// across the roofs (the identity camera looks straight down on the ground), every level drawn at
// every sampled view with those splats is the unpruned level's frame. Judged with one-footprint
// splats it was not (wider splats show leaves the narrow ones leave hidden): 459 pixels differed
// in 10 of the 60 views at depth 8, 199 in 8 at depth 9.
TEST(VisibilityPruning, AScanCoarserThanItsVoxelsDrawsTheUnprunedFramesWithItsWidenedSplats) {
  prepare::Scene scene;
  scene.yaw_deg = prepare::Range{-30, 30};
  scene.pitch_deg = prepare::Range{-40, 40};
  scene.zoom = {2, 3};
  scene.angle_step_deg = 20;
  const std::vector<Camera> cameras = prepare::sceneCameras(scene);
  prepare::PrepareOptions options;
  options.name = "airborne";
  options.depths = {6, 7, 8, 9};
  const prepare::Scan scan = testing::airborneScan(testing::AirborneSampling::kGrid, 1.0, 7);
  const std::vector<std::uint8_t> unpruned_image =
      prepare::serializeModel(prepare::prepareModel(scan, "airborne.ply", options));
  options.visibility_cameras = cameras;
  const std::vector<std::uint8_t> pruned_image =
      prepare::serializeModel(prepare::prepareModel(scan, "airborne.ply", options));
  const ModelView unpruned = *ModelView::fromBytes(unpruned_image, nullptr);
  const ModelView pruned = *ModelView::fromBytes(pruned_image, nullptr);
  ASSERT_EQ(unpruned.levelCount(), 4);
  ASSERT_EQ(pruned.levelCount(), 4);
  EXPECT_GT(unpruned.sampleReach(3), kOneSampleReach);
  std::printf("%zu views, %zu -> %zu bytes\n", cameras.size(), unpruned_image.size(),
              pruned_image.size());
  EXPECT_LT(pruned_image.size(), unpruned_image.size());
  const auto draw_level = [](const ModelView& model, int i, const Camera& camera) {
    FrameSetup setup;
    EXPECT_EQ(buildFrameSetup(camera, model.level(i).depth, kDefaultFractionBits, &setup,
                              model.sampleReach(i)),
              CameraError::kNone);
    Framebuffer frame(camera.width, camera.height);
    frame.clear();
    EXPECT_TRUE(renderLevel(defaultVariant(), model.level(i), setup, frame));
    return frame;
  };
  for (int i = 0; i < unpruned.levelCount(); ++i) {
    EXPECT_EQ(pruned.sampleReach(i), unpruned.sampleReach(i));
    std::size_t differ = 0, views_differing = 0;
    for (const Camera& camera : cameras) {
      const Framebuffer expected = draw_level(unpruned, i, camera);
      const Framebuffer actual = draw_level(pruned, i, camera);
      std::size_t here = 0;
      for (std::size_t p = 0; p < expected.pixels().size(); ++p)
        here += expected.pixels()[p] != actual.pixels()[p];
      differ += here;
      views_differing += here != 0;
    }
    std::printf("depth %d (reach %d/16): %zu -> %zu voxels, %zu pixels differ in %zu views\n",
                unpruned.level(i).depth, unpruned.sampleReach(i), unpruned.level(i).leaves.size(),
                pruned.level(i).leaves.size(), differ, views_differing);
    EXPECT_EQ(differ, 0u) << "depth " << unpruned.level(i).depth;
  }
}

// Random views inside the scene's range, off the sampling grid (angles to the millidegree, any
// zoom in range): at least 99.5% of the object's pixels must be drawn exactly as before.
void expectRandomViewsNearlyIdentical(const prepare::Scan& scan) {
  const prepare::Scene scene = frontalScene();
  const ModelPair pair = prepareBoth(scan, prepare::sceneCameras(scene));
  ASSERT_LT(pair.pruned_image.size(), pair.unpruned_image.size());
  std::mt19937 random(4);
  std::uniform_real_distribution<double> yaw(-30, 30), pitch(-20, 20), log_zoom(0, std::log(2.0));
  Comparison total;
  for (int view = 0; view < 200; ++view) {
    const Camera camera = prepare::cameraFor(yaw(random), pitch(random), 0,
                                             0.5 * std::exp(log_zoom(random)), kWidth, kHeight);
    const Comparison result = compare(pair, camera);
    total.object_pixels += result.object_pixels;
    total.differing += result.differing;
    total.extra += result.extra;
  }
  const double identical =
      1.0 - static_cast<double>(total.differing) / static_cast<double>(total.object_pixels);
  std::printf(
      "identical object pixels over 200 random views: %.4f%% (%zu of %zu differ), size %zu -> %zu "
      "bytes\n",
      100 * identical, total.differing, total.object_pixels, pair.unpruned_image.size(),
      pair.pruned_image.size());
  EXPECT_GE(identical, 0.995);
  EXPECT_EQ(total.extra, 0u);
}

TEST(VisibilityPruning, RandomViewsInsideTheRangeKeepAtLeast995PermilleOfPixelsOnAClosedSphere) {
  expectRandomViewsNearlyIdentical(testing::colouredSphere(1000000));
}

TEST(VisibilityPruning, RandomViewsInsideTheRangeKeepAtLeast995PermilleOfPixelsOnAFace) {
  expectRandomViewsNearlyIdentical(testing::faceLikeHeightField(300));
}

TEST(VisibilityPruning, AFrontalOnlySceneRemovesTheBackOfAClosedSphereEntirely) {
  // A million points: about 20 per surface voxel, so the shell has no holes to see the back
  // through.
  const prepare::Scan sphere = testing::colouredSphere(1000000);
  const prepare::CubeFit fit = prepare::fitCube(sphere.positions, "sphere.pcd");
  const prepare::VoxelSet voxels = prepare::voxelize(sphere, fit, kVisibilityDepth);
  prepare::Scene scene = frontalScene();
  scene.yaw_deg = prepare::Range{0, 0};
  scene.pitch_deg = prepare::Range{0, 0};
  const std::vector<std::uint8_t> visible =
      prepare::visibleVoxels(voxels.keys, kVisibilityDepth, prepare::sceneCameras(scene));
  constexpr std::uint32_t kCentre =
      1u << (kVisibilityDepth - 1);  // z index of the cube's middle plane
  std::size_t kept = 0, back = 0, back_kept = 0;
  for (std::size_t i = 0; i < voxels.keys.size(); ++i) {
    const std::uint32_t z =
        prepare::mortonDecode(voxels.keys[i], kVisibilityDepth)[2];  // away from the viewer
    const bool is_back =
        z >= kCentre + 2;  // behind the silhouette's rim, which straddles the middle
    back += is_back;
    kept += visible[i];
    back_kept += is_back && visible[i];
  }
  EXPECT_GT(back, voxels.keys.size() / 3);
  EXPECT_EQ(back_kept, 0u);
  // The front is kept: about half its voxels win a pixel head-on (it projects to half its area).
  EXPECT_GT(kept, voxels.keys.size() / 6);
}

}  // namespace
}  // namespace octopoint
