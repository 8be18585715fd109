// Scanline hole filling: one test per hole type it fills, one per thing it must leave alone.
// Frames are drawn as ASCII art: 'a'..'z' covered at depth kNear (colour = the letter), 'A'..'Z'
// covered at depth kFar (a surface behind, more than the bridge limit away), '.' empty.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint {
namespace {

constexpr std::uint32_t kLimit = 100;  // the bridge limit used with the art frames, in depth keys
constexpr std::uint32_t kNear = 1000;
constexpr std::uint32_t kFar = kNear + kLimit + 1;

Framebuffer frameFromArt(const std::vector<std::string>& art) {
  Framebuffer frame(static_cast<std::int32_t>(art[0].size()),
                    static_cast<std::int32_t>(art.size()));
  frame.clear();
  for (std::int32_t y = 0; y < frame.height(); ++y) {
    for (std::int32_t x = 0; x < frame.width(); ++x) {
      const char c = art[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
      if (c >= 'a' && c <= 'z')
        frame.plot(x, y, kNear + static_cast<std::uint32_t>(c - 'a'), static_cast<std::uint8_t>(c));
      if (c >= 'A' && c <= 'Z') frame.plot(x, y, kFar, static_cast<std::uint8_t>(c - 'A' + 'a'));
    }
  }
  return frame;
}

// The frame back as art: covered pixels by colour letter (lower case), empty as '.'.
std::vector<std::string> artOf(const Framebuffer& frame) {
  std::vector<std::string> art;
  for (std::int32_t y = 0; y < frame.height(); ++y) {
    std::string row;
    for (std::int32_t x = 0; x < frame.width(); ++x) {
      row += frame.covered(x, y) ? static_cast<char>(frame.colourIndexAt(x, y)) : '.';
    }
    art.push_back(row);
  }
  return art;
}

struct Filled {
  std::vector<std::string> art;
  HoleFillCounts counts;
};

Filled fillArt(const std::vector<std::string>& art) {
  Framebuffer frame = frameFromArt(art);
  HoleFiller filler(frame.width());
  const HoleFillCounts counts = filler.fill(frame, kLimit);
  return {artOf(frame), counts};
}

std::vector<std::string> lowerCase(std::vector<std::string> art) {
  for (std::string& row : art) {
    for (char& c : row) c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  return art;
}

TEST(HoleFill, Type1HorizontalSingleGapTakesTheNearerNeighbour) {
  // 'a' is nearer than 'c' (depth kNear vs kNear + 2).
  const Filled filled = fillArt({".....", ".a.c.", "....."});
  EXPECT_EQ(filled.art, (std::vector<std::string>{".....", ".aac.", "....."}));
  EXPECT_EQ(filled.counts.type1, 1);
  EXPECT_EQ(filled.counts.total(), 1);
}

TEST(HoleFill, Type2VerticalSingleGap) {
  const Filled filled = fillArt({"...", ".c.", "...", ".b.", "..."});
  EXPECT_EQ(filled.art, (std::vector<std::string>{"...", ".c.", ".b.", ".b.", "..."}));
  EXPECT_EQ(filled.counts.type2, 1);
  EXPECT_EQ(filled.counts.total(), 1);
}

TEST(HoleFill, Type3DiagonalGapNeedsAllFourDiagonalNeighbours) {
  const Filled filled = fillArt({".....", ".d.c.", ".....", ".b.e.", "....."});
  // The centre is an X; the pixels between two corners are types 1 and 2.
  EXPECT_EQ(filled.art, (std::vector<std::string>{".....", ".dcc.", ".bbc.", ".bbe.", "....."}));
  EXPECT_EQ(filled.counts.type3, 1);
  EXPECT_EQ(filled.counts.type1, 2);
  EXPECT_EQ(filled.counts.type2, 2);
}

TEST(HoleFill, Type4TwoPixelGapsTakeTheirOwnSide) {
  EXPECT_EQ(fillArt({"......", ".a..c.", "......"}).art,
            (std::vector<std::string>{"......", ".aacc.", "......"}));
  const Filled vertical = fillArt({"...", ".a.", "...", "...", ".c.", "..."});
  EXPECT_EQ(vertical.art, (std::vector<std::string>{"...", ".a.", ".a.", ".c.", ".c.", "..."}));
  EXPECT_EQ(vertical.counts.type4, 2);
  EXPECT_EQ(vertical.counts.total(), 2);
}

TEST(HoleFill, NeverBridgesADepthStep) {
  // The gaps of types 1, 2 and 4 between a near and a far surface stay open.
  for (const std::vector<std::string>& step :
       {std::vector<std::string>{".....", ".a.A.", "....."},
        std::vector<std::string>{"...", ".a.", "...", ".A.", "..."},
        std::vector<std::string>{"......", ".a..A.", "......"},
        std::vector<std::string>{"...", ".A.", "...", "...", ".a.", "..."}}) {
    EXPECT_EQ(fillArt(step).art, lowerCase(step));
  }
  // Type 3: one far corner of the X keeps the centre open, while the same-depth pairs around it
  // (left column, bottom row) still fill.
  const Filled diagonal = fillArt({".....", ".a.A.", ".....", ".a.a.", "....."});
  EXPECT_EQ(diagonal.art, (std::vector<std::string>{".....", ".a.a.", ".a...", ".aaa.", "....."}));
  EXPECT_EQ(diagonal.counts.type3, 0);
}

TEST(HoleFill, LeavesTheOuterBorderAlone) {
  // Type 5: around a blob, the background, the notch open to the right (columns 5 and 6 of row 2)
  // and the inner corner at (5, 2) stay empty; only the holes bounded on both sides fill.
  // clang-format off
  const Filled filled = fillArt({
      ".........",
      "..aaa....",
      "..a......",
      "..a.aaa..",
      "..aaaaa..",
      "........."});
  EXPECT_EQ(filled.art, (std::vector<std::string>{
      ".........",
      "..aaa....",
      "..aaa....",
      "..aaaaa..",
      "..aaaaa..",
      "........."}));
  // clang-format on
  EXPECT_EQ(filled.counts.type3, 1);  // (3, 2)
  EXPECT_EQ(filled.counts.type2, 1);  // (4, 2)
  EXPECT_EQ(filled.counts.type1, 1);  // (3, 3)
}

TEST(HoleFill, LeavesGapsOfThreePixelsOpen) {
  const std::vector<std::string> wide = {".......", ".a...a.", "......."};
  EXPECT_EQ(fillArt(wide).art, wide);
  const std::vector<std::string> tall = {".a.", "...", "...", "...", ".a."};
  EXPECT_EQ(fillArt(tall).art, tall);
}

TEST(HoleFill, FilledPixelsNeverBoundAnotherGap) {
  // (1, 0) fills (type 1); (1, 1) would be a type 2 gap only if that fill counted as covered.
  const Filled filled = fillArt({"a.a", "...", ".a."});
  EXPECT_EQ(filled.art, (std::vector<std::string>{"aaa", "...", ".a."}));
}

TEST(HoleFill, NeverReachesAcrossTheFrameEdge) {
  const std::vector<std::string> art = {".a", "a."};
  EXPECT_EQ(fillArt(art).art, art);
}

TEST(HoleFill, BridgeLimitIsAFixedNumberOfVoxelEdgesWhateverTheRotation) {
  // Depth 8 at zoom 1, 320x240: a voxel edge is 240 / 256 px = 0.9375 px = 30720 in Q17.15.
  for (const int yaw_degrees : {0, 30, 45, 77}) {
    Camera camera;
    camera.yaw = Angle::fromDegrees(yaw_degrees);
    camera.pitch = Angle::fromDegrees(yaw_degrees / 2);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kNone);
    EXPECT_NEAR(bridgeDepthLimit(setup), kBridgeDepthVoxelEdges * 30720, 2 * kBridgeDepthVoxelEdges)
        << "yaw " << yaw_degrees;
  }
}

TEST(HoleFill, CountsEmptyPixelsEnclosedInAllFourDirections) {
  const Framebuffer frame = frameFromArt({"aaaaa", "a.a.a", "aaaaa", "....."});
  EXPECT_EQ(countEnclosedEmptyPixels(frame, frame, 4), 2);
  EXPECT_EQ(countEnclosedEmptyPixels(frame, frame, 0), 0);
  const Framebuffer filled = frameFromArt({"aaaaa", "aaa.a", "aaaaa", "....."});
  EXPECT_EQ(countEnclosedEmptyPixels(frame, filled, 4), 1);
}

TEST(HoleFill, ClosesMostHolesOfTheDefaultModelRotatedAndZoomed) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value());
  Camera camera;
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = Q16::fromRaw(2 * Q16::kOneRaw);
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, model->finestLevel().depth, kDefaultFractionBits, &setup),
            CameraError::kNone);
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  ASSERT_TRUE(renderLevel(Variant::kFixedBaseline, model->finestLevel(), setup, frame));
  Framebuffer filled = frame;
  HoleFiller filler(frame.width());
  const HoleFillCounts counts = filler.fill(filled, bridgeDepthLimit(setup));
  const std::int32_t before = countEnclosedEmptyPixels(frame, frame, 8);
  const std::int32_t after = countEnclosedEmptyPixels(frame, filled, 8);
  EXPECT_GT(before, 1000);
  EXPECT_LT(after * 4, before) << before << " -> " << after;
  EXPECT_GE(counts.total(), before - after) << "every hole that closed was filled";
}

}  // namespace
}  // namespace octopoint
