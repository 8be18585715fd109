// The version 2 validator (renderer/model_read_v2.cpp): flags, the 64-bit metric size, the normal
// palette and the per-leaf normal indices each get their own error; embedded models with normals
// are checked the same way. The level checks both versions share are in model_validation_test.cpp.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "octopoint/model.h"

namespace octopoint {
namespace {

using Normal = std::array<std::int16_t, 3>;

struct ImageSpec {
  std::uint8_t flags = format::v2::kFlagNormals;
  std::uint64_t cube_edge_pm = 1'000'000'000'000'000'000u;  // 1,000 km
  std::uint16_t normal_count = 2;                           // as written in the header
  std::vector<Normal> normals = {{16384, 0, 0}, {0, 0, -16384}};
  std::vector<std::uint8_t> leaf_normals = {0, 1};
};

// A version 2 image built byte by byte: depth 1, children 0 and 7, two colours.
std::vector<std::uint8_t> image(const ImageSpec& spec) {
  std::vector<std::uint8_t> out = {'O', 'C', 'T', 'P', 2, 0, 1, spec.flags};
  for (int shift = 0; shift < 64; shift += 8)
    out.push_back(static_cast<std::uint8_t>(spec.cube_edge_pm >> shift));
  out.insert(out.end(), {2, 0, static_cast<std::uint8_t>(spec.normal_count),
                         static_cast<std::uint8_t>(spec.normal_count >> 8)});
  for (int i = 0; i < 768; ++i)
    out.push_back(i < 6 ? static_cast<std::uint8_t>(10 + i) : std::uint8_t{0});
  for (const Normal& n : spec.normals) {
    for (std::int16_t c : n) {
      out.push_back(static_cast<std::uint8_t>(c));
      out.push_back(static_cast<std::uint8_t>(static_cast<std::uint16_t>(c) >> 8));
    }
  }
  out.insert(out.end(), {1, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 0x81, 0, 1});
  out.insert(out.end(), spec.leaf_normals.begin(), spec.leaf_normals.end());
  return out;
}

ModelIssue issueOf(const std::vector<std::uint8_t>& bytes) {
  ModelIssue issue;
  const auto model = ModelView::fromBytes(bytes, &issue);
  EXPECT_EQ(model.has_value(), issue.error == ModelError::kNone);
  return issue;
}

TEST(ModelValidationV2, AcceptsAModelWithNormalsAndAThousandKilometreCube) {
  const std::vector<std::uint8_t> bytes = image({});
  ModelIssue issue;
  const auto model = ModelView::fromBytes(bytes, &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error) << " at " << issue.offset;
  EXPECT_EQ(model->cubeEdgePicometres(), 1'000'000'000'000'000'000u);
  EXPECT_EQ(model->normalCount(), 2);
  EXPECT_EQ(model->normal(1), (NormalQ14{0, 0, -16384}));
  EXPECT_EQ(model->level(0).normals[1], 1);
}

TEST(ModelValidationV2, AcceptsTheLargestCubeEdgeAndNone) {
  for (const std::uint64_t edge : {std::uint64_t{0}, ~std::uint64_t{0}}) {
    ImageSpec spec;
    spec.cube_edge_pm = edge;
    EXPECT_EQ(issueOf(image(spec)).error, ModelError::kNone) << edge;
  }
}

TEST(ModelValidationV2, RejectsEveryTruncation) {
  const std::vector<std::uint8_t> bytes = image({});
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const std::vector<std::uint8_t> prefix(bytes.begin(),
                                           bytes.begin() + static_cast<std::ptrdiff_t>(length));
    const ModelError error = issueOf(prefix).error;
    const ModelError expected =
        length < 788 + 12 + 12 ? ModelError::kTruncatedHeader : ModelError::kSizeMismatch;
    EXPECT_EQ(error, expected) << "prefix of " << length << " bytes: " << describe(error);
  }
}

TEST(ModelValidationV2, RejectsUnknownFlags) {
  for (const std::uint8_t flag : {4, 8, 0x80}) {
    ImageSpec spec;
    spec.flags = static_cast<std::uint8_t>(spec.flags | flag);
    const ModelIssue issue = issueOf(image(spec));
    EXPECT_EQ(issue.error, ModelError::kBadReservedField);
    EXPECT_EQ(issue.offset, 7u);
  }
}

TEST(ModelValidationV2, RejectsANormalCountThatDisagreesWithTheFlag) {
  ImageSpec no_flag;  // entries and leaf normals, but the flag says there are none
  no_flag.flags = 0;
  EXPECT_EQ(issueOf(image(no_flag)).error, ModelError::kBadNormalCount);
  ImageSpec no_entries;  // the flag, but no entries
  no_entries.normal_count = 0;
  no_entries.normals.clear();
  EXPECT_EQ(issueOf(image(no_entries)).error, ModelError::kBadNormalCount);
}

TEST(ModelValidationV2, RejectsMoreThan255Normals) {
  ImageSpec spec;
  spec.normal_count = 256;
  spec.normals.assign(256, Normal{0, 16384, 0});
  EXPECT_EQ(issueOf(image(spec)).error, ModelError::kBadNormalCount);
  spec.normal_count = 255;
  spec.normals.resize(255);
  EXPECT_EQ(issueOf(image(spec)).error, ModelError::kNone);
}

TEST(ModelValidationV2, RejectsANormalThatIsNotAUnitVector) {
  for (const Normal& bad :
       {Normal{0, 0, 0}, Normal{16384, 16384, 0}, Normal{0, 8192, 0}, Normal{16200, 0, 0}}) {
    ImageSpec spec;
    spec.normals[1] = bad;
    const ModelIssue issue = issueOf(image(spec));
    EXPECT_EQ(issue.error, ModelError::kBadNormalVector);
    EXPECT_EQ(issue.offset, 788u + 6u);  // the second entry
  }
  ImageSpec rounded;                         // within rounding of unit length: accepted
  rounded.normals[1] = {9459, 9459, -9459};  // 16384 / sqrt(3), rounded
  EXPECT_EQ(issueOf(image(rounded)).error, ModelError::kNone);
}

TEST(ModelValidationV2, RejectsALeafNormalPastTheNormalPalette) {
  ImageSpec spec;
  spec.leaf_normals = {0, 2};
  const std::vector<std::uint8_t> bytes = image(spec);
  const ModelIssue issue = issueOf(bytes);
  EXPECT_EQ(issue.error, ModelError::kNormalOutsidePalette);
  EXPECT_TRUE(issue.offset_in_file);
  EXPECT_EQ(issue.offset,
            bytes.size() - 1);  // the second leaf's normal index, the image's last byte
  EXPECT_EQ(issue.depth, 1);
}

TEST(ModelValidationV2, RejectsMissingOrExtraLeafNormals) {
  ImageSpec missing;
  missing.leaf_normals = {0};
  EXPECT_EQ(issueOf(image(missing)).error, ModelError::kSizeMismatch);
  ImageSpec extra;
  extra.leaf_normals = {0, 1, 1};
  EXPECT_EQ(issueOf(image(extra)).error, ModelError::kSizeMismatch);
}

TEST(ModelValidationV2, ValidatesEmbeddedNormalsTheSameWay) {
  const std::uint8_t palette[format::kPaletteBytes] = {};
  const std::uint8_t nodes[] = {0x81};
  const std::uint8_t leaves[] = {0, 0};
  const std::uint8_t normals[] = {0, 1};
  const std::int16_t normal_xyz[] = {16384, 0, 0, 0, 0, -16384};
  const EmbeddedLevel level{1, nodes, 1, leaves, 2, normals};
  EmbeddedModel model{
      "normals", format::kVersion2, format::v2::kFlagNormals, 1, 1, palette, 2, normal_xyz, 1,
      &level};
  ModelIssue issue;
  ASSERT_TRUE(ModelView::fromEmbedded(model, &issue).has_value()) << describe(issue.error);
  EXPECT_EQ(ModelView::fromEmbedded(model, &issue)->normal(1), (NormalQ14{0, 0, -16384}));

  model.normal_count = 1;  // leaf normal 1 is now past the palette
  EXPECT_FALSE(ModelView::fromEmbedded(model, &issue).has_value());
  EXPECT_EQ(issue.error, ModelError::kNormalOutsidePalette);
  model.normal_count = 2;
  model.flags = 0;  // normals without the flag
  EXPECT_FALSE(ModelView::fromEmbedded(model, &issue).has_value());
  EXPECT_EQ(issue.error, ModelError::kBadNormalCount);
  model.flags = format::v2::kFlagNormals;
  model.format_version = 1;  // generated for another layout
  EXPECT_FALSE(ModelView::fromEmbedded(model, &issue).has_value());
  EXPECT_EQ(issue.error, ModelError::kUnsupportedVersion);
  model.format_version = format::kVersion2;
  const std::int16_t short_normal[] = {16384, 0, 0, 0, 0, -100};
  model.normal_xyz = short_normal;
  EXPECT_FALSE(ModelView::fromEmbedded(model, &issue).has_value());
  EXPECT_EQ(issue.error, ModelError::kBadNormalVector);
}

}  // namespace
}  // namespace octopoint
