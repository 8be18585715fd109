// The line pass (octopoint/styles.h) on frames built by hand: silhouettes exactly where a depth
// step or the object's outline is, one pixel wide on the nearer side; creases between normals
// further apart than the angle and nowhere else, and not beside a silhouette that already draws
// them; rows styled in bands exactly as in one piece.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/styles.h"

namespace octopoint {
namespace {

// A model with three normals: +z, +x, and one 30 degrees from +z toward +x. Depth 1, one leaf.
struct ThreeNormals {
  std::array<std::uint8_t, 768> palette{};
  std::uint8_t nodes[1] = {0x01};
  std::uint8_t leaves[1] = {0};
  std::uint8_t normals[1] = {0};
  std::int16_t normal_xyz[9] = {0, 0, 16384, 16384, 0, 0, 8192, 0, 14189};  // 14189 = 16384 cos 30
  EmbeddedLevel level{1, nodes, 1, leaves, 1, normals};
  EmbeddedModel model{
      "three", format::kVersion2, format::v2::kFlagNormals, 0, 1, palette.data(), 3, normal_xyz, 1,
      &level};

  ModelView view() const {
    ModelIssue issue;
    const auto v = ModelView::fromEmbedded(model, &issue);
    EXPECT_TRUE(v.has_value()) << describe(issue.error);
    return *v;
  }
};

constexpr std::uint32_t kJump = 100;  // in the units of word >> 16

std::uint32_t word(std::uint32_t depth, std::uint32_t normal) {
  return Framebuffer::packColourNormal(depth << 8, normal << 8);  // depth in units of word >> 16
}

// '.' none, 'S' silhouette, 'C' crease, ' ' background.
std::vector<std::string> classes(const Framebuffer& frame, const EdgeRule& rule) {
  std::vector<std::string> rows;
  const std::uint32_t* pixels = frame.pixels().data();
  for (std::int32_t y = 0; y < frame.height(); ++y) {
    std::string row;
    const std::uint32_t* line = pixels + y * frame.width();
    for (std::int32_t x = 0; x < frame.width(); ++x) {
      if (line[x] == Framebuffer::kEmpty) {
        row += ' ';
        continue;
      }
      const Edge edge = classifyPixel(frame, x, y, rule);
      row += edge == Edge::kSilhouette ? 'S' : edge == Edge::kCrease ? 'C' : '.';
    }
    rows.push_back(row);
  }
  return rows;
}

// Fills `frame` from a picture: a digit d is depth 1000 + 1000 * d with normal 0; letters a-c are
// depth 1000 with normal 0-2; ' ' is empty.
void paint(Framebuffer& frame, const std::vector<std::string>& picture) {
  frame.clear(PixelPayload::kColourNormal);
  for (std::size_t y = 0; y < picture.size(); ++y) {
    for (std::size_t x = 0; x < picture[y].size(); ++x) {
      const char c = picture[y][x];
      if (c == ' ') continue;
      const std::uint32_t w = c >= 'a' ? word(1000, static_cast<std::uint32_t>(c - 'a'))
                                       : word(1000 + 1000 * static_cast<std::uint32_t>(c - '0'), 0);
      frame.pixelData()[y * static_cast<std::size_t>(frame.width()) + x] = w;
    }
  }
}

TEST(Edges, ASilhouetteRunsExactlyAlongTheNearerSideOfADepthStep) {
  Framebuffer frame(8, 4);
  paint(frame, {"00001111", "00001111", "00011111", "00011111"});
  const EdgeRule rule{kJump, 16, nullptr};
  // The near pixels with a far 4-neighbour, and no other.
  EXPECT_EQ(classes(frame, rule),
            (std::vector<std::string>{"...S....", "...S....", "..S.....", "..S....."}));
}

TEST(Edges, ADepthChangeWithinTheJumpIsNoSilhouette) {
  Framebuffer frame(4, 1);
  frame.clear(PixelPayload::kColourNormal);
  frame.pixelData()[0] = frame.pixelData()[1] = word(1000, 0);
  frame.pixelData()[2] = frame.pixelData()[3] =
      word(1000 + kJump, 0);  // exactly the jump: a surface
  EXPECT_EQ(classes(frame, {kJump, 16, nullptr}), (std::vector<std::string>{"...."}));
  frame.pixelData()[2] = word(1000 + kJump + 1, 0);  // one more: a step
  EXPECT_EQ(classes(frame, {kJump, 16, nullptr}), (std::vector<std::string>{".S.."}));
}

TEST(Edges, ASteepSurfaceRecedesByItsSlopeWithoutSilhouettesAndAStepBeyondIsOne) {
  const ThreeNormals normals;
  const ModelView model = normals.view();
  Camera camera;  // yaw 0: view axes are the model's, normal 2 recedes tan 30 pixels per pixel in x
  camera.width = 40;
  camera.height = 30;
  FrameSetup setup;
  ASSERT_EQ(buildFrameSetup(camera, 3, kDefaultFractionBits, &setup), CameraError::kNone);
  ASSERT_TRUE(setup.splat.active());  // 30 / 2^3 = 3.75-pixel voxels
  SurfaceSlopes slopes;
  slopes.build(model, setup);
  // One pixel of depth in the units of word >> 16, and the reach: footprint + 1 pixels.
  const double pixel = static_cast<double>((1 << setup.fraction_bits) >> setup.depth_shift) / 256;
  const double reach_x = (setup.splat.columns + 1) * pixel;
  const double reach = std::max(setup.splat.columns, setup.splat.rows) * pixel + pixel;
  const double edge = static_cast<double>(voxelEdgeOnScreen(setup) >> setup.depth_shift) / 256;
  const double cos30 = std::cos(3.14159265358979 / 6);  // normal 2: 30 degrees from the view axis
  EXPECT_NEAR(slopes.slack(2, 2), (0.5 * reach_x + (1 - cos30) * edge) / cos30, 1.0);
  EXPECT_NEAR(slopes.slack(1, 1), kMaxSurfaceSlope * (reach + edge), 1.0);  // edge-on: capped
  EXPECT_EQ(slopes.slack(0, 0), 0u);                                        // facing the viewer
  EXPECT_EQ(slopes.slack(0, 2), 0u);  // a pair has the smaller slack of its two pixels
  EXPECT_EQ(slopes.slack(1, 2), slopes.slack(2, 2));

  const EdgeRule rule = edgeRuleFor(setup, PixelPayload::kColourNormal, nullptr, &slopes);
  const std::uint32_t slack = slopes.slack(2, 2);
  ASSERT_GT(slack, 10u);
  // A row of normal-2 pixels receding by exactly jump + slack per pixel: a surface, no line; the
  // same steps on a surface facing the viewer (normal 0) outline every pixel but the last.
  Framebuffer frame(4, 1);
  for (const std::uint32_t n : {2u, 0u}) {
    frame.clear(PixelPayload::kColourNormal);
    for (std::uint32_t x = 0; x < 4; ++x)
      frame.pixelData()[x] = word(1000 + x * (rule.jump + slack), n);
    EXPECT_EQ(classes(frame, rule), (std::vector<std::string>{n == 2 ? "...." : "SSS."}))
        << "normal " << n;
  }
  // One key more than the slope explains is a step.
  frame.clear(PixelPayload::kColourNormal);
  frame.pixelData()[0] = frame.pixelData()[1] = word(1000, 2);
  frame.pixelData()[2] = frame.pixelData()[3] = word(1000 + rule.jump + slack + 1, 2);
  EXPECT_EQ(classes(frame, rule), (std::vector<std::string>{".S.."}));
  // Along y too (the voxels two pixels show may lie apart along x whichever way they neighbour).
  Framebuffer column(1, 3);
  column.clear(PixelPayload::kColourNormal);
  column.pixelData()[0] = word(1000, 2);
  column.pixelData()[1] = word(1000 + rule.jump + slack, 2);
  column.pixelData()[2] = word(1000 + 2 * (rule.jump + slack) + 1, 2);
  EXPECT_EQ(classes(column, rule), (std::vector<std::string>{".", "S", "."}));
  // Without slopes (colour frames, or a rule built without them) the jump alone decides.
  frame.pixelData()[2] = frame.pixelData()[3] = word(1000 + rule.jump + 1, 2);
  EXPECT_EQ(classes(frame, {rule.jump, 16, nullptr, nullptr}), (std::vector<std::string>{".S.."}));
}

TEST(Edges, TheOutlineAgainstTheBackgroundIsOnePixelInsideAndTheFrameEdgeIsNone) {
  Framebuffer frame(7, 5);
  paint(frame, {"00000  ", "00000  ", "000    ", "000    ", "000    "});
  EXPECT_EQ(classes(frame, {kJump, 16, nullptr}),
            (std::vector<std::string>{"....S  ", "...SS  ", "..S    ", "..S    ", "..S    "}));
}

TEST(Edges, CreasesAppearBetweenNormalsFurtherApartThanTheAngleOnly) {
  const ThreeNormals normals;
  const ModelView model = normals.view();
  CreaseTable creases;
  creases.build(model, Angle::fromDegrees(60));
  EXPECT_TRUE(creases.crease(0, 1));   // 90 degrees
  EXPECT_FALSE(creases.crease(0, 2));  // 30 degrees
  EXPECT_FALSE(creases.crease(1, 2));  // exactly 60 degrees: not more than the angle
  EXPECT_FALSE(creases.crease(1, 1));
  Framebuffer frame(6, 2);
  paint(frame, {"aaabbb", "aacccc"});
  // Equal depths: the left (upper) pixel of each pair draws; a-c is 30 degrees: no crease.
  EXPECT_EQ(classes(frame, {kJump, 16, &creases}), (std::vector<std::string>{"..C...", "......"}));
}

TEST(Edges, TheNearerPixelOfACreaseDrawsIt) {
  const ThreeNormals normals;
  CreaseTable creases;
  creases.build(normals.view(), Angle::fromDegrees(60));
  Framebuffer frame(4, 1);
  frame.clear(PixelPayload::kColourNormal);
  frame.pixelData()[0] = frame.pixelData()[1] = word(1000, 0);
  frame.pixelData()[2] = frame.pixelData()[3] = word(990, 1);  // nearer, other normal
  EXPECT_EQ(classes(frame, {kJump, 16, &creases}), (std::vector<std::string>{"..C."}));
}

TEST(Edges, ACreaseWhoseOtherPixelIsASilhouetteIsLeftToTheSilhouette) {
  const ThreeNormals normals;
  CreaseTable creases;
  creases.build(normals.view(), Angle::fromDegrees(60));
  // A face (normal 1) whose outermost pixel, at (1, 1), shows a voxel of the face turned away
  // (normal 0, 90 degrees off, a little farther): that pixel is the outline; its crease with the
  // face is not drawn again beside it. The same pair away from the outline is a crease.
  Framebuffer frame(6, 3);
  frame.clear(PixelPayload::kColourNormal);
  std::uint32_t* pixels = frame.pixelData();
  for (std::size_t i = 0; i < 18; ++i) pixels[i] = word(1000, 1);
  pixels[6] = Framebuffer::kEmpty;
  pixels[7] = word(1005, 0);
  EXPECT_EQ(classes(frame, {kJump, 16, &creases}),
            (std::vector<std::string>{"S.....", " S....", "S....."}));
  pixels[6] = word(1000, 1);  // no outline there any more: the pixel is a crease's other pixel
  EXPECT_EQ(classes(frame, {kJump, 16, &creases}),
            (std::vector<std::string>{".C....", "C.C...", ".C...."}));
}

TEST(Edges, StylingRowsInBandsGivesTheWholeFramesPixels) {
  const ThreeNormals normals;
  const ModelView model = normals.view();
  Framebuffer frame(9, 7);
  paint(frame, {"  000111 ", " aabbb11 ", "aaccc111 ", "aaacc2222", "  0001222", "  00  12 ",
                "    a    "});
  FrameSetup setup;
  Camera camera;
  camera.width = 9;
  camera.height = 7;
  ASSERT_EQ(buildFrameSetup(camera, 1, kDefaultFractionBits, &setup), CameraError::kNone);
  FrameStyler styler(model);
  for (const StyleInfo& info : allStyles()) {
    ASSERT_EQ(styler.setOptions({info.style, {}, Angle::fromDegrees(60), {1, 2, 3}}),
              StyleError::kNone);
    styler.beginFrame(setup);
    std::vector<std::uint8_t> whole(9 * 7 * 3), bands(9 * 7 * 3);
    ASSERT_EQ(styler.resolve(frame, whole), StyleError::kNone);
    for (std::int32_t first = 0; first < 7; first += 3) {
      const std::int32_t end = std::min(first + 3, 7);
      ASSERT_EQ(styler.resolveRows(frame, first, end,
                                   std::span(bands).subspan(static_cast<std::size_t>(first) * 27)),
                StyleError::kNone);
    }
    EXPECT_EQ(whole, bands) << info.name;
  }
}

TEST(FrameStyler, RefusesWhatItCannotDraw) {
  const ThreeNormals normals;
  const ModelView model = normals.view();
  FrameStyler styler(model);
  Framebuffer frame(4, 4);
  frame.clear();  // no normals in the words
  std::vector<std::uint8_t> rgb(4 * 4 * 3);
  ASSERT_EQ(styler.setOptions({Style::kShaded, {}, Angle::fromDegrees(60), {}}), StyleError::kNone);
  EXPECT_EQ(styler.payload(), PixelPayload::kColourNormal);
  EXPECT_EQ(styler.resolve(frame, rgb), StyleError::kFrameWithoutNormals);
  frame.clear(PixelPayload::kColourNormal);
  EXPECT_EQ(styler.resolve(frame, std::span(rgb).first(47)), StyleError::kFrameSizeMismatch);
  EXPECT_EQ(styler.resolveRows(frame, 2, 5, rgb), StyleError::kFrameSizeMismatch);
  EXPECT_EQ(styler.resolve(frame, rgb), StyleError::kNone);

  std::array<std::uint8_t, 768> palette{};
  const std::uint8_t nodes[] = {0x01};
  const std::uint8_t leaves[] = {0};
  const EmbeddedLevel level{1, nodes, 1, leaves, 1, nullptr};
  const EmbeddedModel plain{"plain", format::kVersion2, 0, 0,     1, palette.data(),
                            0,       nullptr,           1, &level};
  ModelIssue issue;
  const ModelView without = *ModelView::fromEmbedded(plain, &issue);
  FrameStyler colour_only(without);
  for (const StyleInfo& info : allStyles()) {
    EXPECT_EQ(colour_only.setOptions({info.style, {}, Angle::fromDegrees(60), {}}),
              info.style == Style::kColour ? StyleError::kNone : StyleError::kNeedsNormals)
        << info.name;
  }
  EXPECT_EQ(colour_only.options().style, Style::kColour);  // a refused style changes nothing
}

}  // namespace
}  // namespace octopoint
