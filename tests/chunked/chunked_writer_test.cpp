// The chunked writer (codegen/chunked_writer.h) on the default model: files no larger than version
// 1 holding the same depths, a head within its budget, nested levels; and the reader against
// damage: refinement walks that break in every way, every prefix of the head and tables, and
// prefixes ending anywhere in the chunks.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>

#include "codegen/level_voxels.h"
#include "codegen/model_writer.h"
#include "codegen/prepare_error.h"
#include "octopoint/camera.h"
#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "renderer/chunked_assembly.h"
#include "tests/support/chunked_test_support.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

using octopoint::testing::Bytes;

TEST(ChunkedWriter, NoLargerThanVersionOneHoldingTheSameDepths) {
  for (const std::vector<int>& depths :
       {std::vector<int>{7, 8}, std::vector<int>{4, 5, 6, 7, 8}, std::vector<int>{5, 8}}) {
    const prepare::PreparedModel prepared = fuzzing::preparedModel(*models::defaultModel(), depths);
    const std::size_t version1 = prepare::serializeModel(prepared).size();
    for (std::size_t target : {1024u, 2048u, 4096u}) {
      prepare::ChunkedLayout layout;
      const Bytes image =
          prepare::serializeChunkedModel(prepared, {target, prepare::kDefaultHeadBudget}, &layout);
      EXPECT_LE(image.size(), version1)
          << "depths from " << depths.front() << ", chunks of " << target << " bytes";
      EXPECT_LE(layout.head_bytes, prepare::kDefaultHeadBudget);
      EXPECT_EQ(layout.file_bytes, image.size());
    }
  }
}

TEST(ChunkedWriter, ASingleDepthIsLargerByItsBaseAndDirectoryOnly) {
  const prepare::PreparedModel prepared = fuzzing::preparedModel(*models::defaultModel(), {8});
  const std::size_t version1 = prepare::serializeModel(prepared).size();
  prepare::ChunkedLayout layout;
  const Bytes image = prepare::serializeChunkedModel(prepared, {}, &layout);
  EXPECT_EQ(layout.chunks, std::vector<std::size_t>{1});  // made as few as possible
  EXPECT_GT(image.size(), version1);
  EXPECT_LE(image.size(), version1 + layout.head_bytes - format::v1::kHeaderBytes + 64);
}

TEST(ChunkedWriter, TheBaseIsTheFinestDepthWhoseHeadFits) {
  const prepare::PreparedModel prepared =
      fuzzing::preparedModel(*models::defaultModel(), {4, 6, 8});
  prepare::ChunkedLayout roomy, tight;
  prepare::serializeChunkedModel(prepared, {2048, 1 << 20}, &roomy);
  EXPECT_EQ(roomy.base_depth, 4);  // the coarsest depth itself
  EXPECT_FALSE(roomy.base_added);
  prepare::serializeChunkedModel(prepared, {2048, 1200}, &tight);
  EXPECT_LT(tight.base_depth, 4);
  EXPECT_TRUE(tight.base_added);
  EXPECT_LE(tight.head_bytes, 1200u);
  EXPECT_EQ(tight.depths, (std::vector<int>{4, 6, 8}));
}

TEST(ChunkedWriter, RefusesLevelsThatAreNotNestedAndNestLevelsMendsThem) {
  prepare::PreparedModel prepared = fuzzing::preparedModel(*models::defaultModel(), {6, 8});
  // Drop the depth-6 voxels of one region: their depth-8 voxels lose their parents.
  prepare::LevelVoxels coarse = prepare::decodeLevel(prepared.levels[0]);
  prepare::LevelVoxels kept{coarse.depth, {}, {}};
  for (std::size_t i = 0; i < coarse.keys.size(); ++i) {
    if (i % 5 == 0) continue;
    kept.keys.push_back(coarse.keys[i]);
    kept.colours.push_back(coarse.colours[i]);
  }
  prepared.levels[0] = prepare::encodeLevel(kept);
  EXPECT_THROW(prepare::serializeChunkedModel(prepared), prepare::PrepareError);
  EXPECT_EQ(prepare::nestLevels(prepared), coarse.keys.size() - kept.keys.size());
  EXPECT_EQ(prepare::decodeLevel(prepared.levels[0]).keys, coarse.keys);
  EXPECT_EQ(prepare::nestLevels(prepared), 0u);
  EXPECT_NO_THROW(prepare::serializeChunkedModel(prepared));
}

TEST(ChunkedWriter, ACoarsestDepthOfOneHasNoRoomForABase) {
  const prepare::PreparedModel prepared = fuzzing::preparedModel(*models::defaultModel(), {1, 8});
  EXPECT_THROW(prepare::serializeChunkedModel(prepared), prepare::PrepareError);
}

// A chunk of a gap-2 level, broken three ways with its CRC made to match.
TEST(ChunkedReader, RefinementWalksThatBreakAreRefused) {
  const Bytes image = fuzzing::chunkedImage(*models::defaultModel(), {4, 6, 8}, {256, 600});
  std::optional<ProgressiveModel> whole = progressiveModelFromPrefix(image, nullptr);
  ASSERT_TRUE(whole.has_value());
  int level = 1;
  while (whole->levelDepth(level) - whole->levelDepth(level - 1) < 2) ++level;
  // The chunk of that level with the most voxels; its first refinement starts its bytes.
  std::uint32_t index = 0;
  for (std::uint32_t i = 0; i < whole->chunkCount(level); ++i) {
    if (whole->record(level, i).points > whole->record(level, index).points) index = i;
  }
  const FetchItem item = whole->chunkItem(level, index);
  const auto broken = [&](std::size_t at, std::uint8_t value) {
    Bytes copy = image;
    copy[static_cast<std::size_t>(item.offset) + at] = value;
    octopoint::testing::reseal(copy);
    std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(copy, nullptr);
    for (int l = 1; l <= level; ++l) {
      const FetchItem table = model->recordTableItem(l);
      EXPECT_EQ(model
                    ->accept(table, std::span(copy).subspan(static_cast<std::size_t>(table.offset),
                                                            static_cast<std::size_t>(table.bytes)))
                    .error,
                ChunkedError::kNone);
    }
    return model
        ->accept(item, std::span(copy).subspan(static_cast<std::size_t>(item.offset),
                                               static_cast<std::size_t>(item.bytes)))
        .error;
  };
  // Refinements of a gap-2 chunk: a first mask, then one leaf-parent mask per bit of it.
  const std::size_t masks =
      static_cast<std::size_t>(item.bytes - whole->record(level, index).points);
  std::vector<std::size_t> starts;
  for (std::size_t at = 0; at < masks;
       at += 1 + static_cast<std::size_t>(
                     std::popcount(image[static_cast<std::size_t>(item.offset) + at]))) {
    starts.push_back(at);
  }
  ASSERT_FALSE(starts.empty());
  const std::size_t last_at = starts[starts.size() - 1];
  const std::uint8_t first = image[static_cast<std::size_t>(item.offset)];
  const std::uint8_t last = image[static_cast<std::size_t>(item.offset) + last_at];
  ASSERT_NE(first, 0);
  ASSERT_LT(std::popcount(last), 8);
  ASSERT_GT(std::popcount(last), 1);
  EXPECT_EQ(broken(last_at, 0xFF), ChunkedError::kChunkTruncated);
  EXPECT_EQ(broken(last_at, static_cast<std::uint8_t>(last & -last)),
            ChunkedError::kChunkTrailingBytes);
  EXPECT_EQ(broken(1, 0x00), ChunkedError::kChunkEmptyNode);
}

// Every prefix of the head and the record tables, and prefixes ending on, before and after every
// chunk boundary of the first levels (then every 97th byte): a model or a clean refusal, and what
// is read draws.
TEST(ChunkedReader, EveryPrefixReadsOrIsRefusedCleanly) {
  const Bytes image = fuzzing::chunkedImage(*models::defaultModel(), {5, 6, 7, 8}, {256, 1500});
  ChunkedIssue issue;
  const std::uint64_t head_bytes = *chunkedHeadBytes(image, &issue);
  std::optional<ProgressiveModel> whole = progressiveModelFromPrefix(image, nullptr);
  const std::uint64_t first_chunk = whole->head().levels[1].chunks_offset;
  std::vector<std::size_t> lengths;
  for (std::size_t n = 0; n <= first_chunk; ++n) lengths.push_back(n);
  for (const FetchItem& item : octopoint::testing::allChunkItems(*whole)) {
    if (item.level > 2) break;
    for (std::uint64_t n :
         {item.offset + item.bytes - 1, item.offset + item.bytes, item.offset + item.bytes + 1}) {
      lengths.push_back(static_cast<std::size_t>(n));
    }
  }
  for (std::size_t n = static_cast<std::size_t>(first_chunk); n <= image.size(); n += 97)
    lengths.push_back(n);
  Camera camera;
  Framebuffer frame(camera.width, camera.height);
  for (std::size_t n : lengths) {
    const Bytes prefix(image.begin(),
                       image.begin() + static_cast<std::ptrdiff_t>(std::min(n, image.size())));
    std::optional<ProgressiveModel> model = progressiveModelFromPrefix(prefix, &issue);
    if (n < head_bytes) {
      EXPECT_FALSE(model.has_value());
      EXPECT_EQ(issue.error, ChunkedError::kTruncatedHead) << n;
      continue;
    }
    ASSERT_TRUE(model.has_value()) << n;
    EXPECT_EQ(issue.error, ChunkedError::kNone) << n;
    frame.clear();
    EXPECT_TRUE(model->draw(camera, Variant::kFixedFast, frame));
  }
}

// Version 5: the cube's placement sits at the end of the head, before its CRC; the default
// model's (a y-up scan) is read back as written, and a placement no file may hold is refused
// even under a correct CRC.
TEST(ChunkedWriter, TheHeadCarriesTheCubesPlacement) {
  const prepare::PreparedModel prepared = fuzzing::preparedModel(*models::defaultModel(), {6, 7});
  ASSERT_TRUE(prepared.cube.recorded());
  Bytes image = prepare::serializeChunkedModel(prepared);
  ChunkedIssue issue;
  std::optional<ChunkedHead> head = parseChunkedHead(image, &issue);
  ASSERT_TRUE(head) << describe(issue.error);
  EXPECT_EQ(head->format_version, 7);
  EXPECT_EQ(head->cube, prepared.cube);
  const std::size_t placement_at = head->head_bytes - 4 - format::kCubePlacementBytes;
  EXPECT_EQ(image[placement_at + 32], format::kScanAxesYUp);
  image[placement_at + 7] = 0x7f;  // the corner's x: exponent all ones (the sign bit cleared)
  image[placement_at + 6] = 0xf0;
  octopoint::testing::reseal(image);
  head = parseChunkedHead(image, &issue);
  EXPECT_FALSE(head);
  EXPECT_EQ(issue.error, ChunkedError::kBadCubePlacement);
  EXPECT_EQ(issue.offset, placement_at);
}

// Version 7: each level table row carries its level's sample reach (byte 2); the base's is one
// footprint. A model assembled from the chunks keeps them (an embedded model of version 6), and a
// reach no file may hold is refused even under a correct CRC, at its byte.
TEST(ChunkedWriter, EachLevelRowCarriesItsSampleReach) {
  prepare::PreparedModel prepared = fuzzing::preparedModel(*models::defaultModel(), {6, 7});
  prepared.levels[1].sample_reach = 48;  // depth 7: three footprints
  Bytes image = prepare::serializeChunkedModel(prepared);
  ChunkedIssue issue;
  std::optional<ChunkedHead> head = parseChunkedHead(image, &issue);
  ASSERT_TRUE(head) << describe(issue.error);
  ASSERT_EQ(head->level_count, 3);  // a coarser base: depth 6 is over the head's budget
  EXPECT_EQ(head->levels[0].sample_reach, kOneSampleReach);
  EXPECT_EQ(head->levels[1].depth, 6);
  EXPECT_EQ(head->levels[1].sample_reach, kOneSampleReach);
  EXPECT_EQ(head->levels[2].depth, 7);
  EXPECT_EQ(head->levels[2].sample_reach, 48);

  std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(image, &issue);
  ASSERT_TRUE(model) << describe(issue.error);
  octopoint::testing::feedTables(*model, image);
  for (const FetchItem& item : octopoint::testing::allChunkItems(*model))
    octopoint::testing::feed(*model, image, item);
  const std::unique_ptr<AssembledModel> assembled = assembleChunked(*model);
  ASSERT_TRUE(assembled->view);
  EXPECT_EQ(assembled->view->formatVersion(), format::kVersion6);
  EXPECT_EQ(assembled->view->sampleReachOfDepth(7), 48);
  EXPECT_EQ(assembled->view->sampleReachOfDepth(6), kOneSampleReach);

  const std::size_t row_at = chunked::kFixedHeaderBytes + 3 * prepared.palette.size() +
                             2 * chunked::kLevelRowBytes;  // depth 7's row
  ASSERT_EQ(image[row_at], 7);
  for (const std::uint8_t bad : {0, 15, 129}) {
    Bytes broken = image;
    broken[row_at + 2] = bad;
    octopoint::testing::reseal(broken);
    EXPECT_FALSE(parseChunkedHead(broken, &issue));
    EXPECT_EQ(issue.error, ChunkedError::kBadSampleReach);
    EXPECT_EQ(issue.offset, row_at + 2);
  }
  Bytes reserved = image;
  reserved[row_at + 3] = 1;
  octopoint::testing::reseal(reserved);
  EXPECT_FALSE(parseChunkedHead(reserved, &issue));
  EXPECT_EQ(issue.error, ChunkedError::kBadReservedField);
  // As version 5, the same byte is reserved.
  Bytes as_v5 = image;
  as_v5[chunked::offset::kVersion] = 5;
  octopoint::testing::reseal(as_v5);
  EXPECT_FALSE(parseChunkedHead(as_v5, &issue));
  EXPECT_EQ(issue.error, ChunkedError::kBadReservedField);
}

}  // namespace
}  // namespace octopoint
