// The preparer's pipeline on synthetic scans with known answers, drawn by the real renderer.
#include "codegen/prepare.h"

#include <gtest/gtest.h>

#include <map>

#include "codegen/cube_fit.h"
#include "codegen/model_writer.h"
#include "codegen/palette.h"
#include "codegen/prepare_error.h"
#include "octopoint/framebuffer.h"
#include "octopoint/render.h"
#include "tests/support/synthetic_scans.h"

namespace octopoint {
namespace {

using prepare::Rgb8;

constexpr Rgb8 kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kYellow{255, 255, 0},
    kWhite{255, 255, 255};
constexpr Rgb kBackground{1, 2, 3};

// Five points on the corners and edges of the unit cube: at depth 2 they fall in voxels
// (0,0,0) red, (3,3,3) blue, (3,0,2) green, (0,3,0) white, and (0,0,3) yellow, which hides
// behind red when seen from the front.
prepare::Scan fivePointScan() {
  prepare::Scan scan;
  scan.shading = prepare::ScanShading::kColour;
  scan.positions = {{0, 0, 0}, {1, 1, 1}, {1, 0, 0.5f}, {0, 1, 0}, {0, 0, 1}};
  scan.colours = {kRed, kBlue, kGreen, kWhite, kYellow};
  scan.points_in_file = 5;
  return scan;
}

// Prepares, serializes, validates and draws: the whole path a user's `.oct` file takes.
std::vector<Rgb> renderThroughOctFile(const prepare::Scan& scan, int depth, const Camera& camera) {
  prepare::PrepareOptions options;
  options.name = "synthetic";
  options.depths = {depth};
  const std::vector<std::uint8_t> image =
      prepare::serializeModel(prepare::prepareModel(scan, "synthetic.pcd", options));
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromBytes(image, &issue);
  EXPECT_TRUE(model.has_value()) << describe(issue.error);
  if (!model) return {};
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, depth, kDefaultFractionBits, &setup), CameraError::kNone);
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  EXPECT_TRUE(renderLevel(Variant::kFixedBaseline, model->finestLevel(), setup, frame));
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width * camera.height) * 3);
  EXPECT_TRUE(resolveToRgb(frame, *model, kBackground, rgb));
  std::vector<Rgb> pixels;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    pixels.push_back({rgb[i], rgb[i + 1], rgb[i + 2]});
  return pixels;
}

Rgb rgb(const Rgb8& c) { return {c[0], c[1], c[2]}; }

std::vector<Rgb> expectedFrame(int width, const std::map<std::pair<int, int>, Rgb8>& lit,
                               int height) {
  std::vector<Rgb> pixels(static_cast<std::size_t>(width * height), kBackground);
  for (const auto& [xy, colour] : lit)
    pixels[static_cast<std::size_t>(xy.second * width + xy.first)] = rgb(colour);
  return pixels;
}

TEST(PrepareAndRender, FivePointScanFromTheFrontLightsExactlyTheExpectedPixels) {
  Camera camera;
  camera.width = camera.height = 4;  // one pixel per voxel at depth 2
  const auto expected =
      expectedFrame(4, {{{0, 0}, kRed}, {{3, 3}, kBlue}, {{3, 0}, kGreen}, {{0, 3}, kWhite}}, 4);
  EXPECT_TRUE(renderThroughOctFile(fivePointScan(), 2, camera) == expected);
}

TEST(PrepareAndRender, FivePointScanFromBehindShowsTheHiddenPointMirrored) {
  Camera camera;
  camera.width = camera.height = 4;
  camera.yaw = Angle::fromDegrees(180);  // x and z flip: yellow is now in front of red
  const auto expected =
      expectedFrame(4, {{{3, 0}, kYellow}, {{0, 3}, kBlue}, {{0, 0}, kGreen}, {{3, 3}, kWhite}}, 4);
  EXPECT_TRUE(renderThroughOctFile(fivePointScan(), 2, camera) == expected);
}

TEST(PrepareAndRender, ZoomHalfWithPanMergesNeighbouringVoxelsIntoOnePixel) {
  Camera camera;
  camera.width = camera.height = 4;
  camera.zoom =
      Q16::fromRaw(Q16::kOneRaw / 2);  // the cube spans 2 pixels: voxels half a pixel apart
  camera.pan_x_px = 1;
  // Voxel i lands on pixel floor(2 + 0.5 * (i + 0.5 - 2)) = 1, 1, 2, 2 for i = 0..3, plus the pan.
  const auto expected =
      expectedFrame(4, {{{2, 1}, kRed}, {{2, 2}, kWhite}, {{3, 1}, kGreen}, {{3, 2}, kBlue}}, 4);
  EXPECT_TRUE(renderThroughOctFile(fivePointScan(), 2, camera) == expected);
}

TEST(PrepareModel, KeepsEveryDistinctColourExactlyWhenThereAreFewerThan256) {
  prepare::PrepareOptions options;
  options.name = "sphere";
  options.depths = {4, 6};
  const prepare::PreparedModel model =
      prepare::prepareModel(testing::colouredSphere(5000), "sphere.pcd", options);
  EXPECT_EQ(model.palette.size(), 8u);
  ASSERT_EQ(model.levels.size(), 2u);
  EXPECT_EQ(model.levels[0].depth, 4);
  EXPECT_LT(model.levels[0].leaves.size(), model.levels[1].leaves.size());
}

TEST(PrepareModel, RefusesPointsThatAreAllIdentical) {
  prepare::Scan scan;
  scan.positions.assign(10, {0.5f, 0.5f, 0.5f});
  scan.points_in_file = 10;
  prepare::PrepareOptions options;
  options.name = "dot";
  try {
    prepare::prepareModel(scan, "dot.pcd", options);
    FAIL() << "identical points were accepted";
  } catch (const prepare::PrepareError& error) {
    EXPECT_NE(std::string(error.what()).find("dot.pcd: all 10 points are at the same position"),
              std::string::npos)
        << error.what();
  }
}

TEST(Palette, ReducesManyColoursTo256WithSmallError) {
  const prepare::Scan cloud = testing::randomCloud(20000, 7);
  const prepare::Palette palette = prepare::Palette::build(cloud.colours);
  EXPECT_EQ(palette.colours().size(), 256u);
  double squared_error = 0;
  for (const Rgb8& colour : cloud.colours) {
    const Rgb8& chosen = palette.colours()[palette.indexOf(colour)];
    for (std::size_t ch = 0; ch < 3; ++ch)
      squared_error += (colour[ch] - chosen[ch]) * (colour[ch] - chosen[ch]);
  }
  // Uniform random RGB cut into 256 cells of about 40^3: RMS error per channel near 12.
  EXPECT_LT(std::sqrt(squared_error / (3.0 * static_cast<double>(cloud.colours.size()))), 16.0);
}

TEST(Palette, HonoursASmallerColourCount) {
  const prepare::Palette palette =
      prepare::Palette::build(testing::randomCloud(2000, 3).colours, 16);
  EXPECT_EQ(palette.colours().size(), 16u);
}

TEST(CubeFit, CentresTheBoundingBoxInACubeOfItsLongestSide) {
  const std::vector<std::array<float, 3>> points = {{0, 0, 0}, {4, 2, 1}};
  const prepare::CubeFit fit = prepare::fitCube(points, "box.pcd");
  EXPECT_DOUBLE_EQ(fit.edge, 4.0);
  EXPECT_DOUBLE_EQ(fit.origin[1], -1.0);
  EXPECT_DOUBLE_EQ(fit.origin[2], -1.5);
  EXPECT_EQ(prepare::voxelIndex(4.0, fit.origin[0], fit.edge, 3), 7u);  // the far face is inside
  EXPECT_EQ(prepare::voxelIndex(0.0, fit.origin[0], fit.edge, 3), 0u);
}

}  // namespace
}  // namespace octopoint
