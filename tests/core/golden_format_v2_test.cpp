// Golden models of format version 2 (octopoint/model.h, docs/format.md): `.oct` images
// written out byte by byte with literal offsets, frozen here. They must validate and decode to
// exactly the fields, leaves and pixels worked out by hand, so that a change of the layout breaks
// this file and has to be made deliberately, with a new version. Version 1's goldens are in
// golden_format_test.cpp and must keep passing: version 1 stays readable.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/render.h"
#include "tests/support/golden_support.h"

namespace octopoint {
namespace {

using Bytes = std::vector<std::uint8_t>;
using testing::identitySetup;
using testing::validated;

// A version 2 image: the 20 header bytes, the palette entries given (zero up to byte 788), the
// normal palette bytes, then the level table and the streams.
Bytes goldenImage(const Bytes& header20, const Bytes& palette, const Bytes& normal_palette,
                  const Bytes& table_and_streams) {
  EXPECT_EQ(header20.size(), 20u);
  Bytes image = header20;
  image.insert(image.end(), palette.begin(), palette.end());
  image.resize(788, 0);
  image.insert(image.end(), normal_palette.begin(), normal_palette.end());
  image.insert(image.end(), table_and_streams.begin(), table_and_streams.end());
  return image;
}

// Depth 1, children 0 and 7 of the root, red and blue; a 5 km cube (past version 1's 4.29 km).
const Bytes kKilometreCorners = goldenImage(
    {'O',  'C',  'T',  'P',  0x02, 0x00, 0x01, 0x00,  // magic, version 2, one level, no flags
     0x00, 0x80, 0xe0, 0x37, 0x79, 0xc3, 0x11, 0x00,  // cube edge 5,000,000,000,000,000 pm = 5 km
     0x02, 0x00, 0x00, 0x00},                         // 2 colours, no normals
    {0xff, 0x00, 0x00, 0x00, 0x00, 0xff}, {},
    {0x01, 0x00, 0x00, 0x00,  // depth 1, reserved
     0x01, 0x00, 0x00, 0x00,  // 1 node byte
     0x02, 0x00, 0x00, 0x00,  // 2 leaves
     0x81,                    // root: children 0 and 7
     0x00, 0x01});            // leaf colours

// The same two leaves with normals and a made-up (grey) palette, in a 1 nm cube: leaf 0 faces the
// sensor (-z), leaf 1 points right (+x).
const Bytes kCornersWithNormals = goldenImage(
    {'O',  'C',  'T',  'P',  0x02, 0x00, 0x01, 0x03,  // flags: normals | synthetic colour
     0xe8, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // cube edge 1,000 pm = 1 nm
     0x02, 0x00, 0x02, 0x00},                         // 2 colours, 2 normals
    {0x40, 0x40, 0x40, 0xc0, 0xc0, 0xc0},
    {0x00, 0x40, 0x00, 0x00, 0x00, 0x00,   // normal 0: (+1, 0, 0) in Q1.14
     0x00, 0x00, 0x00, 0x00, 0x00, 0xc0},  // normal 1: (0, 0, -1)
    {0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00,
     0x81,          // node bytes
     0x01, 0x00,    // leaf colours
     0x01, 0x00});  // leaf normals: leaf 0 -> normal 1 (-z), leaf 1 -> normal 0 (+x)

// Every fixed variant draws `expected` (one string per row: '.' empty, else a digit from `index`).
template <typename Index>
void expectPixels(const LevelView& level, PixelPayload payload, Index index,
                  const std::vector<std::string>& expected) {
  for (const VariantInfo& info : allVariants()) {
    if (!info.name.starts_with("fixed_")) continue;
    Framebuffer frame(8, 8);
    frame.clear(payload);
    if (payload == PixelPayload::kColourNormal &&
        !drawsNormals(info.variant)) {  // fixed_delta: refused
      EXPECT_FALSE(renderLevel(info.variant, level, identitySetup(level.depth), frame))
          << info.name;
      continue;
    }
    ASSERT_TRUE(renderLevel(info.variant, level, identitySetup(level.depth), frame)) << info.name;
    std::vector<std::string> drawn(8, std::string(8, '.'));
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        if (frame.covered(x, y))
          drawn[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] =
              static_cast<char>('0' + index(frame, x, y));
      }
    }
    EXPECT_EQ(drawn, expected) << info.name;
  }
}

const auto kColourAt = [](const Framebuffer& f, int x, int y) { return f.colourIndexAt(x, y); };
const auto kNormalAt = [](const Framebuffer& f, int x, int y) { return f.normalIndexAt(x, y); };

TEST(GoldenFormatV2, KilometreCubeHasTheFrozenHeaderFields) {
  ASSERT_EQ(kKilometreCorners.size(), 788u + 12u + 3u);
  const ModelView model = validated(kKilometreCorners);
  EXPECT_EQ(model.formatVersion(), 2);
  EXPECT_EQ(model.cubeEdgePicometres(), 5'000'000'000'000'000u);
  EXPECT_FALSE(model.hasNormals());
  EXPECT_FALSE(model.colourIsSynthetic());
  EXPECT_EQ(model.paletteColour(1), (Rgb{0, 0, 0xff}));
  ASSERT_EQ(model.levelCount(), 1);
  EXPECT_TRUE(model.level(0).normals.empty());
  expectPixels(model.level(0), PixelPayload::kColour, kColourAt,
               {"........", "........", "..0.....", "........", "........", "........", "......1.",
                "........"});
}

TEST(GoldenFormatV2, NormalsModelHasTheFrozenHeaderFieldsAndPalette) {
  ASSERT_EQ(kCornersWithNormals.size(), 788u + 12u + 12u + 5u);
  const ModelView model = validated(kCornersWithNormals);
  EXPECT_EQ(model.cubeEdgePicometres(), 1000u);
  EXPECT_TRUE(model.colourIsSynthetic());
  ASSERT_TRUE(model.hasNormals());
  ASSERT_EQ(model.normalCount(), 2);
  EXPECT_EQ(model.normal(0), (NormalQ14{16384, 0, 0}));
  EXPECT_EQ(model.normal(1), (NormalQ14{0, 0, -16384}));
  EXPECT_EQ(model.level(0).normals.size(), 2u);
}

TEST(GoldenFormatV2, NormalsModelDrawsColourAndNormalIndicesPerPixel) {
  const ModelView model = validated(kCornersWithNormals);
  const std::vector<std::string> colours = {"........", "........", "..1.....", "........",
                                            "........", "........", "......0.", "........"};
  const std::vector<std::string> normals = {"........", "........", "..1.....", "........",
                                            "........", "........", "......0.", "........"};
  expectPixels(model.level(0), PixelPayload::kColour, kColourAt, colours);
  expectPixels(model.level(0), PixelPayload::kColourNormal, kColourAt, colours);
  expectPixels(model.level(0), PixelPayload::kColourNormal, kNormalAt, normals);
}

TEST(GoldenFormatV2, AFrameThatWantsNormalsIsNotDrawnFromAModelWithout) {
  const ModelView model = validated(kKilometreCorners);
  for (const VariantInfo& info : allVariants()) {
    Framebuffer frame(8, 8);
    frame.clear(PixelPayload::kColourNormal);
    EXPECT_FALSE(renderLevel(info.variant, model.level(0), identitySetup(1), frame)) << info.name;
    for (std::uint32_t word : frame.pixels()) ASSERT_EQ(word, Framebuffer::kEmpty) << info.name;
  }
}

}  // namespace
}  // namespace octopoint
