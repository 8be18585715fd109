// fixed_delta's leaf arithmetic (renderer/delta_leaves.h) at the edges of its preconditions, and
// the RGB565 conversion's two paths (octopoint/framebuffer.h). The variant's frames at the default
// set-up are compared with fixed_baseline's with every other variant (render_variants_test.cpp,
// band_renderer_test.cpp).
#include "renderer/delta_leaves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint {
namespace {

const ModelView& defaultModel() {
  static const std::optional<ModelView> model = [] {
    ModelIssue issue;
    return ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return *model;
}

std::vector<std::uint32_t> draw(Variant variant, const LevelView& level, const FrameSetup& setup) {
  Framebuffer frame(setup.width, setup.height);
  frame.clear();
  EXPECT_TRUE(renderLevel(variant, level, setup, frame));
  return {frame.pixels().begin(), frame.pixels().end()};
}

// Every fraction bit count a turned, panned frame accepts: up to 15 the packed carries, above it
// the plain plot; the frames must be fixed_baseline's either way.
TEST(DeltaLeaves, EveryFractionBitCountDrawsTheBaselineFrame) {
  const LevelView& level = *defaultModel().levelOfDepth(8);
  Camera camera;
  camera.yaw = Angle::fromDegrees(-35);
  camera.pitch = Angle::fromDegrees(25);
  camera.zoom = Q16::fromRaw(Q16::kOneRaw * 3 / 4);
  camera.pan_x_px = 41;  // part of the model off the frame: straddling subtrees too
  int packed = 0, plain = 0;
  for (int bits = kMinFractionBits; bits <= kMaxFractionBits; ++bits) {
    FrameSetup setup;
    if (buildFrameSetup(camera, level.depth, bits, &setup) != CameraError::kNone) continue;
    setup.splat = SplatFootprint{};
    (deltaLeavesApply(setup) ? packed : plain) += 1;
    EXPECT_TRUE(draw(Variant::kFixedDelta, level, setup) ==
                draw(Variant::kFixedBaseline, level, setup))
        << bits << " fraction bits";
  }
  EXPECT_EQ(packed, 15);
  EXPECT_GE(plain, 5);
}

// The key's shift by 8 - s, at every shift the packed path takes and one past it: the set-up's
// shift and bias overridden (keys may then overflow 24 bits; both decoders pack them alike).
TEST(DeltaLeaves, EveryDepthShiftDrawsTheBaselineFrame) {
  const LevelView& level = *defaultModel().levelOfDepth(7);
  Camera camera;
  camera.yaw = Angle::fromDegrees(150);
  camera.pitch = Angle::fromDegrees(-40);
  FrameSetup natural;
  ASSERT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &natural),
            CameraError::kNone);
  for (int shift = 0; shift <= 9; ++shift) {
    for (const std::uint32_t bias :
         {natural.depth_bias, natural.depth_bias * 3 + 12345u, 0xFFFF'F000u}) {
      FrameSetup setup = natural;
      setup.depth_shift = shift;
      setup.depth_bias = bias;
      EXPECT_EQ(deltaLeavesApply(setup), shift <= 8);
      EXPECT_TRUE(draw(Variant::kFixedDelta, level, setup) ==
                  draw(Variant::kFixedBaseline, level, setup))
          << "shift " << shift << " bias " << bias;
    }
  }
}

// The packed fractions: for every pair of fractions at the largest F, one addition gives both
// carries (F = 15: x's out of bit 31, y's in bit 16) and nothing leaks between the fields.
TEST(DeltaLeaves, PackedFractionsCarryExactly) {
  constexpr int f = 15;
  std::mt19937 random(3);
  std::uniform_int_distribution<std::uint32_t> fraction(0, (1u << f) - 1);
  for (int i = 0; i < 100000; ++i) {
    const std::uint32_t fx = i < 4 ? (i & 1 ? (1u << f) - 1 : 0) : fraction(random);
    const std::uint32_t fy = i < 4 ? (i & 2 ? (1u << f) - 1 : 0) : fraction(random);
    const std::uint32_t gx = fraction(random), gy = fraction(random);
    const std::uint32_t packed = fx << (32 - f) | fy << (16 - f),
                        step = gx << (32 - f) | gy << (16 - f);
    std::uint32_t sum;
    const bool carry_x = __builtin_add_overflow(packed, step, &sum);
    ASSERT_EQ(carry_x, fx + gx >= (1u << f));
    ASSERT_EQ((sum & 0x1'0000u) != 0, fy + gy >= (1u << f));
  }
}

// Both conversions equal the definition, for every palette index, empty words, odd lengths, in
// place and into separate memory.
TEST(Rgb565, BothConversionsEqualTheDefinition) {
  std::mt19937 random(5);
  std::uniform_int_distribution<std::uint32_t> any_word;
  Rgb565Palette with_255, without_255;
  for (std::size_t i = 0; i < 256; ++i) {
    with_255.colour[i] = static_cast<std::uint16_t>(i * 251 + 7);
    without_255.colour[i] = with_255.colour[i];
  }
  with_255.background = without_255.background = 0xBEEF;
  without_255.last_index_unused = true;
  without_255.colour[255] = without_255.background;
  for (const bool uses_255 : {true, false}) {
    const Rgb565Palette& palette = uses_255 ? with_255 : without_255;
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{8},
                                    std::size_t{9}, std::size_t{4099}}) {
      std::vector<std::uint32_t> words(count);
      for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t word = any_word(random);
        // A third empty; the rest real words (key below 2^24 - 1), with index 255 only if used.
        words[i] = i % 3 == 0 ? FrameView::kEmpty
                              : FrameView::pack(
                                    FrameView::depthKeyOf(word) % (FrameView::kMaxDepthKey + 1),
                                    static_cast<std::uint8_t>(uses_255 ? word : word % 255));
      }
      if (count > 5) words[5] = FrameView::pack(FrameView::kMaxDepthKey, uses_255 ? 255 : 254);
      std::vector<std::uint16_t> expected(count);
      for (std::size_t i = 0; i < count; ++i) {
        expected[i] = words[i] == FrameView::kEmpty
                          ? palette.background
                          : palette.colour[FrameView::colourIndexOf(words[i])];
      }
      std::vector<std::uint16_t> apart(count);
      packedToRgb565(words.data(), count, palette, reinterpret_cast<std::uint8_t*>(apart.data()));
      EXPECT_TRUE(apart == expected) << count << (uses_255 ? " with" : " without") << " index 255";
      packedToRgb565(words.data(), count, palette, reinterpret_cast<std::uint8_t*>(words.data()));
      const auto* in_place = reinterpret_cast<const std::uint16_t*>(words.data());
      EXPECT_TRUE(std::equal(expected.begin(), expected.end(), in_place)) << count << " in place";
    }
  }
}

TEST(Rgb565, APaletteOfFewerThan256ColoursFreesIndex255ForTheBackground) {
  const Rgb565Palette palette = makeRgb565Palette(defaultModel(), Rgb{1, 2, 3});
  EXPECT_EQ(palette.last_index_unused, defaultModel().paletteCount() < 256);
  EXPECT_EQ(palette.background, toRgb565(Rgb{1, 2, 3}));
}

}  // namespace
}  // namespace octopoint
