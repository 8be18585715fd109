// Golden models of format version 4 (octopoint/model.h, docs/format.md): version 2 and, after the
// normal palette, the cube's placement in the scan (CubePlacement). Written out byte by byte with
// literal offsets and frozen here; the placement's every rule has a refusal of its own.
// Versions 1 and 2 keep their goldens (golden_format_test.cpp, golden_format_v2_test.cpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

#include "octopoint/model.h"
#include "tests/support/golden_support.h"

namespace octopoint {
namespace {

using V4Bytes = std::vector<std::uint8_t>;

// The placement block: corner (-1.5, 2, 0.25) and edge 5000 scan units (binary64, little-endian),
// a y-up scan, 7 reserved bytes.
const V4Bytes kPlacementBlock = {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xf8, 0xbf,   // -1.5
                                 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x40,   // 2
                                 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xd0, 0x3f,   // 0.25
                                 0x00, 0x00, 0x00, 0x00, 0x00, 0x88, 0xb3, 0x40,   // 5000
                                 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};  // y-up, reserved

// Depth 1, children 0 and 7 of the root, red and blue, a 5 km cube, placed by `placement`.
V4Bytes placedCorners(const V4Bytes& placement) {
  V4Bytes image = {'O',  'C',  'T',  'P',  0x04, 0x00, 0x01, 0x00,  // magic, version 4, 1 level
                   0x00, 0x80, 0xe0, 0x37, 0x79, 0xc3, 0x11, 0x00,  // cube edge 5 km in pm
                   0x02, 0x00, 0x00, 0x00,                          // 2 colours, no normals
                   0xff, 0x00, 0x00, 0x00, 0x00, 0xff};             // red, blue
  image.resize(788, 0);  // the rest of the palette; no normal palette
  image.insert(image.end(), placement.begin(), placement.end());  // at 788
  const V4Bytes table_and_stream = {0x01, 0x00, 0x00, 0x00,       // depth 1, reserved
                                    0x01, 0x00, 0x00, 0x00,       // 1 node byte
                                    0x02, 0x00, 0x00, 0x00,       // 2 leaves
                                    0x81, 0x00, 0x01};            // root, leaf colours
  image.insert(image.end(), table_and_stream.begin(), table_and_stream.end());
  return image;
}

ModelError v4Refusal(const V4Bytes& image, std::size_t* offset = nullptr) {
  ModelIssue issue;
  EXPECT_FALSE(ModelView::fromBytes(image, &issue).has_value());
  if (offset != nullptr) *offset = issue.offset;
  return issue.error;
}

TEST(GoldenFormatV4, ThePlacementIsReadAsFrozen) {
  const ModelView model = testing::validated(placedCorners(kPlacementBlock));
  EXPECT_EQ(model.formatVersion(), 4);
  EXPECT_EQ(model.cubeEdgePicometres(), 5'000'000'000'000'000u);
  const CubePlacement& cube = model.cubePlacement();
  EXPECT_TRUE(cube.recorded());
  EXPECT_EQ(cube.corner_bits[0], 0xbff8000000000000u);
  EXPECT_EQ(cube.corner_bits[1], 0x4000000000000000u);
  EXPECT_EQ(cube.corner_bits[2], 0x3fd0000000000000u);
  EXPECT_EQ(cube.edge_bits, 0x40b3880000000000u);
  EXPECT_EQ(cube.scan_axes, format::kScanAxesYUp);
  ASSERT_EQ(model.levelCount(), 1);
  EXPECT_EQ(model.level(0).leaves.size(), 2u);
}

TEST(GoldenFormatV4, AnAllZeroPlacementIsNotRecorded) {
  const ModelView model = testing::validated(placedCorners(V4Bytes(40, 0)));
  EXPECT_FALSE(model.cubePlacement().recorded());
}

TEST(GoldenFormatV4, EachPlacementRuleHasItsRefusal) {
  // The block with bytes changed: {offset in the block, value} pairs.
  const auto broken = [](std::initializer_list<std::pair<std::size_t, std::uint8_t>> changes) {
    V4Bytes block = kPlacementBlock;
    for (const auto& [at, value] : changes) block[at] = value;
    return placedCorners(block);
  };
  std::size_t offset = 0;
  // A NaN corner, an infinite one (exponent all ones), a negative edge, an infinite edge, unknown
  // axes, a reserved byte: each refused, at the block.
  for (const V4Bytes& image :
       {broken({{7, 0x7f}}), broken({{14, 0xf0}, {15, 0xff}}), broken({{31, 0xc0}}),
        broken({{30, 0xf0}, {31, 0x7f}}), broken({{32, 2}}), broken({{39, 1}})}) {
    EXPECT_EQ(v4Refusal(image, &offset), ModelError::kBadCubePlacement);
    EXPECT_EQ(offset, 788u);
  }
  // A corner without an edge: not "not recorded", refused.
  V4Bytes no_edge = kPlacementBlock;
  for (std::size_t i = 24; i < 32; ++i) no_edge[i] = 0;
  EXPECT_EQ(v4Refusal(placedCorners(no_edge)), ModelError::kBadCubePlacement);
  // Cut inside the block: a truncated header.
  const V4Bytes image = placedCorners(kPlacementBlock);
  EXPECT_EQ(v4Refusal(V4Bytes(image.begin(), image.begin() + 800)), ModelError::kTruncatedHeader);
  // Version 2 with the same bytes reads them as its level table, which they are not.
  V4Bytes as_v2 = image;
  as_v2[4] = 2;
  EXPECT_NE(v4Refusal(as_v2), ModelError::kNone);
}

TEST(GoldenFormatV4, EmbeddedModelsCarryThePlacementOfTheirVersion) {
  const std::uint8_t palette[768] = {255, 0, 0, 0, 0, 255};
  const std::uint8_t nodes[] = {0x81};
  const std::uint8_t leaves[] = {0, 1};
  const EmbeddedLevel level{1, nodes, 1, leaves, 2};
  CubePlacement placed;
  placed.corner_bits[0] = 0xbff8000000000000u;  // -1.5
  placed.edge_bits = 0x40b3880000000000u;       // 5000
  EmbeddedModel model{"placed", format::kVersion4, 0, 0, 2, palette, 0, nullptr, 1, &level, placed};
  ModelIssue issue;
  const std::optional<ModelView> view = ModelView::fromEmbedded(model, &issue);
  ASSERT_TRUE(view) << describe(issue.error);
  EXPECT_EQ(view->cubePlacement(), placed);

  model.cube.corner_bits[1] = 0x7ff8000000000000u;  // NaN
  EXPECT_FALSE(ModelView::fromEmbedded(model, &issue));
  EXPECT_EQ(issue.error, ModelError::kBadCubePlacement);
  // Version 2 sources end before the placement: one that has it is not a version 2 source.
  model.cube = placed;
  model.format_version = format::kVersion2;
  EXPECT_FALSE(ModelView::fromEmbedded(model, &issue));
  EXPECT_EQ(issue.error, ModelError::kBadCubePlacement);
  model.cube = {};
  EXPECT_TRUE(ModelView::fromEmbedded(model, &issue));
}

}  // namespace
}  // namespace octopoint
