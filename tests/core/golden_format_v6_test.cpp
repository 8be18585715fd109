// Golden models of format version 6 (octopoint/model.h, docs/format.md): version 4 with each
// level's sample reach in byte 1 of its level table row, in sixteenths of a voxel footprint.
// Written out byte by byte with literal offsets and frozen here; the reach's rules each have a
// refusal. Versions 1, 2 and 4 keep their goldens (golden_format_test.cpp,
// golden_format_v2_test.cpp, golden_format_v4_test.cpp) and read as one footprint.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "octopoint/model.h"
#include "tests/support/golden_support.h"

namespace octopoint {
namespace {

using V6Bytes = std::vector<std::uint8_t>;

constexpr std::size_t kV6TableAt = 788 + 40;  // no normal palette, then the placement block

// Two levels: depth 1 (children 0 and 7 of the root, red and blue) at one footprint, and depth 2
// (one leaf in each of them) at `fine_reach` sixteenths; a 5 km cube, placement not recorded.
V6Bytes twoReaches(std::uint8_t fine_reach, std::uint16_t version = 6) {
  V6Bytes image = {'O',  'C',  'T',  'P',  static_cast<std::uint8_t>(version),
                   0x00, 0x02, 0x00, 0x00, 0x80,
                   0xe0, 0x37, 0x79, 0xc3, 0x11,
                   0x00,                    // cube edge 5 km in pm
                   0x02, 0x00, 0x00, 0x00,  // 2 colours, no normals
                   0xff, 0x00, 0x00, 0x00, 0x00,
                   0xff};       // red, blue
  image.resize(kV6TableAt, 0);  // the rest of the palette; an unrecorded placement (40 zeros)
  const V6Bytes table_and_streams = {
      0x01, 0x10,       0x00, 0x00,        // depth 1, reach 16 (one footprint), reserved
      0x01, 0x00,       0x00, 0x00,        // 1 node byte
      0x02, 0x00,       0x00, 0x00,        // 2 leaves
      0x02, fine_reach, 0x00, 0x00,        // depth 2, its reach, reserved
      0x03, 0x00,       0x00, 0x00,        // 3 node bytes
      0x02, 0x00,       0x00, 0x00,        // 2 leaves
      0x81, 0x00,       0x01,              // depth 1: root, leaf colours
      0x81, 0x01,       0x80, 0x00, 0x01,  // depth 2: root, child 0's child 0, child 7's child 7
  };
  image.insert(image.end(), table_and_streams.begin(), table_and_streams.end());
  return image;
}

ModelError v6Refusal(const V6Bytes& image, std::size_t* offset = nullptr) {
  ModelIssue issue;
  EXPECT_FALSE(ModelView::fromBytes(image, &issue).has_value());
  if (offset != nullptr) *offset = issue.offset;
  return issue.error;
}

TEST(GoldenFormatV6, EachLevelsReachIsReadAsFrozen) {
  const ModelView model = testing::validated(twoReaches(0x30));
  EXPECT_EQ(model.formatVersion(), 6);
  ASSERT_EQ(model.levelCount(), 2);
  EXPECT_EQ(model.sampleReach(0), 16);
  EXPECT_EQ(model.sampleReach(1), 48);  // three footprints
  EXPECT_EQ(model.sampleReachOfDepth(2), 48);
  EXPECT_EQ(model.sampleReachOfDepth(3), kOneSampleReach);  // no such depth
  EXPECT_EQ(model.level(1).leaves.size(), 2u);
  EXPECT_EQ(testing::validated(twoReaches(128)).sampleReach(1), kMaxSampleReach);
}

TEST(GoldenFormatV6, AReachOutsideOneToEightFootprintsIsRefusedAtItsByte) {
  const std::size_t fine_reach_at = kV6TableAt + 12 + 1;
  for (const std::uint8_t bad : {0, 1, 15, 129, 255}) {
    std::size_t offset = 0;
    EXPECT_EQ(v6Refusal(twoReaches(bad), &offset), ModelError::kBadSampleReach) << int{bad};
    EXPECT_EQ(offset, fine_reach_at);
  }
  // The row's last two bytes stay reserved.
  V6Bytes reserved = twoReaches(32);
  reserved[fine_reach_at + 2] = 1;
  std::size_t offset = 0;
  EXPECT_EQ(v6Refusal(reserved, &offset), ModelError::kBadReservedField);
  EXPECT_EQ(offset, fine_reach_at + 2);
  // The declared sizes are still checked before the body is read, the reach too.
  ModelIssue issue;
  EXPECT_TRUE(ModelView::checkDeclaredSizes(twoReaches(32), twoReaches(32).size(), &issue));
  EXPECT_FALSE(ModelView::checkDeclaredSizes(twoReaches(0), twoReaches(0).size(), &issue));
  EXPECT_EQ(issue.error, ModelError::kBadSampleReach);
}

TEST(GoldenFormatV6, OlderVersionsReserveTheByteAndReadAsOneFootprint) {
  // The same bytes as version 4: the reach byte is a reserved field there.
  EXPECT_EQ(v6Refusal(twoReaches(32, 4)), ModelError::kBadReservedField);
  V6Bytes v4 = twoReaches(0, 4);
  v4[kV6TableAt + 1] = 0;  // the coarse row's reach too
  const ModelView model = testing::validated(v4);
  EXPECT_EQ(model.formatVersion(), 4);
  EXPECT_EQ(model.sampleReach(0), kOneSampleReach);
  EXPECT_EQ(model.sampleReach(1), kOneSampleReach);
}

TEST(GoldenFormatV6, EmbeddedModelsCarryTheReachOfTheirVersion) {
  const std::uint8_t palette[768] = {255, 0, 0, 0, 0, 255};
  const std::uint8_t nodes[] = {0x81};
  const std::uint8_t leaves[] = {0, 1};
  EmbeddedLevel level{1, nodes, 1, leaves, 2, nullptr, 32};
  EmbeddedModel model{"reach", format::kVersion6, 0, 0, 2, palette, 0, nullptr, 1, &level, {}};
  ModelIssue issue;
  std::optional<ModelView> view = ModelView::fromEmbedded(model, &issue);
  ASSERT_TRUE(view) << describe(issue.error);
  EXPECT_EQ(view->sampleReach(0), 32);
  for (const std::uint8_t bad : {0, 15, 129}) {
    level.sample_reach = bad;
    EXPECT_FALSE(ModelView::fromEmbedded(model, &issue));
    EXPECT_EQ(issue.error, ModelError::kBadSampleReach);
  }
  // Version 4 sources end before the reach: one that has it is not a version 4 source.
  level.sample_reach = 32;
  model.format_version = format::kVersion4;
  EXPECT_FALSE(ModelView::fromEmbedded(model, &issue));
  EXPECT_EQ(issue.error, ModelError::kBadSampleReach);
  level.sample_reach = 0;
  view = ModelView::fromEmbedded(model, &issue);
  ASSERT_TRUE(view);
  EXPECT_EQ(view->sampleReach(0), kOneSampleReach);
}

}  // namespace
}  // namespace octopoint
