// Every fixed variant draws the bit-identical frame (colours and z-buffer) as fixed_baseline at one
// pixel per leaf, over many cameras and random trees of every depth up to 9; with the set-up's
// footprint splats, the variants that draw them (fixed_fast, fixed_simd) draw the frame of the
// splat's definition (tests/support/splat_reference.h), the others still fixed_baseline's; every
// floating point variant stays within its stated bound of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "tests/support/splat_reference.h"

namespace octopoint {
namespace {

struct Frames {
  Framebuffer reference;
  Framebuffer candidate;
};

std::vector<Camera> manyCameras() {
  std::vector<Camera> cameras;
  std::mt19937 random(2024);
  std::uniform_int_distribution<int> angle(-400, 400);
  std::uniform_int_distribution<int> zoom_percent(20, 400);
  std::uniform_int_distribution<int> pan(-200, 200);
  const std::pair<int, int> sizes[] = {{320, 240}, {176, 208}, {64, 48}, {1, 1}, {401, 299}};
  for (int i = 0; i < 60; ++i) {
    Camera camera;
    camera.yaw = Angle::fromDegrees(angle(random));
    camera.pitch = Angle::fromDegrees(angle(random));
    camera.roll = Angle::fromDegrees(angle(random));
    camera.zoom = Q16::fromRaw(zoom_percent(random) * Q16::kOneRaw / 100);
    camera.pan_x_px = i % 3 == 0 ? pan(random) : 0;  // a third pan partly off screen
    camera.pan_y_px = i % 3 == 0 ? pan(random) : 0;
    camera.width = sizes[i % 5].first;
    camera.height = sizes[i % 5].second;
    cameras.push_back(camera);
  }
  return cameras;
}

class RenderVariants : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelIssue issue;
    model_ = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    ASSERT_TRUE(model_.has_value()) << describe(issue.error);
  }

  // Draws one level with one variant; returns whether it completed.
  static void draw(Variant variant, const LevelView& level, const FrameSetup& setup,
                   Framebuffer& frame) {
    frame.clear();
    ASSERT_TRUE(renderLevel(variant, level, setup, frame));
  }

  std::optional<ModelView> model_;
};

// Draws `level` with every fixed variant (with and without an abort flag to poll) and checks each
// frame: at one pixel per leaf (`setup`'s splat reset) against fixed_baseline's, with the set-up's
// own footprint against the splat's definition for the variants that draw splats.
// With `payload` kColourNormal the frames carry the leaves' normal indices too.
void expectEveryFixedVariantMatches(const LevelView& level, const FrameSetup& natural,
                                    const std::string& label,
                                    PixelPayload payload = PixelPayload::kColour) {
  static const std::atomic<bool> never_set{false};
  FrameSetup one_pixel = natural;
  one_pixel.splat = SplatFootprint{};
  Framebuffer baseline(natural.width, natural.height), splatted(natural.width, natural.height);
  Framebuffer candidate(natural.width, natural.height);
  baseline.clear(payload);
  ASSERT_TRUE(renderLevel(Variant::kFixedBaseline, level, one_pixel, baseline));
  splatted.clear(payload);
  testing_support::ReferenceSplat::draw(level, natural, splatted);
  for (const VariantInfo& info : allVariants()) {
    if (!isFixedPoint(info.variant)) continue;
    if (payload == PixelPayload::kColourNormal &&
        !drawsNormals(info.variant)) {  // fixed_delta: refused
      candidate.clear(payload);
      EXPECT_FALSE(renderLevel(info.variant, level, natural, candidate))
          << info.name << " " << label;
      EXPECT_TRUE(std::ranges::all_of(
          candidate.pixels(), [](std::uint32_t word) { return word == Framebuffer::kEmpty; }))
          << info.name << " drew into a frame it refused, " << label;
      continue;
    }
    for (const FrameSetup* setup : {static_cast<const FrameSetup*>(&one_pixel), &natural}) {
      const Framebuffer& expected =
          setup == &natural && drawsSplats(info.variant) ? splatted : baseline;
      for (const std::atomic<bool>* abort :
           {static_cast<const std::atomic<bool>*>(nullptr), &never_set}) {
        candidate.clear(payload);
        ASSERT_TRUE(renderLevel(info.variant, level, *setup, candidate, abort));
        ASSERT_TRUE(std::ranges::equal(candidate.pixels(), expected.pixels()))
            << info.name << " " << label
            << (setup == &natural ? " with its splats " : " one pixel per leaf ")
            << (natural.splat.active() ? "(splat active)" : "(no splat)")
            << (abort != nullptr ? " with" : " without") << " an abort flag";
      }
    }
  }
}

TEST_F(RenderVariants, EveryFixedVariantDrawsTheBaselineFrameBitForBit) {
  int splatting = 0, frames = 0;
  for (int i = 0; i < model_->levelCount(); ++i) {
    const LevelView& level = model_->level(i);
    for (const Camera& camera : manyCameras()) {
      FrameSetup setup;
      ASSERT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup),
                CameraError::kNone);
      splatting += setup.splat.active() ? 1 : 0;
      ++frames;
      expectEveryFixedVariantMatches(
          level, setup,
          "depth " + std::to_string(level.depth) + " yaw " + std::to_string(camera.yaw.turns16()));
    }
  }
  EXPECT_GT(splatting, frames / 10);  // both kinds of frame are among these cameras
  EXPECT_LT(splatting, frames - frames / 10);
}

// The same with the normal indices in the frame (PixelPayload::kColourNormal): the default model
// has normals, and every fixed variant must draw the same words from them too.
TEST_F(RenderVariants, EveryFixedVariantDrawsTheBaselineFrameWithNormalsBitForBit) {
  ASSERT_TRUE(model_->hasNormals());
  const std::vector<Camera> cameras = manyCameras();
  for (int i = 0; i < model_->levelCount(); ++i) {
    const LevelView& level = model_->level(i);
    for (std::size_t c = 0; c < cameras.size(); c += 2) {
      FrameSetup setup;
      ASSERT_EQ(buildFrameSetup(cameras[c], level.depth, kDefaultFractionBits, &setup),
                CameraError::kNone);
      expectEveryFixedVariantMatches(
          level, setup,
          "normals, depth " + std::to_string(level.depth) + " camera " + std::to_string(c),
          PixelPayload::kColourNormal);
    }
  }
}

// A random valid level of `depth` with about `leaves_wanted` leaves: each child of each node is
// present with the same probability (a node keeps at least one), and every leaf has a random
// palette index.
struct RandomLevel {
  std::vector<std::uint8_t> nodes, leaves, normals;
  LevelView view(int depth) const { return LevelView{depth, nodes, leaves, normals}; }
};

RandomLevel randomLevel(int depth, double leaves_wanted, std::mt19937& random) {
  const double children_per_node = std::min(8.0, std::pow(leaves_wanted, 1.0 / depth));
  std::bernoulli_distribution present(children_per_node / 8.0);
  std::uniform_int_distribution<int> colour(0, 255);
  std::uniform_int_distribution<int> normal(0, 254);
  RandomLevel level;
  auto grow = [&](auto& self, int level_index) -> void {
    unsigned mask = 0;
    while (mask == 0) {
      for (unsigned k = 0; k < 8; ++k) mask |= present(random) ? 1u << k : 0u;
    }
    level.nodes.push_back(static_cast<std::uint8_t>(mask));
    for (int child = std::popcount(mask); child > 0; --child) {
      if (level_index + 1 == depth) {
        level.leaves.push_back(static_cast<std::uint8_t>(colour(random)));
        level.normals.push_back(static_cast<std::uint8_t>(normal(random)));
      } else {
        self(self, level_index + 1);
      }
    }
  };
  grow(grow, 0);
  // Buffers that end at the last byte: under ASan, a decoder reading past the stream fails.
  level.nodes.shrink_to_fit();
  level.leaves.shrink_to_fit();
  level.normals.shrink_to_fit();
  return level;
}

// Random trees from a few leaves to thousands, depth 1 to 9: the decoders' special cases (a
// model's last leaves, subtrees emitted in one call, levels above the abort poll) all occur, and
// the frames must still match fixed_baseline's, with and without an abort flag to poll.
TEST_F(RenderVariants, EveryFixedVariantDrawsTheBaselineFrameOfRandomTreesOfEveryDepth) {
  std::mt19937 random(7);
  const std::vector<Camera> cameras = manyCameras();
  for (int depth = 1; depth <= 9; ++depth) {
    for (const double leaves_wanted : {6.0, 70.0, 600.0, 5000.0}) {
      const RandomLevel tree = randomLevel(depth, leaves_wanted, random);
      const LevelView level = tree.view(depth);
      ASSERT_EQ(validateLevelStream(level, 256, 255).error, ModelError::kNone);
      for (std::size_t c = 0; c < cameras.size(); c += 6) {
        const Camera& camera = cameras[c];
        FrameSetup setup;
        ASSERT_EQ(buildFrameSetup(camera, depth, kDefaultFractionBits, &setup), CameraError::kNone);
        for (const PixelPayload payload : {PixelPayload::kColour, PixelPayload::kColourNormal}) {
          expectEveryFixedVariantMatches(level, setup,
                                         "depth " + std::to_string(depth) + " leaves " +
                                             std::to_string(tree.leaves.size()) + " camera " +
                                             std::to_string(c),
                                         payload);
        }
      }
    }
  }
}

// fixed_fast and fixed_simd step over off-screen subtrees through the level's skip index
// (octopoint/model.h) where it has one. Zoomed in and panned, so that most subtrees are off
// screen (some frames wholly), on the default model (ModelView's index) and on random trees of
// depth 4 to 9, each frame equals the one drawn without the index (the byte walk), bit for bit:
// with the set-up's splats and one pixel per leaf, colour and normals.
TEST_F(RenderVariants, FastAndSimdDrawTheSameFrameWithTheSkipIndexAsWithout) {
  std::mt19937 random(31);
  std::uniform_int_distribution<int> angle(-400, 400);
  std::uniform_int_distribution<int> zoom_quarters(4, 64);
  std::uniform_int_distribution<int> pan(-800, 800);
  const std::pair<int, int> sizes[] = {{176, 208}, {320, 240}, {64, 48}};
  std::vector<Camera> cameras;
  for (int i = 0; i < 24; ++i) {
    Camera camera;
    camera.yaw = Angle::fromDegrees(angle(random));
    camera.pitch = Angle::fromDegrees(angle(random));
    camera.zoom = Q16::fromRaw(zoom_quarters(random) * (Q16::kOneRaw / 4));
    camera.pan_x_px = i % 4 == 0 ? 0 : pan(random);
    camera.pan_y_px = i % 4 == 0 ? 0 : pan(random);
    camera.width = sizes[i % 3].first;
    camera.height = sizes[i % 3].second;
    cameras.push_back(camera);
  }
  int frames = 0;
  const auto expectSameFrames = [&](const LevelView& indexed, const std::string& label) {
    ASSERT_GT(indexed.skip.level, 0) << label;
    LevelView plain = indexed;
    plain.skip = SkipIndex{};
    for (const Camera& camera : cameras) {
      FrameSetup natural;
      ASSERT_EQ(buildFrameSetup(camera, indexed.depth, kDefaultFractionBits, &natural),
                CameraError::kNone);
      FrameSetup one_pixel = natural;
      one_pixel.splat = SplatFootprint{};
      Framebuffer expected(camera.width, camera.height), candidate(camera.width, camera.height);
      for (const FrameSetup* setup : {&natural, &one_pixel}) {
        for (const PixelPayload payload : {PixelPayload::kColour, PixelPayload::kColourNormal}) {
          for (const Variant variant : {Variant::kFixedFast, Variant::kFixedSimd}) {
            expected.clear(payload);
            ASSERT_TRUE(renderLevel(variant, plain, *setup, expected));
            candidate.clear(payload);
            ASSERT_TRUE(renderLevel(variant, indexed, *setup, candidate));
            ASSERT_TRUE(std::ranges::equal(candidate.pixels(), expected.pixels()))
                << label << ", variant " << static_cast<int>(variant)
                << (setup == &natural ? ", splats" : ", one pixel") << ", zoom "
                << camera.zoom.raw() << ", pan " << camera.pan_x_px << "," << camera.pan_y_px;
            ++frames;
          }
        }
      }
    }
  };
  for (int i = 0; i < model_->levelCount(); ++i) {
    expectSameFrames(model_->level(i),
                     "default model depth " + std::to_string(model_->level(i).depth));
  }
  for (int depth = 4; depth <= 9; ++depth) {
    const RandomLevel tree = randomLevel(depth, 5000.0, random);
    LevelView level = tree.view(depth);
    std::vector<SubtreeEnd> storage(skipIndexEntries(level));
    level.skip = buildSkipIndex(level, storage);
    expectSameFrames(level, "random tree depth " + std::to_string(depth));
  }
  EXPECT_EQ(frames, (3 + 6) * 24 * 8);
}

// The floating point variants land each leaf on the fixed pixel or one beside it (their positions
// differ by at most depth/2 fixed ulps plus single precision rounding), so frames differ only along
// pixel boundaries. Stated bound: at most 0.5% of the pixels that either frame covers differ in
// coverage or colour (measured on these cameras: at most 0.06%).
TEST_F(RenderVariants, FloatVariantsDifferFromTheFixedFrameInAtMostHalfAPercentOfPixels) {
  constexpr double kMaxDifferingShare = 0.005;
  for (const Camera& camera : manyCameras()) {
    const LevelView& level = model_->finestLevel();
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup),
              CameraError::kNone);
    Framebuffer reference(camera.width, camera.height);
    Framebuffer candidate(camera.width, camera.height);
    draw(Variant::kFixedBaseline, level, setup, reference);
    for (const VariantInfo& info : allVariants()) {
      if (isFixedPoint(info.variant)) continue;
      draw(info.variant, level, setup, candidate);
      std::size_t covered = 0, differing = 0;
      const std::span<const std::uint32_t> fixed = reference.pixels(),
                                           floating = candidate.pixels();
      for (std::size_t p = 0; p < fixed.size(); ++p) {
        const bool a = fixed[p] != Framebuffer::kEmpty;
        const bool b = floating[p] != Framebuffer::kEmpty;
        if (!a && !b) continue;
        ++covered;
        if (a != b ||
            Framebuffer::colourIndexOf(fixed[p]) != Framebuffer::colourIndexOf(floating[p]))
          ++differing;
      }
      if (covered < 100) continue;  // a handful of pixels says nothing about a share
      EXPECT_LE(static_cast<double>(differing), kMaxDifferingShare * static_cast<double>(covered))
          << info.name << ": " << differing << " of " << covered << " pixels differ, size "
          << camera.width << "x" << camera.height;
    }
  }
}

}  // namespace
}  // namespace octopoint
