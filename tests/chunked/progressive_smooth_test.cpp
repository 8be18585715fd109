// Smooth splats over the progressive model (ProgressiveModel::drawSmooth): holding every chunk a
// view needs, the blended frame and its colours are renderSmooth's of the whole model's stream at
// the depth drawn, bit for bit; where voxels are at most a pixel it is draw's box frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "codegen/model_writer.h"
#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "octopoint/smooth.h"
#include "tests/support/chunked_test_support.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

struct SmoothProgressiveFixture {
  prepare::PreparedModel prepared =
      fuzzing::preparedModel(*models::defaultModel(), {4, 5, 6, 7, 8});
  octopoint::testing::Bytes image = prepare::serializeChunkedModel(prepared, {64, 600});
  std::vector<prepare::PreparedLevel> streams = octopoint::testing::levelStreams(image, prepared);
};

const SmoothProgressiveFixture& smoothProgressiveFixture() {
  static const SmoothProgressiveFixture fixture;
  return fixture;
}

PaletteRgb smoothProgressivePalette() {
  PaletteRgb palette{};
  for (std::size_t i = 0; i < palette.size(); ++i) {
    palette[i] = {static_cast<std::uint8_t>(i * 37), static_cast<std::uint8_t>(i * 91 + 40),
                  static_cast<std::uint8_t>(255 - i * 13)};
  }
  return palette;
}

TEST(ProgressiveSmooth, HoldingEverythingBlendsTheWholeModelStreamsFrame) {
  const SmoothProgressiveFixture& f = smoothProgressiveFixture();
  ChunkedIssue issue;
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(f.image, &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  const PaletteRgb palette = smoothProgressivePalette();
  ProgressiveFrame snapshot;
  int blended = 0;
  for (const Camera& camera : {octopoint::testing::makeCamera(30, -20, 3, 320, 240),
                               octopoint::testing::makeCamera(15, 5, 6, 320, 240, 40, -30),
                               octopoint::testing::makeCamera(-60, 10, 4, 200, 150),
                               octopoint::testing::makeCamera(0, 0, 1, 320, 240)}) {
    ASSERT_TRUE(model->viewComplete(camera));
    const int wanted = *model->wantedDepth(camera);
    const prepare::PreparedLevel* level = octopoint::testing::finestLevelAtMost(f.streams, wanted);
    ASSERT_NE(level, nullptr);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup),
              CameraError::kNone);
    blended += voxelEdgeOnScreen(setup) > (std::uint64_t{1} << setup.fraction_bits) ? 1 : 0;
    const std::size_t bytes = static_cast<std::size_t>(camera.width * camera.height) * 3;
    Framebuffer expected(setup);
    expected.clear();
    SmoothSplats whole(setup);
    ASSERT_TRUE(renderSmooth(Variant::kFixedFast,
                             LevelView{level->depth, level->nodes, level->leaves}, setup, expected,
                             whole, palette));
    std::vector<std::uint8_t> expected_rgb(bytes), rgb(bytes);
    ASSERT_TRUE(whole.resolveToRgb(expected, palette, Rgb{}, expected_rgb));

    Framebuffer frame(setup);
    frame.clear();
    SmoothSplats smooth(setup);
    model->snapshot(snapshot);
    ASSERT_TRUE(model->drawSmooth(snapshot, camera, Variant::kFixedFast, frame, smooth, palette));
    ASSERT_TRUE(smooth.resolveToRgb(frame, palette, Rgb{}, rgb));
    EXPECT_TRUE(octopoint::testing::sameFrame(frame, expected)) << "depth " << level->depth;
    EXPECT_TRUE(rgb == expected_rgb) << "depth " << level->depth;
  }
  EXPECT_EQ(blended, 3);
}

}  // namespace
}  // namespace octopoint
