// A partly held chunked model drawn in perspective (renderer/chunked_assembly.h,
// assembleHeldParts): held whole it is one part, the model assembleChunked gives; held in part (a
// prefix of the file, cut halfway through a level's chunks) every region is drawn at the finest
// depth held there: the frame covers what the coarser levels drawn alone cover (no hole where a
// coarser level is held) and draws the held chunks of the cut level where the view asks for them.
#include <gtest/gtest.h>

#include "codegen/chunked_writer.h"
#include "octopoint/framebuffer.h"
#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "renderer/chunked_assembly.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/chunked_test_support.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

struct HeldPartsFixture {
  prepare::PreparedModel prepared =
      fuzzing::preparedModel(*models::defaultModel(), {4, 5, 6, 7, 8});
  octopoint::testing::Bytes image = prepare::serializeChunkedModel(prepared, {64, 600});
};

// An eye at the table's edge looking down at the objects (depth 8 near, coarser far), or one
// 2.5 cube edges before the cube's centre (depth 7: a depth-8 voxel spans under a pixel).
PerspectiveView heldPartsView(bool far) {
  PerspectiveCamera camera;
  camera.eye =
      far ? ModelPoint{0, 0, -kPerspectiveUnit * 5 / 2}
          : ModelPoint{kPerspectiveUnit / 10, -kPerspectiveUnit / 8, -kPerspectiveUnit * 2 / 5};
  camera.pitch = Angle::fromDegrees(far ? 0 : -25);
  camera.width = 320;
  camera.height = 240;
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  return view;
}

std::uint64_t drawParts(const HeldParts& parts, const PerspectiveView& view, Framebuffer& frame) {
  frame.clear();
  std::uint64_t leaves = 0;
  for (const std::unique_ptr<AssembledModel>& part : parts.parts) {
    PerspectiveDrawStats stats;
    EXPECT_TRUE(
        PerspectiveRenderer(*part->view, parts.detailDepths()).draw(view, {}, frame, &stats));
    leaves += stats.leaves;
  }
  return leaves;
}

TEST(HeldParts, AWholeModelIsOnePartTheAssembledModel) {
  const HeldPartsFixture f;
  const std::optional<ProgressiveModel> model = progressiveModelFromPrefix(f.image, nullptr);
  ASSERT_TRUE(model.has_value());
  const HeldParts parts = assembleHeldParts(*model);
  const std::unique_ptr<AssembledModel> whole = assembleChunked(*model);
  ASSERT_EQ(parts.parts.size(), 1u);
  ASSERT_NE(whole, nullptr);
  EXPECT_EQ(parts.parts.front()->nodes, whole->nodes);
  EXPECT_EQ(parts.parts.front()->leaves, whole->leaves);
  EXPECT_EQ(parts.detailDepths().size(), static_cast<std::size_t>(model->levelCount()));
  // And its frame is the assembled model's, bit for bit.
  const PerspectiveView view = heldPartsView(false);
  Framebuffer from_parts(320, 240), from_whole(320, 240);
  drawParts(parts, view, from_parts);
  from_whole.clear();
  ASSERT_TRUE(PerspectiveRenderer(*whole->view).draw(view, {}, from_whole));
  EXPECT_TRUE(std::equal(from_parts.pixels().begin(), from_parts.pixels().end(),
                         from_whole.pixels().begin()));
}

TEST(HeldParts, APartlyHeldLevelIsDrawnWhereHeldAndTheCoarserLevelElsewhere) {
  const HeldPartsFixture f;
  const std::optional<ProgressiveModel> whole = progressiveModelFromPrefix(f.image, nullptr);
  ASSERT_TRUE(whole.has_value());
  const ChunkedHead& head = whole->head();
  const std::unique_ptr<AssembledModel> whole_model = assembleChunked(*whole);
  ASSERT_NE(whole_model, nullptr);
  for (const bool far : {false, true}) {
    const PerspectiveView view = heldPartsView(far);
    for (int level = 1; level < head.level_count; ++level) {
      SCOPED_TRACE(std::string(far ? "far" : "near") + " view, cut in level " +
                   std::to_string(level));
      if (whole->chunkCount(level) < 2) continue;  // a level of one chunk is held or not
      const ChunkedLevel& cut_level = head.levels[static_cast<std::size_t>(level)];
      const std::size_t cut = (cut_level.chunks_offset + cut_level.chunks_end) / 2;
      const std::optional<ProgressiveModel> held =
          progressiveModelFromPrefix(std::span(f.image).first(cut), nullptr);
      ASSERT_TRUE(held.has_value());
      ASSERT_GT(held->chunksIn(ChunkState::kHeld), 0u);
      // The coarser levels alone (the complete ones), with the same detail as the parts.
      const std::unique_ptr<AssembledModel> coarse = assembleChunked(*held);
      ASSERT_NE(coarse, nullptr);
      const HeldParts parts = assembleHeldParts(*held);
      ASSERT_GE(parts.parts.size(), 2u);  // the held half of the level, the coarser rest
      Framebuffer from_parts(320, 240), from_coarse(320, 240);
      const std::uint64_t part_leaves = drawParts(parts, view, from_parts);
      from_coarse.clear();
      PerspectiveDrawStats coarse_stats;
      ASSERT_TRUE(PerspectiveRenderer(*coarse->view, parts.detailDepths())
                      .draw(view, {}, from_coarse, &coarse_stats));
      // No hole where a coarser level is held: every pixel the whole model covers, the parts
      // cover (a coarser voxel holds its finer ones, its splat theirs), and the coarser levels
      // alone cover no more than their silhouette's edges more (a coarser voxel's splat is larger).
      Framebuffer from_whole(320, 240);
      from_whole.clear();
      ASSERT_TRUE(PerspectiveRenderer(*whole_model->view).draw(view, {}, from_whole));
      std::size_t coarse_covered = 0, whole_covered = 0, lost = 0, lost_whole = 0, differ = 0;
      for (std::int32_t y = 0; y < 240; ++y) {
        for (std::int32_t x = 0; x < 320; ++x) {
          coarse_covered += from_coarse.covered(x, y);
          whole_covered += from_whole.covered(x, y);
          lost += from_coarse.covered(x, y) && !from_parts.covered(x, y);
          lost_whole += from_whole.covered(x, y) && !from_parts.covered(x, y);
          differ += from_coarse.pixelAt(x, y) != from_parts.pixelAt(x, y);
        }
      }
      ASSERT_GT(coarse_covered, 2'000u);
      EXPECT_EQ(lost_whole, 0u) << lost_whole << " of " << whole_covered;
      EXPECT_LE(lost * 40, coarse_covered) << lost << " of " << coarse_covered << " lost";
      // Where the view asks for the cut level (the near view: every level; the far one up to
      // depth 7, level 4; level 0 is the head's base), its held chunks are drawn: a different,
      // finer frame. Where it does not, the frame is the coarser levels' bit for bit (a voxel in
      // two parts draws the same).
      if (!far || level <= 4) {
        EXPECT_GT(differ, 1000u);
        EXPECT_GT(part_leaves, coarse_stats.leaves);
      } else {
        EXPECT_EQ(differ, 0u);
      }
    }
  }
}

}  // namespace
}  // namespace octopoint
