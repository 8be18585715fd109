// Golden models of format version 1: small `.oct` images written out byte by byte, frozen here
// (version 2: golden_format_v2_test.cpp). They must validate and
// decode to exactly the leaves and pixels worked out by hand below, so that any change of the
// format (docs/format.md) breaks this file and has to be made deliberately, with a new version.
// Nothing here is built with the library's own constants or writer: every offset and size is a
// literal, as a reader in another language would see the format.
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
#include "renderer/decode_baseline.h"
#include "tests/support/golden_support.h"

namespace octopoint {
namespace {

using Bytes = std::vector<std::uint8_t>;
using testing::identitySetup;
using testing::validated;

// The image of a version 1 model: the 16 header bytes, the palette entries given (the rest of the
// 768 palette bytes are zero, up to byte 784), then the level table and the streams.
Bytes goldenImage(const Bytes& header16, const Bytes& palette, const Bytes& table_and_streams) {
  EXPECT_EQ(header16.size(), 16u);
  Bytes image = header16;
  image.insert(image.end(), palette.begin(), palette.end());
  image.resize(784, 0);
  image.insert(image.end(), table_and_streams.begin(), table_and_streams.end());
  return image;
}

// One level, depth 1: the root has children 0 (x-, y-, z-) and 7 (x+, y+, z+), red and blue.
const Bytes kCornersDepth1 = goldenImage(
    {'O', 'C', 'T', 'P', 0x01, 0x00, 0x01, 0x00,  // magic, version 1, one level, reserved
     0x40, 0x42, 0x0f, 0x00,                      // cube edge 1,000,000 um
     0x02, 0x00, 0x00, 0x00},                     // 2 colours, reserved
    {0xff, 0x00, 0x00, 0x00, 0x00, 0xff},
    {0x01, 0x00, 0x00, 0x00,  // depth 1, reserved
     0x01, 0x00, 0x00, 0x00,  // 1 node byte
     0x02, 0x00, 0x00, 0x00,  // 2 leaves
     0x81,                    // root: children 0 and 7
     0x00, 0x01});            // leaf colours

// Two levels. Depth 1: child 0 only. Depth 2: the root's child 0 has children 0, 1 and 6; children
// 0 and 1 differ only in z, so they fall on one pixel, and the nearer (child 0) must win although
// it comes first in the stream.
const Bytes kOcclusionDepths1And2 = goldenImage(
    {'O', 'C', 'T', 'P', 0x01, 0x00, 0x02, 0x00, 0xe8, 0x03, 0x00, 0x00,  // cube edge 1,000 um
     0x04, 0x00, 0x00, 0x00},                                             // 4 colours
    {0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x70, 0x80, 0x90, 0xa0, 0xb0, 0xc0},
    {0x01, 0x00, 0x00, 0x00, 0x01, 0x00,
     0x00, 0x00, 0x01, 0x00, 0x00, 0x00,  // depth 1: 1 node, 1 leaf
     0x02, 0x00, 0x00, 0x00, 0x02, 0x00,
     0x00, 0x00, 0x03, 0x00, 0x00, 0x00,  // depth 2: 2 nodes, 3 leaves
     0x01,                                // depth 1 nodes
     0x03,                                // depth 1 leaves
     0x01, 0x43,                          // depth 2 nodes: root -> child 0 -> children 0, 1, 6
     0x01, 0x02, 0x03});                  // depth 2 leaves

// A full palette and a single path down to depth 3, ending in the last colour: child 7 of child 0
// of child 4 of the root.
const Bytes kFullPaletteDepth3 = [] {
  Bytes palette;
  for (int i = 0; i < 256; ++i)
    palette.insert(palette.end(), {std::uint8_t(i), std::uint8_t(255 - i), 7});
  return goldenImage({'O', 'C', 'T', 'P', 0x01, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                      0x01, 0x00, 0x00},  // cube edge 0, 256 colours
                     palette,
                     {0x03, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x10,
                      0x01, 0x80, 0xff});
}();

struct Leaf {
  std::int32_t x, y, z;
  std::uint8_t colour;
  bool operator==(const Leaf&) const = default;
};

struct LeafList {
  std::vector<Leaf> leaves;
  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t colour) {
    leaves.push_back({x, y, z, colour});
  }
};

std::vector<Leaf> walk(const LevelView& level) {
  const FrameSetup setup = identitySetup(level.depth);
  LeafList list;
  BaselineWalk<LeafList> walker(level, setup, list);
  EXPECT_TRUE(walker.run());
  return list.leaves;
}

constexpr std::int32_t px(std::int32_t pixels) { return pixels * 32768; }  // Q17.15

// Every fixed-point variant draws the same frame, which must be `expected`: one row per string,
// '.' for an empty pixel, else the palette index as a digit.
void expectPixels(const LevelView& level, const std::vector<std::string>& expected) {
  const FrameSetup setup = identitySetup(level.depth);
  for (const VariantInfo& info : allVariants()) {
    if (!info.name.starts_with("fixed_")) continue;  // float references are only close, not exact
    Framebuffer frame(8, 8);
    frame.clear();
    ASSERT_TRUE(renderLevel(info.variant, level, setup, frame));
    std::vector<std::string> drawn(8, std::string(8, '.'));
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        if (frame.covered(x, y))
          drawn[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] =
              static_cast<char>('0' + frame.colourIndexAt(x, y));
      }
    }
    EXPECT_EQ(drawn, expected) << info.name;
  }
}

TEST(GoldenFormat, CornersModelHasTheFrozenHeaderFields) {
  ASSERT_EQ(kCornersDepth1.size(), 784u + 12u + 3u);
  const ModelView model = validated(kCornersDepth1);
  EXPECT_EQ(model.formatVersion(), 1);
  EXPECT_EQ(model.cubeEdgePicometres(), 1'000'000'000'000u);  // 1,000,000 um
  EXPECT_FALSE(model.hasNormals());
  EXPECT_EQ(model.paletteCount(), 2);
  EXPECT_EQ(model.paletteColour(0), (Rgb{0xff, 0, 0}));
  EXPECT_EQ(model.paletteColour(1), (Rgb{0, 0, 0xff}));
  ASSERT_EQ(model.levelCount(), 1);
  EXPECT_EQ(model.level(0).depth, 1);
}

TEST(GoldenFormat, CornersModelDecodesToTwoOppositeLeaves) {
  const ModelView model = validated(kCornersDepth1);
  const std::vector<Leaf> expected = {{px(2), px(2), px(-2), 0}, {px(6), px(6), px(2), 1}};
  EXPECT_EQ(walk(model.level(0)), expected);
  expectPixels(model.level(0), {"........", "........", "..0.....", "........", "........",
                                "........", "......1.", "........"});
}

TEST(GoldenFormat, TwoLevelModelDecodesBothDepths) {
  const ModelView model = validated(kOcclusionDepths1And2);
  ASSERT_EQ(model.levelCount(), 2);
  EXPECT_EQ(model.cubeEdgePicometres(), 1'000'000'000u);  // 1,000 um
  EXPECT_EQ(model.paletteColour(3), (Rgb{0xa0, 0xb0, 0xc0}));
  EXPECT_EQ(walk(*model.levelOfDepth(1)), (std::vector<Leaf>{{px(2), px(2), px(-2), 3}}));
  const std::vector<Leaf> depth2 = {
      {px(1), px(1), px(-3), 1}, {px(1), px(1), px(-1), 2}, {px(3), px(3), px(-3), 3}};
  EXPECT_EQ(walk(*model.levelOfDepth(2)), depth2);
}

TEST(GoldenFormat, TwoLevelModelDrawsTheNearerOfTwoLeavesOnOnePixel) {
  const ModelView model = validated(kOcclusionDepths1And2);
  expectPixels(*model.levelOfDepth(2), {"........", ".1......", "........", "...3....", "........",
                                        "........", "........", "........"});
  Framebuffer frame(8, 8);
  frame.clear();
  ASSERT_TRUE(
      renderLevel(Variant::kFixedBaseline, *model.levelOfDepth(2), identitySetup(2), frame));
  EXPECT_EQ(frame.depthKeyAt(1, 1), identitySetup(2).depthKey(px(-3)));
}

TEST(GoldenFormat, FullPaletteModelReachesTheLastColour) {
  const ModelView model = validated(kFullPaletteDepth3);
  EXPECT_EQ(model.paletteCount(), 256);
  EXPECT_EQ(model.paletteColour(255), (Rgb{255, 0, 7}));
  // Child 4 of the root: x + 2; its child 0: -1 on each axis; that one's child 7: + 0.5 each.
  EXPECT_EQ(walk(model.level(0)), (std::vector<Leaf>{{px(4) + px(2) - px(1) + px(1) / 2,
                                                      px(4) - px(2) - px(1) + px(1) / 2,
                                                      -px(2) - px(1) + px(1) / 2, 255}}));
}

TEST(GoldenFormat, AnyOtherVersionIsRefused) {
  for (const std::uint8_t version : {0, 3, 255}) {
    Bytes image = kCornersDepth1;
    image[4] = version;
    ModelIssue issue;
    EXPECT_FALSE(ModelView::fromBytes(image, &issue).has_value());
    EXPECT_EQ(issue.error, ModelError::kUnsupportedVersion);
  }
}

}  // namespace
}  // namespace octopoint
