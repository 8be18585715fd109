// Smooth splats (octopoint/smooth.h): the box frame bit for bit where voxels are at most a pixel;
// the same frame whatever order the leaves arrive in; a magnified sphere's silhouette covered
// (empty share at most 1%) and its outline within half a voxel of the exact disc; fixed_fast and
// fixed_simd blend the same frames; frames with fixed checksums, which the armel build (qemu-arm)
// checks too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"
#include "renderer/crc32.h"
#include "tests/support/synthetic_levels.h"

namespace octopoint {
namespace {

using testing_support::SyntheticLevel;

constexpr double kSmoothSphereRadius = 0.35;  // cube units
constexpr Rgb kSmoothBackground{236, 236, 240};

Camera smoothCamera(int width, int height, double zoom, int yaw, int pitch = 0) {
  return testing_support::viewOf(width, height, zoom, yaw, pitch);
}

FrameSetup smoothSetup(const Camera& camera, int depth) {
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, depth, kDefaultFractionBits, &setup), CameraError::kNone);
  return setup;
}

// A palette whose neighbouring indices differ: blending shows.
PaletteRgb spreadPalette() {
  PaletteRgb palette{};
  for (std::size_t i = 0; i < palette.size(); ++i) {
    palette[i] = {static_cast<std::uint8_t>(i * 37), static_cast<std::uint8_t>(i * 91 + 40),
                  static_cast<std::uint8_t>(255 - i * 13)};
  }
  return palette;
}

struct SmoothFrame {
  Framebuffer frame;
  std::vector<std::uint8_t> rgb;
};

SmoothFrame drawSmooth(Variant variant, const LevelView& level, const FrameSetup& setup,
                       const PaletteRgb& palette) {
  SmoothFrame out{
      Framebuffer(setup),
      std::vector<std::uint8_t>(static_cast<std::size_t>(setup.width * setup.height) * 3)};
  SmoothSplats smooth(setup);
  out.frame.clear();
  EXPECT_TRUE(renderSmooth(variant, level, setup, out.frame, smooth, palette));
  EXPECT_TRUE(smooth.resolveToRgb(out.frame, palette, kSmoothBackground, out.rgb));
  return out;
}

std::vector<Variant> splatVariants() {
  std::vector<Variant> variants{Variant::kFixedFast};
  if (simdDecoderAvailable()) variants.push_back(Variant::kFixedSimd);
  return variants;
}

const ModelView& defaultModelView() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

TEST(SmoothSplats, FrameIsTheBoxFrameWhereVoxelsAreAtMostAPixel) {
  const ModelView& model = defaultModelView();
  const PaletteRgb palette = paletteOf(model);
  const LevelView& level = *model.levelOfDepth(8);
  int cases = 0;
  int turned = 0;  // footprints wider than a pixel, edges at most a pixel
  for (const Camera& camera : {smoothCamera(320, 240, 1, 0), smoothCamera(320, 240, 0.5, 30),
                               smoothCamera(176, 208, 1, 0, 20), smoothCamera(256, 256, 1, 90),
                               smoothCamera(320, 240, 1, 30, 10), smoothCamera(256, 256, 1, 45)}) {
    const FrameSetup setup = smoothSetup(camera, level.depth);
    ASSERT_LE(voxelEdgeOnScreen(setup), std::uint64_t{1} << setup.fraction_bits);
    turned += setup.splat.active() ? 1 : 0;
    for (const Variant variant : splatVariants()) {
      Framebuffer box(setup);
      box.clear();
      ASSERT_TRUE(renderLevel(variant, level, setup, box));
      std::vector<std::uint8_t> box_rgb(static_cast<std::size_t>(setup.width * setup.height) * 3);
      ASSERT_TRUE(resolveToRgb(box, model, kSmoothBackground, box_rgb));
      const SmoothFrame smooth = drawSmooth(variant, level, setup, palette);
      EXPECT_TRUE(std::ranges::equal(smooth.frame.pixels(), box.pixels()));
      EXPECT_EQ(smooth.rgb, box_rgb);
      ++cases;
    }
  }
  EXPECT_GE(cases, 6);
  EXPECT_EQ(turned, 2);
}

// The sphere's voxels in three random parts, each its own level: drawn into one frame (box pass
// of every part, then each part accumulated), in every order of the parts and with the leaves
// shuffled among them anew, the frame and its colours are the whole level's.
TEST(SmoothSplats, FrameDoesNotDependOnTheOrderLeavesArriveIn) {
  constexpr int kDepth = 5;
  const std::vector<std::uint64_t> keys = testing_support::sphereKeys(kSmoothSphereRadius, kDepth);
  const SyntheticLevel whole =
      testing_support::encodeLevel(keys, kDepth, testing_support::colourOf);
  const PaletteRgb palette = spreadPalette();
  std::mt19937 random(31);
  for (const Camera& camera : {smoothCamera(320, 240, 2, 30, 20), smoothCamera(200, 150, 1, 0)}) {
    const FrameSetup setup = smoothSetup(camera, kDepth);
    ASSERT_TRUE(setup.splat.active());
    const SmoothFrame expected = drawSmooth(Variant::kFixedFast, whole.view(), setup, palette);
    for (int round = 0; round < 3; ++round) {
      std::vector<std::vector<std::uint64_t>> parts(3);
      for (const std::uint64_t key : keys) parts[random() % 3].push_back(key);
      std::vector<SyntheticLevel> levels;
      for (const auto& part : parts) {
        levels.push_back(testing_support::encodeLevel(part, kDepth, testing_support::colourOf));
      }
      std::vector<int> order{0, 1, 2};
      do {
        Framebuffer frame(setup);
        frame.clear();
        for (const int i : order)
          ASSERT_TRUE(renderLevel(Variant::kFixedFast, levels[i].view(), setup, frame));
        SmoothSplats smooth(setup);
        ASSERT_TRUE(smooth.begin(setup, frame));
        for (const int i : order) {
          ASSERT_TRUE(
              smooth.accumulate(levels[static_cast<std::size_t>(i)].view(), setup, frame, palette));
        }
        ASSERT_TRUE(smooth.finish(frame));
        std::vector<std::uint8_t> rgb(expected.rgb.size());
        ASSERT_TRUE(smooth.resolveToRgb(frame, palette, kSmoothBackground, rgb));
        EXPECT_TRUE(std::ranges::equal(frame.pixels(), expected.frame.pixels()));
        EXPECT_EQ(rgb, expected.rgb);
      } while (std::ranges::next_permutation(order).found);
    }
  }
}

TEST(SmoothSplats, FastAndSimdBlendTheSameFrames) {
  if (!simdDecoderAvailable()) GTEST_SKIP() << "no AVX2";
  const ModelView& model = defaultModelView();
  const PaletteRgb palette = paletteOf(model);
  for (const double zoom : {1.0, 2.0, 4.0}) {
    for (const int yaw : {0, 30, 135}) {
      const Camera camera = smoothCamera(320, 240, zoom, yaw, 15);
      const FrameSetup setup = smoothSetup(camera, 8);
      const SmoothFrame fast =
          drawSmooth(Variant::kFixedFast, *model.levelOfDepth(8), setup, palette);
      const SmoothFrame simd =
          drawSmooth(Variant::kFixedSimd, *model.levelOfDepth(8), setup, palette);
      EXPECT_TRUE(std::ranges::equal(fast.frame.pixels(), simd.frame.pixels()));
      EXPECT_EQ(fast.rgb, simd.rgb) << "zoom " << zoom << ", yaw " << yaw;
    }
  }
}

// The magnified sphere against its exact silhouette, a disc (a rotated sphere still projects to
// one): the pixels whose centre lies inside it by more than a hundredth of a pixel are covered but
// for at most 1%, none of them more than half a voxel inside the outline, and the frame's outline
// lies no farther out than the box frame's, and on average nearer the disc's where the view is
// turned. (Neither lies within half a voxel of the disc: the sphere's voxels are every voxel
// its surface meets, whose centres lie up to 0.87 voxel edges outside it. docs/splats.md has the
// numbers.)
struct OutlineMeasure {
  long judged = 0, empty = 0;
  double worst_outside = 0, worst_inside = 0;  // voxel edges past the outline, either way
  double outline_sum = 0;  // |distance| of the frame's outline pixels from the disc's outline
  long outline_pixels = 0;
  double meanOutline() const { return outline_pixels ? outline_sum / outline_pixels : 0; }
};

OutlineMeasure measureOutline(const FrameView& frame, const Camera& camera, int depth) {
  const double edge_px = std::ldexp(camera.zoom.raw(), -16) * std::min(camera.width, camera.height);
  const double radius_px = kSmoothSphereRadius * edge_px;
  const double voxel_px = edge_px / std::ldexp(1.0, depth);
  OutlineMeasure m;
  for (std::int32_t y = 0; y < frame.height(); ++y) {
    for (std::int32_t x = 0; x < frame.width(); ++x) {
      const double inside =
          radius_px - std::hypot(x + 0.5 - camera.width / 2.0, y + 0.5 - camera.height / 2.0);
      const bool covered = frame.covered(x, y);
      const auto empty_at = [&](std::int32_t u, std::int32_t v) {
        return u >= 0 && v >= 0 && u < frame.width() && v < frame.height() && !frame.covered(u, v);
      };
      if (covered &&
          (empty_at(x - 1, y) || empty_at(x + 1, y) || empty_at(x, y - 1) || empty_at(x, y + 1))) {
        m.outline_sum += std::fabs(inside) / voxel_px;
        ++m.outline_pixels;
      }
      if (inside > 0.01) {
        ++m.judged;
        if (!covered) {
          ++m.empty;
          m.worst_inside = std::max(m.worst_inside, inside / voxel_px);
        }
      } else if (inside < 0 && covered) {
        m.worst_outside = std::max(m.worst_outside, -inside / voxel_px);
      }
    }
  }
  return m;
}

TEST(SmoothSplats, MagnifiedSphereKeepsItsSilhouetteAndLosesTheStaircase) {
  const PaletteRgb palette = spreadPalette();
  for (const int depth : {4, 5, 6}) {
    const SyntheticLevel sphere = testing_support::sphereLevel(kSmoothSphereRadius, depth);
    for (const double zoom : {0.5, 1.0, 2.0}) {
      for (const int yaw : {0, 30}) {
        const Camera camera = smoothCamera(320, 240, zoom, yaw, yaw / 2);
        const FrameSetup setup = smoothSetup(camera, depth);
        if (!setup.splat.active()) continue;
        const SmoothFrame smooth = drawSmooth(Variant::kFixedFast, sphere.view(), setup, palette);
        Framebuffer box(setup);
        box.clear();
        ASSERT_TRUE(renderLevel(Variant::kFixedFast, sphere.view(), setup, box));
        const OutlineMeasure s = measureOutline(smooth.frame, camera, depth);
        const OutlineMeasure b = measureOutline(box, camera, depth);
        SCOPED_TRACE("depth " + std::to_string(depth) + ", zoom " + std::to_string(zoom) +
                     ", yaw " + std::to_string(yaw));
        ASSERT_GT(s.judged, 100);
        EXPECT_LE(s.empty * 100, s.judged);
        EXPECT_LE(s.worst_inside, 0.5);  // no hole inside the outline
        EXPECT_LE(s.worst_outside, b.worst_outside);
        if (yaw != 0 && b.outline_pixels > 0) {
          // Turned, the box frame's outline is the staircase of the footprints' bounding boxes;
          // the blended one cuts its corners.
          EXPECT_LT(s.meanOutline(), b.meanOutline());
        }
      }
    }
  }
}

std::uint32_t rgbChecksum(const std::vector<std::uint8_t>& rgb) {
  return crc32(std::span<const std::uint8_t>(rgb));
}

// CRC-32 of the RGB bytes of smooth frames of the default model: the same on every build, so that
// scripts/test-armel checks an ARMv5 blends the same frames. A change of the kernel, the
// tolerance or the threshold changes them (then look at the new frames and update them).
TEST(SmoothSplats, FramesHaveTheirFixedChecksums) {
  const ModelView& model = defaultModelView();
  const PaletteRgb palette = paletteOf(model);
  const Camera cameras[] = {smoothCamera(176, 208, 2, 30, 10), smoothCamera(320, 240, 4, 0),
                            smoothCamera(160, 120, 8, 60, -20)};
  const std::uint32_t expected[] = {0xa9b15697, 0x82dbe994, 0xdf3c032c};
  for (std::size_t i = 0; i < std::size(cameras); ++i) {
    const FrameSetup setup = smoothSetup(cameras[i], 8);
    const SmoothFrame smooth =
        drawSmooth(Variant::kFixedFast, *model.levelOfDepth(8), setup, palette);
    EXPECT_EQ(rgbChecksum(smooth.rgb), expected[i])
        << i << std::hex << ": 0x" << rgbChecksum(smooth.rgb);
  }
}

}  // namespace
}  // namespace octopoint
