// A chunked model spliced back into one model (renderer/chunked_assembly.h): held whole, its
// depths are the very streams the one-file model holds, byte for byte, and so its perspective
// frames are that model's; held in part (a prefix of the file), the base and the complete levels
// only, each again the one-file stream.
#include "renderer/chunked_assembly.h"

#include <gtest/gtest.h>

#include "codegen/chunked_writer.h"
#include "codegen/level_voxels.h"
#include "codegen/model_writer.h"
#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/chunked_test_support.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

// The default model at depths 4..8, in small chunks; `thin`: with whole chunks of depth 8 that
// hold no voxel (as visibility pruning leaves them), which the splice must leave out.
struct AssemblyFixture {
  explicit AssemblyFixture(bool thin) {
    prepared = fuzzing::preparedModel(*models::defaultModel(), {4, 5, 6, 7, 8});
    if (thin) {
      prepare::LevelVoxels finest = prepare::decodeLevel(prepared.levels.back());
      prepare::LevelVoxels kept{finest.depth, {}, {}};
      for (std::size_t i = 0; i < finest.keys.size(); ++i) {
        if ((finest.keys[i] >> 12) % 5 == 2) continue;  // every fifth depth-4 cell emptied
        kept.keys.push_back(finest.keys[i]);
        kept.colours.push_back(finest.colours[i]);
      }
      prepared.levels.back() = prepare::encodeLevel(kept);
    }
    image = prepare::serializeChunkedModel(prepared, {64, 600});
    streams = octopoint::testing::levelStreams(image, prepared);
  }
  prepare::PreparedModel prepared;
  octopoint::testing::Bytes image;
  std::vector<prepare::PreparedLevel> streams;
};

void expectLevels(const AssembledModel& assembled,
                  const std::vector<prepare::PreparedLevel>& streams, std::size_t count) {
  ASSERT_EQ(assembled.nodes.size(), count);
  ASSERT_EQ(assembled.view->levelCount(), static_cast<int>(count));
  for (std::size_t i = 0; i < count; ++i) {
    EXPECT_EQ(assembled.view->level(static_cast<int>(i)).depth, streams[i].depth);
    EXPECT_EQ(assembled.nodes[i], streams[i].nodes) << "depth " << streams[i].depth;
    EXPECT_EQ(assembled.leaves[i], streams[i].leaves) << "depth " << streams[i].depth;
  }
}

class ChunkedAssembly : public ::testing::TestWithParam<bool> {};

TEST_P(ChunkedAssembly, AWholeChunkedModelIsTheOneFileModelStreamForStream) {
  const AssemblyFixture f(GetParam());
  ChunkedIssue issue;
  const std::optional<ProgressiveModel> model = progressiveModelFromPrefix(f.image, &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  const std::unique_ptr<AssembledModel> assembled = assembleChunked(*model);
  ASSERT_NE(assembled, nullptr);
  expectLevels(*assembled, f.streams, f.streams.size());
  EXPECT_EQ(assembled->view->cubePlacement().recorded(), f.prepared.cube.recorded());
}

TEST_P(ChunkedAssembly, APrefixKeepsTheBaseAndTheCompleteLevelsOnly) {
  const AssemblyFixture f(GetParam());
  ChunkedIssue issue;
  const std::optional<ProgressiveModel> whole = progressiveModelFromPrefix(f.image, &issue);
  ASSERT_TRUE(whole.has_value());
  const ChunkedHead& head = whole->head();
  for (int level = 1; level < head.level_count; ++level) {
    // Cut halfway through the level's chunks: the levels before it are whole, it is not.
    const ChunkedLevel& cut_level = head.levels[static_cast<std::size_t>(level)];
    const std::size_t cut = (cut_level.chunks_offset + cut_level.chunks_end) / 2;
    const std::optional<ProgressiveModel> part =
        progressiveModelFromPrefix(std::span(f.image).first(cut), &issue);
    ASSERT_TRUE(part.has_value());
    const std::unique_ptr<AssembledModel> assembled = assembleChunked(*part);
    ASSERT_NE(assembled, nullptr);
    SCOPED_TRACE("cut in level " + std::to_string(level));
    expectLevels(*assembled, f.streams, static_cast<std::size_t>(level));
  }
}

// The frames the same streams give: a view from inside the cube by distance over every depth,
// drawn from the spliced model and from the one-file model, bit for bit.
TEST_P(ChunkedAssembly, ItsPerspectiveFrameIsTheOneFileModelsFrame) {
  const AssemblyFixture f(GetParam());
  const std::optional<ProgressiveModel> model = progressiveModelFromPrefix(f.image, nullptr);
  ASSERT_TRUE(model.has_value());
  const std::unique_ptr<AssembledModel> assembled = assembleChunked(*model);
  ASSERT_NE(assembled, nullptr);
  const octopoint::testing::Bytes one_file = prepare::serializeModel(f.prepared);
  ModelIssue issue;
  const std::optional<ModelView> single = ModelView::fromBytes(one_file, &issue);
  ASSERT_TRUE(single.has_value()) << describe(issue.error);
  PerspectiveCamera camera;
  camera.eye = {kPerspectiveUnit / 10, -kPerspectiveUnit / 8, -kPerspectiveUnit * 2 / 5};
  camera.pitch = Angle::fromDegrees(-25);
  camera.width = 320;
  camera.height = 240;
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  Framebuffer from_chunks(320, 240), from_file(320, 240);
  from_chunks.clear();
  from_file.clear();
  PerspectiveDrawStats chunk_stats, file_stats;
  ASSERT_TRUE(PerspectiveRenderer(*assembled->view).draw(view, {}, from_chunks, &chunk_stats));
  ASSERT_TRUE(PerspectiveRenderer(*single).draw(view, {}, from_file, &file_stats));
  EXPECT_GT(chunk_stats.leaves, 1000u);
  EXPECT_EQ(chunk_stats.leaves, file_stats.leaves);
  EXPECT_TRUE(std::equal(from_chunks.pixels().begin(), from_chunks.pixels().end(),
                         from_file.pixels().begin()));
}

INSTANTIATE_TEST_SUITE_P(WholeAndThinned, ChunkedAssembly, ::testing::Bool());

}  // namespace
}  // namespace octopoint
