// The render threads draw a model's levels with the sample reach it stores (docs/splats.md,
// "Samples coarser than the voxel"), as octopoint-render does: a level whose samples lie farther
// apart than its voxels is drawn with splats that wide, in the viewer as on the command line.
#include <vector>

#include "renderer/level_of_detail.h"
#include "tests/support/dual_resolution_fixture.h"

namespace octopoint::dual_resolution_testing {
namespace {

// Three footprints (Q4): wider splats change every frame where voxels reach a pixel.
constexpr std::int32_t kWideReach = 48;

TEST_F(DualResolution, BuiltFromAModelTheFineFrameHasTheLevelsStoredReach) {
  // The default model with every level's stored reach set to kWideReach.
  const EmbeddedModel& source = *models::defaultModel();
  ASSERT_EQ(source.format_version, format::kVersion6);
  std::vector<EmbeddedLevel> levels(source.levels, source.levels + source.level_count);
  for (EmbeddedLevel& level : levels) level.sample_reach = kWideReach;
  EmbeddedModel wide = source;
  wide.levels = levels.data();
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(wide, &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);

  InteractiveConfig config;
  config.initial_view.zoom = Q16::fromRaw(2 << 16);  // voxels over a pixel: the splats draw
  DualResolutionRenderer renderer(*model, clock_, config);
  ASSERT_TRUE(renderer.waitUntil(
      [](const RendererStatus& s) { return s.latest.source == FrameSource::kFine; }, kPatience));
  FrameInfo info;
  const Framebuffer* shown = renderer.acquireLatest(&info);
  ASSERT_NE(shown, nullptr);
  const LevelView* level = model->levelOfDepth(info.depth);
  ASSERT_NE(level, nullptr);
  const std::uint32_t wide_frame =
      frameChecksum(directRender(*level, info.view, config.width, config.height, kWideReach));
  const std::uint32_t one_footprint =
      frameChecksum(directRender(*level, info.view, config.width, config.height));
  ASSERT_NE(wide_frame, one_footprint) << "the reach must change this frame";
  EXPECT_EQ(frameChecksum(*shown), wide_frame);
}

}  // namespace
}  // namespace octopoint::dual_resolution_testing
