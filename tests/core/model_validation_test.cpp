// A model from a file is untrusted: every malformation gets its own error, found before drawing.
// The images here are format version 1 (what the version 1 validator and the shared level checks
// see); version 2's own fields are tested in model_validation_v2_test.cpp.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "octopoint/model.h"

namespace octopoint {
namespace {

struct TestLevel {
  std::uint8_t depth;
  std::vector<std::uint8_t> nodes;
  std::vector<std::uint8_t> leaves;
};

// Builds a model image by hand, byte by byte, as docs/format.md describes it.
std::vector<std::uint8_t> modelImage(const std::vector<TestLevel>& levels,
                                     std::uint16_t palette_count = 2) {
  std::vector<std::uint8_t> out = {
      'O', 'C', 'T', 'P', 1, 0, static_cast<std::uint8_t>(levels.size()), 0};
  const std::uint32_t edge_um = 250000;
  for (int shift = 0; shift < 32; shift += 8)
    out.push_back(static_cast<std::uint8_t>(edge_um >> shift));
  out.push_back(static_cast<std::uint8_t>(palette_count));
  out.push_back(static_cast<std::uint8_t>(palette_count >> 8));
  out.push_back(0);
  out.push_back(0);
  for (int i = 0; i < format::kPaletteEntries * 3; ++i) {
    out.push_back(i < 3 * palette_count ? static_cast<std::uint8_t>(i)
                                        : std::uint8_t{0});  // unused: 0
  }
  auto put32 = [&](std::size_t value) {
    for (int shift = 0; shift < 32; shift += 8)
      out.push_back(static_cast<std::uint8_t>(value >> shift));
  };
  for (const TestLevel& level : levels) {
    out.insert(out.end(), {level.depth, 0, 0, 0});
    put32(level.nodes.size());
    put32(level.leaves.size());
  }
  for (const TestLevel& level : levels) {
    out.insert(out.end(), level.nodes.begin(), level.nodes.end());
    out.insert(out.end(), level.leaves.begin(), level.leaves.end());
  }
  return out;
}

// Depth 1: a root with children 0 and 7. Depth 2: root -> child 0 -> its children 0 and 7.
const TestLevel kDepthOne{1, {0x81}, {0, 1}};
const TestLevel kDepthTwo{2, {0x01, 0x81}, {1, 0}};

ModelError errorOf(const std::vector<std::uint8_t>& image) {
  ModelIssue issue;
  const auto model = ModelView::fromBytes(image, &issue);
  EXPECT_EQ(model.has_value(), issue.error == ModelError::kNone);
  return issue.error;
}

TEST(ModelValidation, AcceptsAWellFormedTwoLevelModel) {
  const std::vector<std::uint8_t> image = modelImage({kDepthOne, kDepthTwo});
  ModelIssue issue;
  const auto model = ModelView::fromBytes(image, &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error);
  EXPECT_EQ(model->levelCount(), 2);
  EXPECT_EQ(model->finestLevel().depth, 2);
  EXPECT_EQ(model->formatVersion(), 1);
  EXPECT_EQ(model->cubeEdgePicometres(), 250'000'000'000u);  // 250,000 um
  EXPECT_EQ(model->paletteColour(1).r, 3);
  EXPECT_EQ(model->levelOfDepth(1)->leaves.size(), 2u);
  EXPECT_EQ(model->levelOfDepth(3), nullptr);
}

TEST(ModelValidation, RejectsEveryTruncationOfAValidModel) {
  const std::vector<std::uint8_t> image = modelImage({kDepthOne, kDepthTwo});
  for (std::size_t length = 0; length < image.size(); ++length) {
    const std::vector<std::uint8_t> prefix(image.begin(),
                                           image.begin() + static_cast<std::ptrdiff_t>(length));
    EXPECT_NE(errorOf(prefix), ModelError::kNone) << "prefix of " << length << " bytes accepted";
  }
}

TEST(ModelValidation, RejectsABadMagic) {
  auto image = modelImage({kDepthOne});
  image[0] = 'X';
  EXPECT_EQ(errorOf(image), ModelError::kBadMagic);
}

TEST(ModelValidation, RejectsAnUnknownVersion) {
  auto image = modelImage({kDepthOne});
  for (const std::uint8_t version : {0, 3, 200}) {
    image[4] = version;
    EXPECT_EQ(errorOf(image), ModelError::kUnsupportedVersion) << int{version};
  }
}

TEST(ModelValidation, RejectsZeroLevelsAndTooManyLevels) {
  auto image = modelImage({kDepthOne});
  image[6] = 0;
  EXPECT_EQ(errorOf(image), ModelError::kBadLevelCount);
  image[6] = format::kMaxLevels + 1;
  EXPECT_EQ(errorOf(image), ModelError::kBadLevelCount);
}

TEST(ModelValidation, RejectsANonZeroReservedField) {
  auto image = modelImage({kDepthOne});
  image[7] = 1;
  EXPECT_EQ(errorOf(image), ModelError::kBadReservedField);
}

TEST(ModelValidation, RejectsAColourPastThePaletteCount) {
  for (const std::size_t at : {format::v1::kPaletteOffset + 6, format::v1::kHeaderBytes - 1}) {
    auto image = modelImage({kDepthOne}, 2);
    image[at] = 1;
    EXPECT_EQ(errorOf(image), ModelError::kBadReservedField) << "byte " << at;
  }
}

TEST(ModelValidation, RejectsAnEmptyOrOversizedPalette) {
  EXPECT_EQ(errorOf(modelImage({kDepthOne}, 0)), ModelError::kBadPaletteCount);
  EXPECT_EQ(errorOf(modelImage({kDepthOne}, 257)), ModelError::kBadPaletteCount);
}

TEST(ModelValidation, RejectsDepthsOutsideTheSupportedRange) {
  EXPECT_EQ(errorOf(modelImage({{0, {0x81}, {0, 1}}})), ModelError::kBadDepth);
  EXPECT_EQ(errorOf(modelImage({{format::kMaxDepth + 1, {0x81}, {0, 1}}})), ModelError::kBadDepth);
}

TEST(ModelValidation, RejectsDepthsNotStrictlyAscending) {
  EXPECT_EQ(errorOf(modelImage({kDepthTwo, kDepthOne})), ModelError::kDepthsNotAscending);
  EXPECT_EQ(errorOf(modelImage({kDepthOne, kDepthOne})), ModelError::kDepthsNotAscending);
}

TEST(ModelValidation, RejectsATrailingByteAfterTheLastLevel) {
  auto image = modelImage({kDepthOne});
  image.push_back(0);
  EXPECT_EQ(errorOf(image), ModelError::kSizeMismatch);
}

TEST(ModelValidation, RejectsAHugeDeclaredSizeWithoutReadingPastTheBuffer) {
  auto image = modelImage({kDepthOne});
  const std::size_t node_bytes_at = format::v1::kHeaderBytes + 4;
  for (int i = 0; i < 4; ++i) image[node_bytes_at + static_cast<std::size_t>(i)] = 0xff;
  EXPECT_EQ(errorOf(image), ModelError::kSizeMismatch);
}

TEST(ModelValidation, RejectsALevelWithoutNodes) {
  EXPECT_EQ(errorOf(modelImage({{1, {}, {}}})), ModelError::kEmptyLevel);
}

TEST(ModelValidation, RejectsAZeroChildMask) {
  EXPECT_EQ(errorOf(modelImage({{2, {0x01, 0x00}, {0}}})), ModelError::kEmptyNode);
}

TEST(ModelValidation, RejectsAStreamThatNeedsMoreNodeBytesThanDeclared) {
  EXPECT_EQ(errorOf(modelImage({{2, {0x03, 0x01}, {0}}})), ModelError::kStreamTruncated);
}

TEST(ModelValidation, RejectsNodeBytesLeftOverWhenTheTreeIsComplete) {
  EXPECT_EQ(errorOf(modelImage({{2, {0x01, 0x81, 0x01}, {0, 1}}})), ModelError::kTrailingNodeBytes);
}

TEST(ModelValidation, RejectsSizesNoTreeOfThatDepthCanHave) {
  // Depth 1 has exactly one node byte and at most 8 leaves.
  EXPECT_EQ(errorOf(modelImage({{1, {0x81, 0x01}, {0, 1}}})), ModelError::kImplausibleLevelSize);
  EXPECT_EQ(errorOf(modelImage({{1, {0xff}, std::vector<std::uint8_t>(9, 0)}})),
            ModelError::kImplausibleLevelSize);
  // Fewer node bytes than the depth: no path from the root down to a leaf.
  EXPECT_EQ(errorOf(modelImage({{3, {0x01, 0x01}, {0}}})), ModelError::kImplausibleLevelSize);
  // More node bytes than depth x leaves: some inner node would have no leaf below it.
  EXPECT_EQ(errorOf(modelImage({{2, {0x01, 0x01, 0x01}, {0}}})), ModelError::kImplausibleLevelSize);
  // More than 8 leaves per node byte.
  EXPECT_EQ(errorOf(modelImage({{3, {0x01, 0x01, 0xff}, std::vector<std::uint8_t>(25, 0)}})),
            ModelError::kImplausibleLevelSize);
}

TEST(ModelValidation, DescribesEveryErrorDifferently) {
  std::set<std::string> seen;
  for (int code = 0; code <= static_cast<int>(ModelError::kNormalOutsidePalette); ++code) {
    const std::string text = describe(static_cast<ModelError>(code));
    EXPECT_NE(text, "unknown error") << "code " << code;
    EXPECT_TRUE(seen.insert(text).second) << "code " << code << " repeats '" << text << "'";
  }
}

TEST(ModelValidation, RejectsALeafCountThatDisagreesWithTheTree) {
  EXPECT_EQ(errorOf(modelImage({{1, {0x81}, {0, 1, 1}}})), ModelError::kLeafCountMismatch);
  EXPECT_EQ(errorOf(modelImage({{1, {0x81}, {0}}})), ModelError::kLeafCountMismatch);
}

TEST(ModelValidation, RejectsALeafColourPastThePalette) {
  EXPECT_EQ(errorOf(modelImage({{1, {0x81}, {0, 2}}}, 2)), ModelError::kLeafOutsidePalette);
}

TEST(ModelValidation, ReportsWhereTheStreamWentWrong) {
  ModelIssue issue;
  const auto image = modelImage({kDepthOne, {2, {0x01, 0x00}, {0}}});
  EXPECT_FALSE(ModelView::fromBytes(image, &issue).has_value());
  EXPECT_EQ(issue.error, ModelError::kEmptyNode);
  EXPECT_EQ(issue.depth, 2);
  // The second byte of that level's node stream, counted in the file (its 3 bytes end the image).
  EXPECT_TRUE(issue.offset_in_file);
  EXPECT_EQ(issue.offset, image.size() - 3 + 1);
  EXPECT_EQ(image[issue.offset], 0x00);
  // validateLevelStream itself counts in the stream.
  const ModelIssue in_stream =
      validateLevelStream({2, std::span<const std::uint8_t>(image).last(3).first(2),
                           std::span<const std::uint8_t>(image).last(1)},
                          1);
  EXPECT_EQ(in_stream.offset, 1u);
  EXPECT_FALSE(in_stream.offset_in_file);
}

TEST(ModelValidation, LevelSizeAndLeafErrorsPointAtTheirBytesInTheFile) {
  ModelIssue issue;
  // A leaf colour past the palette: the leaf's own byte.
  const auto image = modelImage({{1, {0x81}, {0, 2}}}, 2);
  EXPECT_FALSE(ModelView::fromBytes(image, &issue).has_value());
  EXPECT_EQ(issue.error, ModelError::kLeafOutsidePalette);
  EXPECT_EQ(issue.offset, image.size() - 1);
  // A leaf count the tree does not have: the count in the level table.
  const auto miscounted = modelImage({{1, {0x81}, {0, 1, 1}}});
  EXPECT_FALSE(ModelView::fromBytes(miscounted, &issue).has_value());
  EXPECT_EQ(issue.error, ModelError::kLeafCountMismatch);
  EXPECT_EQ(issue.offset, format::v1::kHeaderBytes + 8);
}

TEST(ModelValidation, ValidatesEmbeddedModelsTheSameWay) {
  const std::uint8_t palette[format::kPaletteEntries * 3] = {};
  const std::uint8_t nodes[] = {0x01, 0x81, 0x01};
  const std::uint8_t leaves[] = {0, 0};
  const EmbeddedLevel level{2, nodes, 3, leaves, 2, nullptr};
  const EmbeddedModel model{"broken", format::kVersion2, 0, 1000,  1, palette,
                            0,        nullptr,           1, &level};
  ModelIssue issue;
  EXPECT_FALSE(ModelView::fromEmbedded(model, &issue).has_value());
  EXPECT_EQ(issue.error, ModelError::kTrailingNodeBytes);
}

}  // namespace
}  // namespace octopoint
