// The line styles' loop (octopoint/styles.h) gives every pixel exactly the class the per-pixel
// definition (classifyPixel, octopoint/styles.h) gives it: on frames of random words (background,
// depth steps around the jump, keys near the largest, few and many normals, bands of rows, drawn
// rectangles smaller than the frame) and on the default model's frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/styles.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

// A model of one leaf with kNormals random unit normals (Q1.14), for a crease table.
constexpr int kNormals = 24;
struct RandomNormals {
  std::array<std::uint8_t, 768> palette{};
  std::uint8_t nodes[1] = {0x01};
  std::uint8_t leaves[1] = {0};
  std::uint8_t normals[1] = {0};
  std::array<std::int16_t, 3 * kNormals> normal_xyz{};
  EmbeddedLevel level{1, nodes, 1, leaves, 1, normals};
  EmbeddedModel model{"random",       format::kVersion2, format::v2::kFlagNormals, 0, 1,
                      palette.data(), kNormals,          normal_xyz.data(),        1, &level};

  RandomNormals() {
    // Normals spread over a quarter sphere, so that some pairs are creases and some are not. The
    // validator wants unit length within rounding: built from integer Pythagorean-like triples
    // scaled to 16384 would be exact, but a normalised double rounded is within one unit.
    std::mt19937 random(5);
    std::uniform_real_distribution<double> angle(0.0, 1.6);
    for (int i = 0; i < kNormals; ++i) {
      const double a = angle(random), b = angle(random);
      const double v[3] = {std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b)};
      for (int c = 0; c < 3; ++c)
        normal_xyz[static_cast<std::size_t>(3 * i + c)] =
            static_cast<std::int16_t>(std::lround(v[c] * 16384));
    }
  }
  ModelView view() const {
    ModelIssue issue;
    const auto v = ModelView::fromEmbedded(model, &issue);
    EXPECT_TRUE(v.has_value()) << describe(issue.error);
    return *v;
  }
};

// Rows [first_row, end_row) of `frame` as the loop paints them (edge in the low 2 bits, the word's
// palette index and normal index above it, or all ones for background) ...
std::vector<std::uint32_t> loopClasses(const FrameView& frame, std::int32_t first_row,
                                       std::int32_t end_row, const EdgeRule& rule) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>((end_row - first_row) * frame.width()) *
                                3);
  forEachStyledPixel(frame, first_row, end_row, rule, rgb, [](std::uint32_t word, Edge edge) {
    return word == Framebuffer::kEmpty ? 0xFFFFFFu
                                       : (word & 0xFFFFu) << 2 | static_cast<std::uint32_t>(edge);
  });
  std::vector<std::uint32_t> classes;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    classes.push_back(std::uint32_t{rgb[i]} << 16 | std::uint32_t{rgb[i + 1]} << 8 | rgb[i + 2]);
  return classes;
}

// ... and as the definition classifies them, pixel by pixel.
std::vector<std::uint32_t> definitionClasses(const FrameView& frame, std::int32_t first_row,
                                             std::int32_t end_row, const EdgeRule& rule) {
  std::vector<std::uint32_t> classes;
  for (std::int32_t y = first_row; y < end_row; ++y) {
    for (std::int32_t x = 0; x < frame.width(); ++x) {
      const std::uint32_t word = frame.pixelAt(x, y);
      classes.push_back(word == Framebuffer::kEmpty
                            ? 0xFFFFFFu
                            : (word & 0xFFFFu) << 2 |
                                  static_cast<std::uint32_t>(classifyPixel(frame, x, y, rule)));
    }
  }
  return classes;
}

void expectLoopMatchesDefinition(const FrameView& frame, const EdgeRule& rule, const char* what) {
  const std::vector<std::uint32_t> whole = loopClasses(frame, 0, frame.height(), rule);
  const std::vector<std::uint32_t> defined = definitionClasses(frame, 0, frame.height(), rule);
  std::size_t differing = 0, first_differing = 0;
  for (std::size_t i = whole.size(); i-- > 0;) {
    if (whole[i] != defined[i]) {
      ++differing;
      first_differing = i;
    }
  }
  EXPECT_EQ(differing, 0u) << what << " (" << frame.width() << " x " << frame.height() << ", jump "
                           << rule.jump << "): first at x "
                           << first_differing % static_cast<std::size_t>(frame.width()) << ", y "
                           << first_differing / static_cast<std::size_t>(frame.width())
                           << ", loop class " << (whole[first_differing] & 3) << ", defined "
                           << (defined[first_differing] & 3);
  // Bands of 1, 2 and 7 rows give the same rows.
  for (const std::int32_t band : {1, 2, 7}) {
    std::vector<std::uint32_t> banded;
    for (std::int32_t first = 0; first < frame.height(); first += band) {
      const std::vector<std::uint32_t> part =
          loopClasses(frame, first, std::min(first + band, frame.height()), rule);
      banded.insert(banded.end(), part.begin(), part.end());
    }
    EXPECT_EQ(banded, whole) << what << ", bands of " << band << " rows";
  }
}

TEST(EdgesFastPath, RandomFramesClassifyAsTheDefinitionSays) {
  const RandomNormals normals;
  const ModelView model = normals.view();
  CreaseTable creases;
  creases.build(model, Angle::fromDegrees(40));
  std::mt19937 random(13);
  std::size_t silhouettes = 0, crease_pixels = 0, explained_steps = 0;
  for (int round = 0; round < 60; ++round) {
    const std::int32_t width = 1 + static_cast<std::int32_t>(random() % 40);
    const std::int32_t height = 1 + static_cast<std::int32_t>(random() % 30);
    Framebuffer frame(width, height);
    frame.clear(PixelPayload::kColourNormal);
    // Keys around a base, some near the largest key (0xFFFF) where depth + jump passes it.
    const std::uint32_t base =
        round % 3 == 0 ? 0xFFF0u : static_cast<std::uint32_t>(random() % 0xF000);
    const std::uint32_t spread = 1 + random() % 64, normal_count = 1 + random() % kNormals;
    const std::uint32_t empty_per_16 = random() % 8;
    // Drawn only inside a rectangle, sometimes smaller than the frame.
    const std::int32_t x0 =
        round % 2 ? static_cast<std::int32_t>(random() % static_cast<std::uint32_t>(width)) : 0;
    const std::int32_t y0 =
        round % 2 ? static_cast<std::int32_t>(random() % static_cast<std::uint32_t>(height)) : 0;
    std::uint32_t* pixels = frame.pixelsToDraw({x0, width, y0, height});
    for (std::int32_t y = y0; y < height; ++y) {
      for (std::int32_t x = x0; x < width; ++x) {
        if (random() % 16 < empty_per_16) continue;
        const std::uint32_t key = std::min<std::uint32_t>(base + random() % spread, 0xFFFF);
        const std::uint32_t normal = random() % normal_count, colour = random() % 256;
        pixels[static_cast<std::size_t>(y * width + x)] = key << 16 | normal << 8 | colour;
      }
    }
    // Slopes of a turned set-up with one-pixel voxels: a pair's slack, 2 pixels (256 key units)
    // times its slope, is below the keys' spread for the steeper normals and above for the others.
    Camera camera;
    camera.width = camera.height = 16;
    camera.yaw = Angle::fromDegrees(static_cast<std::int32_t>(random() % 360));
    camera.pitch = Angle::fromDegrees(static_cast<std::int32_t>(random() % 180) - 90);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, 1, kDefaultFractionBits, &setup), CameraError::kNone);
    SurfaceSlopes slopes;
    slopes.build(model, setup);
    for (const std::uint32_t jump : {0u, 1u, 8u, 40u, 0xFFFFu}) {
      const EdgeRule rule{jump, 16, round % 5 == 4 ? nullptr : &creases,
                          round % 3 == 1 ? nullptr : &slopes};
      expectLoopMatchesDefinition(frame, rule, "random frame");
      if (rule.slopes != nullptr) {
        for (std::int32_t y = 0; y < height; ++y) {
          for (std::int32_t x = 0; x < width; ++x) {
            const EdgeRule without{jump, 16, rule.creases, nullptr};
            explained_steps += frame.pixelAt(x, y) != Framebuffer::kEmpty &&
                               hasSilhouetteNeighbour(frame, x, y, without) &&
                               !hasSilhouetteNeighbour(frame, x, y, rule);
          }
        }
      }
      for (const std::uint32_t c : loopClasses(frame, 0, height, rule)) {
        silhouettes += c != 0xFFFFFFu && (c & 3) == static_cast<std::uint32_t>(Edge::kSilhouette);
        crease_pixels += c != 0xFFFFFFu && (c & 3) == static_cast<std::uint32_t>(Edge::kCrease);
      }
    }
  }
  // The frames exercise both kinds of line.
  EXPECT_GT(silhouettes, 1000u);
  EXPECT_GT(crease_pixels, 1000u);
  EXPECT_GT(explained_steps, 1000u);  // steps over the jump that the pair's slope explains
}

TEST(EdgesFastPath, TheDefaultModelsFramesClassifyAsTheDefinitionSays) {
  ModelIssue issue;
  const ModelView model = *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.hasNormals());
  CreaseTable creases;
  creases.build(model, Angle::fromDegrees(kDefaultCreaseDegrees));
  for (const auto& [width, height, yaw, zoom_q16] :
       std::vector<std::array<std::int32_t, 4>>{{320, 240, 30, 65536},
                                                {160, 120, -70, 131072},
                                                {200, 300, 10, 16384},
                                                {640, 480, 150, 98304}}) {
    Camera camera;
    camera.width = width;
    camera.height = height;
    camera.yaw = Angle::fromDegrees(yaw);
    camera.zoom = Q16::fromRaw(zoom_q16);
    const LevelView* level = autoLevel(model, camera);
    ASSERT_NE(level, nullptr);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup),
              CameraError::kNone);
    Framebuffer frame(setup);
    frame.clear(PixelPayload::kColourNormal);
    ASSERT_TRUE(renderLevel(Variant::kFixedFast, *level, setup, frame));
    SurfaceSlopes slopes;
    slopes.build(model, setup);
    expectLoopMatchesDefinition(
        frame, edgeRuleFor(setup, PixelPayload::kColourNormal, &creases, &slopes), "default model");
    expectLoopMatchesDefinition(
        frame, edgeRuleFor(setup, PixelPayload::kColourNormal, &creases, nullptr), "default model");
  }
}

}  // namespace
}  // namespace octopoint
