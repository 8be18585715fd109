// The sample reach stored in the model and used (docs/splats.md, "Samples coarser than the
// voxel"): an airborne-like scan on a 1 m grid of scan lines, prepared and written as a `.oct` file
// by the preparer's code, drawn by the octopoint-render program at depth 8 (0.88 m voxels, finer
// than the samples). With the reach the file stores, at most 1% of the surface the coarsest depth
// covers is left empty; the same file with that reach byte set to one footprint shows the grid of
// empty lines (so the program must read the stored reach for the test to pass).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/level_of_detail.h"
#include "tests/support/airborne_scans.h"

namespace octopoint {
namespace {

namespace fs = std::filesystem;

constexpr int kCoarseDepth = 6;  // 3.5 m voxels: every one of them sampled
constexpr int kFineDepth = 8;    // 0.88 m voxels under 1 m samples: the grid of empty lines

struct DrawnCover {
  int width = 0, height = 0;
  std::vector<bool> covered;  // per pixel: not octopoint-render's background
};

// octopoint-render's picture of `model` at `depth`, 640x480, as covered pixels.
DrawnCover renderedCover(const fs::path& model, int depth, const fs::path& png) {
  const std::string command = std::string(OCTOPOINT_RENDER_PROGRAM) + " --file " + model.string() +
                              " --depth " + std::to_string(depth) + " --size 640x480 -o " +
                              png.string() + " > /dev/null";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  const cv::Mat bgr = cv::imread(png.string(), cv::IMREAD_COLOR);
  DrawnCover cover{.width = bgr.cols, .height = bgr.rows, .covered = {}};
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b pixel = bgr.at<cv::Vec3b>(y, x);  // the background is RGB (236, 236, 240)
      cover.covered.push_back(!(pixel[0] == 240 && pixel[1] == 236 && pixel[2] == 236));
    }
  }
  return cover;
}

// Per mille of the coarse level's surface (less a border of one coarse voxel, whose cubes reach
// past the ground's edge) that `fine` leaves empty.
int openPerMille(const DrawnCover& coarse, const DrawnCover& fine) {
  const int border = (std::min(coarse.width, coarse.height) >> kCoarseDepth) + 1;
  const auto at = [&](int x, int y) { return static_cast<std::size_t>(y * coarse.width + x); };
  std::size_t surface = 0, open = 0;
  for (int y = border; y < coarse.height - border; ++y) {
    for (int x = border; x < coarse.width - border; ++x) {
      bool inside = true;
      for (int dy = -border; dy <= border && inside; dy += border) {
        for (int dx = -border; dx <= border && inside; dx += border)
          inside = coarse.covered[at(x + dx, y + dy)];
      }
      if (!inside) continue;
      ++surface;
      if (!fine.covered[at(x, y)]) ++open;
    }
  }
  return surface == 0 ? 1000 : static_cast<int>(open * 1000 / surface);
}

TEST(StoredSampleReach, OctopointRenderDrawsTheAirborneGridWithoutItsEmptyLines) {
  prepare::PrepareOptions options;
  options.name = "airborne_grid";
  options.depths = {kCoarseDepth, 7, kFineDepth};
  const prepare::PreparedModel prepared = prepare::prepareModel(
      testing::airborneScan(testing::AirborneSampling::kGrid, 1.0, 7), "airborne.ply", options);
  std::vector<std::uint8_t> image = prepare::serializeModel(prepared);
  const fs::path folder = fs::path(::testing::TempDir()) / "stored_sample_reach";
  fs::create_directories(folder);
  const fs::path model = folder / "airborne_grid.oct";
  const auto write = [&] {
    std::ofstream(model, std::ios::binary)
        .write(reinterpret_cast<const char*>(image.data()),
               static_cast<std::streamsize>(image.size()));
  };
  write();

  ModelIssue issue;
  const std::optional<ModelView> view = ModelView::fromBytes(image, &issue);
  ASSERT_TRUE(view) << describe(issue.error);
  ASSERT_EQ(view->formatVersion(), format::kVersion6);
  EXPECT_EQ(view->sampleReachOfDepth(kCoarseDepth), kOneSampleReach);
  const std::int32_t stored = view->sampleReachOfDepth(kFineDepth);
  EXPECT_GT(stored, kOneSampleReach);  // 1 m samples under 0.88 m voxels

  // Depth auto takes depth 8 where its voxels are over a pixel (1.9 at 640x480): it has 2.99 times
  // depth 7's voxels, under the dense rule's 3, but its stored reach draws it whole.
  Camera camera;
  camera.width = 640;
  camera.height = 480;
  ASSERT_NE(autoLevel(*view, camera), nullptr);
  EXPECT_EQ(autoLevel(*view, camera)->depth, kFineDepth);

  const DrawnCover coarse = renderedCover(model, kCoarseDepth, folder / "coarse.png");
  const DrawnCover fine = renderedCover(model, kFineDepth, folder / "fine.png");
  ASSERT_EQ(fine.covered.size(), coarse.covered.size());
  const int open = openPerMille(coarse, fine);
  EXPECT_LE(open, 10) << "reach " << stored << "/16";

  // The same file with depth 8's reach byte (its level table row's byte 1) at one footprint.
  const std::size_t table_at = format::v2::kNormalPaletteOffset + format::kCubePlacementBytes;
  const std::size_t row = table_at + format::kLevelRowBytes * 2;
  ASSERT_EQ(image[row], kFineDepth);
  image[row + 1] = format::kOneSampleReachQ4;
  write();
  const int unwidened = openPerMille(coarse, renderedCover(model, kFineDepth, folder / "one.png"));
  std::printf(
      "airborne grid, depth %d, 640x480: reach %d/16 leaves %d.%d%% open, one footprint "
      "%d.%d%%\n",
      kFineDepth, stored, open / 10, open % 10, unwidened / 10, unwidened % 10);
  EXPECT_GT(unwidened, 10);
}

}  // namespace
}  // namespace octopoint
