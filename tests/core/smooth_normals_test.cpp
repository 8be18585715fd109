// Smooth splats with normals (octopoint/smooth.h, docs/splats.md "Smooth splats"): the styles light
// the blended normal, so a magnified sphere shades without facets; where voxels are at most a pixel
// every style draws the box frame's picture bit for bit; styled smooth frames with fixed checksums,
// which the armel build (qemu-arm) checks too.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "octopoint/render.h"
#include "octopoint/smooth.h"
#include "octopoint/styles.h"
#include "renderer/crc32.h"
#include "tests/support/synthetic_levels.h"

namespace octopoint {
namespace {

using testing_support::SyntheticLevel;

constexpr double kLitSphereRadius = 0.35;  // cube units
constexpr int kLitNormalCount = 254;

// A sphere of one grey whose leaves carry normals, as octopoint-prepare --normals stores them: a
// palette of 254 directions spread evenly over the sphere (a Fibonacci lattice), each leaf the
// entry nearest its centre's direction from the sphere's centre.
class LitSphere {
 public:
  explicit LitSphere(int depth) {
    palette_[0] = palette_[1] = palette_[2] = 200;
    const double golden = std::acos(-1.0) * (3.0 - std::sqrt(5.0));
    std::vector<std::array<double, 3>> directions;
    for (int i = 0; i < kLitNormalCount; ++i) {
      const double z = 1.0 - (2.0 * i + 1.0) / kLitNormalCount;
      const double r = std::sqrt(1.0 - z * z);
      directions.push_back({r * std::cos(golden * i), r * std::sin(golden * i), z});
      for (std::size_t c = 0; c < 3; ++c) {
        normal_xyz_[static_cast<std::size_t>(i) * 3 + c] =
            static_cast<std::int16_t>(std::lround(directions.back()[c] * 16384));
      }
    }
    const auto normalOf = [&](std::uint64_t key) {
      std::array<double, 3> centre{};
      for (int level = 0; level < depth; ++level) {
        const auto child = static_cast<unsigned>(key >> (3 * (depth - 1 - level)) & 7u);
        for (unsigned axis = 0; axis < 3; ++axis) {
          centre[axis] = centre[axis] * 2 + ((child >> (2 - axis)) & 1u);
        }
      }
      for (double& c : centre) c = (c + 0.5) / std::ldexp(1.0, depth) - 0.5;
      std::size_t best = 0;
      double best_dot = -2;
      for (std::size_t i = 0; i < directions.size(); ++i) {
        const double dot = centre[0] * directions[i][0] + centre[1] * directions[i][1] +
                           centre[2] * directions[i][2];
        if (dot > best_dot) best_dot = dot, best = i;
      }
      return static_cast<std::uint8_t>(best);
    };
    level_ = testing_support::encodeLevel(testing_support::sphereKeys(kLitSphereRadius, depth),
                                          depth, [&](std::uint64_t key) {
                                            leaf_normals_.push_back(normalOf(key));
                                            return std::uint8_t{0};
                                          });
    embedded_level_ = {static_cast<std::uint8_t>(depth),
                       level_.nodes.data(),
                       static_cast<std::uint32_t>(level_.nodes.size()),
                       level_.leaves.data(),
                       static_cast<std::uint32_t>(level_.leaves.size()),
                       leaf_normals_.data()};
    embedded_ = {"lit sphere",    format::kVersion2, format::v2::kFlagNormals, 0, 1,
                 palette_.data(), kLitNormalCount,   normal_xyz_.data(),       1, &embedded_level_,
                 CubePlacement{}};
    ModelIssue issue;
    const auto view = ModelView::fromEmbedded(embedded_, &issue);
    EXPECT_TRUE(view.has_value()) << describe(issue.error);
    if (view) model_.emplace(*view);
  }

  const ModelView& model() const { return *model_; }
  int depth() const { return level_.depth; }

 private:
  std::array<std::uint8_t, 768> palette_{};
  std::array<std::int16_t, kLitNormalCount * 3> normal_xyz_{};
  SyntheticLevel level_;
  std::vector<std::uint8_t> leaf_normals_;
  EmbeddedLevel embedded_level_{};
  EmbeddedModel embedded_{};
  std::optional<ModelView> model_;
};

FrameSetup litSetup(const Camera& camera, int depth) {
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, depth, kDefaultFractionBits, &setup), CameraError::kNone);
  return setup;
}

// The picture of `model`'s level in `style`, box or smooth.
std::vector<std::uint8_t> litPicture(const ModelView& model, const FrameSetup& setup, Style style,
                                     SplatMode splats) {
  FrameStyler styler(model);
  EXPECT_EQ(styler.setOptions(
                {style, Light{}, Angle::fromDegrees(kDefaultCreaseDegrees), Rgb{236, 236, 240}}),
            StyleError::kNone);
  Framebuffer frame(setup);
  frame.clear(styler.payload());
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(setup.width * setup.height) * 3);
  const LevelView& level = *model.levelOfDepth(setup.depth);
  SmoothSplats smooth(setup.width, setup.height, model);
  PixelBlend blend;
  if (splats == SplatMode::kSmooth) {
    EXPECT_TRUE(renderSmooth(Variant::kFixedFast, level, setup, frame, smooth, paletteOf(model)));
    blend = smooth.pixelBlend();
  } else {
    EXPECT_TRUE(renderLevel(Variant::kFixedFast, level, setup, frame));
  }
  styler.beginFrame(setup);
  EXPECT_EQ(styler.resolve(frame, rgb, blend), StyleError::kNone);
  return rgb;
}

// The steps of a shaded picture between neighbouring pixels inside the sphere's disc (its inner
// `share` of the radius: the outline, where the far side lies within the depth tolerance, is the
// silhouette's business), in grey levels (green): the largest, and the sum of their squares (a
// gradient spread over many small steps sums to less than the same shades in a few facet edges).
struct ShadingSteps {
  int largest = 0;
  long squares = 0, pairs = 0;
};

ShadingSteps shadingSteps(const std::vector<std::uint8_t>& rgb, const Camera& camera,
                          double share) {
  const double radius = share * kLitSphereRadius * std::ldexp(camera.zoom.raw(), -16) *
                        std::min(camera.width, camera.height);
  const auto inside = [&](std::int32_t x, std::int32_t y) {
    return std::hypot(x + 0.5 - camera.width / 2.0, y + 0.5 - camera.height / 2.0) < radius;
  };
  const auto green = [&](std::int32_t x, std::int32_t y) {
    return int{rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(camera.width) +
                    static_cast<std::size_t>(x)) *
                       3 +
                   1]};
  };
  ShadingSteps steps;
  for (std::int32_t y = 0; y + 1 < camera.height; ++y) {
    for (std::int32_t x = 0; x + 1 < camera.width; ++x) {
      if (!inside(x, y)) continue;
      for (const auto& [u, v] : {std::pair{x + 1, y}, std::pair{x, y + 1}}) {
        if (!inside(u, v)) continue;
        const int step = std::abs(green(x, y) - green(u, v));
        steps.largest = std::max(steps.largest, step);
        steps.squares += step * step;
        ++steps.pairs;
      }
    }
  }
  return steps;
}

TEST(SmoothNormals, MagnifiedSphereShadesWithoutFacets) {
  for (const int depth : {4, 5}) {
    const LitSphere sphere(depth);
    for (const int yaw : {0, 30}) {
      const Camera camera = testing_support::viewOf(320, 240, 1, yaw, 15);
      const FrameSetup setup = litSetup(camera, sphere.depth());
      ASSERT_GT(voxelEdgeOnScreen(setup), std::uint64_t{7} << setup.fraction_bits);
      const auto box = litPicture(sphere.model(), setup, Style::kShaded, SplatMode::kBox);
      const auto smooth = litPicture(sphere.model(), setup, Style::kShaded, SplatMode::kSmooth);
      const ShadingSteps b = shadingSteps(box, camera, 0.85);
      const ShadingSteps s = shadingSteps(smooth, camera, 0.85);
      SCOPED_TRACE("depth " + std::to_string(depth) + ", yaw " + std::to_string(yaw) +
                   ": box largest " + std::to_string(b.largest) + ", squares " +
                   std::to_string(b.squares) + "; smooth largest " + std::to_string(s.largest) +
                   ", squares " + std::to_string(s.squares) + " of " + std::to_string(s.pairs) +
                   " pairs");
      ASSERT_GT(s.pairs, 20000);
      // Box: a flat facet per voxel, a step of a palette normal's shade at each voxel's edge
      // (largest 41 to 68, squares 0.67 M to 0.77 M); smooth: largest 8 to 17, squares 61 k to
      // 84 k (measured).
      EXPECT_GE(b.largest, 10);
      EXPECT_LE(s.largest * 3, b.largest);
      EXPECT_LE(s.squares * 5, b.squares);
    }
  }
}

TEST(SmoothNormals, EveryStyleIsTheBoxPictureWhereVoxelsAreAtMostAPixel) {
  const LitSphere sphere(7);
  int turned = 0;
  for (const Camera& camera : {testing_support::viewOf(320, 240, 0.5, 30, 10),
                               testing_support::viewOf(320, 240, 0.5, 0)}) {
    const FrameSetup setup = litSetup(camera, sphere.depth());
    ASSERT_LE(voxelEdgeOnScreen(setup), std::uint64_t{1} << setup.fraction_bits);
    turned += setup.splat.active() ? 1 : 0;
    for (const StyleInfo& style : allStyles()) {
      EXPECT_EQ(litPicture(sphere.model(), setup, style.style, SplatMode::kSmooth),
                litPicture(sphere.model(), setup, style.style, SplatMode::kBox))
          << style.name;
    }
  }
  EXPECT_EQ(turned, 1);
}

// The colour style of a blended frame through FrameStyler (octopoint-render's way) is what
// SmoothSplats::resolveToRgb makes of it.
TEST(SmoothNormals, StylerColoursAreResolveToRgbs) {
  const LitSphere sphere(5);
  const FrameSetup setup = litSetup(testing_support::viewOf(200, 150, 2, 30, 10), sphere.depth());
  Framebuffer frame(setup);
  frame.clear();
  SmoothSplats smooth(setup);
  const PaletteRgb palette = paletteOf(sphere.model());
  ASSERT_TRUE(renderSmooth(Variant::kFixedFast, *sphere.model().levelOfDepth(5), setup, frame,
                           smooth, palette));
  std::vector<std::uint8_t> expected(static_cast<std::size_t>(200 * 150) * 3);
  ASSERT_TRUE(smooth.resolveToRgb(frame, palette, Rgb{236, 236, 240}, expected));
  EXPECT_EQ(litPicture(sphere.model(), setup, Style::kColour, SplatMode::kSmooth), expected);
}

// CRC-32 of smooth styled pictures of the lit sphere: the same on every build (scripts/test-armel
// runs it on an ARMv5). A change of the normals' blending or renormalisation changes them.
TEST(SmoothNormals, StyledFramesHaveTheirFixedChecksums) {
  const LitSphere sphere(5);
  const FrameSetup setup = litSetup(testing_support::viewOf(176, 208, 2, 30, 10), sphere.depth());
  const Style styles[] = {Style::kShaded, Style::kToon, Style::kLines, Style::kOutlined};
  const std::uint32_t expected[] = {0x72d72b31, 0x490f64c1, 0x54ee97d5, 0xbe11d701};
  for (std::size_t i = 0; i < std::size(styles); ++i) {
    const auto rgb = litPicture(sphere.model(), setup, styles[i], SplatMode::kSmooth);
    const std::uint32_t sum = crc32(std::span<const std::uint8_t>(rgb));
    EXPECT_EQ(sum, expected[i]) << styleName(styles[i]) << std::hex << ": 0x" << sum;
  }
}

}  // namespace
}  // namespace octopoint
