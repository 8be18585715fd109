// Detail by distance (docs/perspective.md): the upper tree index that lets a walk visit a level's
// nodes in any order; the depth each part of a frame is drawn at (every point of space by exactly
// one stored depth, each by depth auto's rule at its own distance, checked in double precision);
// frames that cover what the finest depth's covers with fewer leaves where the model recedes; and
// their fixed checksums, which scripts/test-armel checks on ARMv5 too.

#include "renderer/perspective_detail.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "renderer/bit_scan.h"
#include "renderer/crc32.h"
#include "renderer/decode_algorithms.h"
#include "renderer/perspective_renderer.h"
#include "renderer/perspective_walk.h"
#include "renderer/upper_tree_index.h"
#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace {

const ModelView& detailModel() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

// A voxel of a level: its integer coordinates on the 2^depth grid (x right, y down, z away).
struct GridVoxel {
  std::int64_t x, y, z;
};

void collectGridVoxels(const std::uint8_t*& node, int level, int depth, GridVoxel at,
                       std::vector<GridVoxel>& out) {
  if (level == depth) {
    out.push_back(at);
    return;
  }
  const unsigned mask = *node++;
  for (unsigned k = 0; k < 8; ++k) {
    if (!(mask & (1u << k))) continue;
    collectGridVoxels(node, level + 1, depth,
                      {2 * at.x + ((k >> 2) & 1), 2 * at.y + ((k >> 1) & 1), 2 * at.z + (k & 1)},
                      out);
  }
}

// Every leaf of `level` in stream order.
std::vector<GridVoxel> gridVoxelsOf(const LevelView& level) {
  std::vector<GridVoxel> voxels;
  const std::uint8_t* node = level.nodes.data();
  collectGridVoxels(node, 0, level.depth, {0, 0, 0}, voxels);
  return voxels;
}

// A voxel's centre in camera space (units), in double precision.
std::array<double, 3> cameraCentreOf(const PerspectiveCamera& camera, const GridVoxel& v,
                                     int depth) {
  const double edge = kUnit / static_cast<double>(std::int64_t{1} << depth);
  return exactCameraSpace(worldToCamera(camera), camera.eye,
                          Vector3{(static_cast<double>(v.x) + 0.5) * edge - kUnit / 2,
                                  (static_cast<double>(v.y) + 0.5) * edge - kUnit / 2,
                                  (static_cast<double>(v.z) + 0.5) * edge - kUnit / 2});
}

struct DetailView {
  std::string name;
  PerspectiveCamera camera;
  bool recedes;  // parts of the model lie far enough for a coarser depth than the finest
};

// Views where the model recedes: from outside far enough for coarse depths, and from inside,
// at the table's edge (a little above it, looking across it at the objects on it).
std::vector<DetailView> detailViews() {
  const std::int64_t u = kPerspectiveUnit;
  std::vector<DetailView> views;
  const auto add = [&](std::string name, ModelPoint eye, int yaw, int pitch, int fov, int width,
                       int height, bool recedes) {
    views.push_back(
        {std::move(name), perspectiveCameraOf(eye, yaw, pitch, fov, width, height), recedes});
  };
  // The default model stores depths 6, 7 and 8. With the eye 3 cube edges away depths 6 and 7
  // suffice; 2 edges away, 7 and 8; at the table's edge on 320x240 the far end takes 7; the
  // others need 8 everywhere (the same frame as depth 8 alone).
  add("outside, far", {0, 0, -3 * u}, 0, 0, 60, 320, 240, true);
  add("outside, nearer", {0, 0, -2 * u}, 0, 0, 60, 320, 240, true);
  add("outside, grazing", {0, u / 8, -3 * u / 2}, 10, 20, 60, 640, 480, false);
  add("at the table's edge", {0, 28 * u / 100, -46 * u / 100}, 0, 28, 90, 320, 240, true);
  add("at the table's edge, 1280x960", {0, 28 * u / 100, -46 * u / 100}, 0, 28, 90, 1280, 960,
      false);
  add("deep inside, wide", {u / 16, u / 8, 0}, 170, 30, 120, 320, 240, false);
  return views;
}

PerspectiveView detailViewOf(const PerspectiveCamera& camera) {
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  return view;
}

TEST(UpperTreeIndex, EveryEntryIsItsNodeWithItsFirstLeafAndItsChildren) {
  for (int i = 0; i < detailModel().levelCount(); ++i) {
    const LevelView& level = detailModel().level(i);
    SCOPED_TRACE("depth " + std::to_string(level.depth));
    std::vector<UpperTreeNode> storage(upperTreeEntries(level));
    ASSERT_FALSE(storage.empty());
    const UpperTreeIndex index = buildUpperTreeIndex(level, storage);
    ASSERT_EQ(index.bottom, level.depth - 3);
    // Not enough room: no index.
    EXPECT_EQ(buildUpperTreeIndex(level, std::span(storage).first(storage.size() - 1)).bottom, -1);
    // Walk the stream from each entry: the node's subtree holds as many leaves as the next node's
    // first leaf says, and its children are the entries first_child.. in order.
    std::size_t checked = 0;
    const auto check = [&](auto& self, std::uint32_t entry, int depth_of_node) -> void {
      const UpperTreeNode& node = index.entries[entry];
      const unsigned mask = level.nodes[node.node];
      ASSERT_NE(mask, 0u);
      ++checked;
      if (depth_of_node == index.bottom) return;
      std::uint32_t leaf = node.leaf;
      for (int c = 0; c < childCount(mask); ++c) {
        const UpperTreeNode& child = index.entries[node.first_child + static_cast<unsigned>(c)];
        EXPECT_EQ(child.leaf, leaf);
        // The child's first byte follows its parent's and its elder siblings' subtrees.
        if (c == 0) {
          EXPECT_EQ(child.node, node.node + 1);
        }
        self(self, node.first_child + static_cast<unsigned>(c), depth_of_node + 1);
        // Its leaves: count them by walking its bytes.
        const std::uint8_t* cursor = level.nodes.data() + child.node;
        const std::uint8_t* leaves = level.leaves.data() + child.leaf;
        skipSubtree(cursor, leaves, depth_of_node + 1, level.depth);
        leaf = static_cast<std::uint32_t>(leaves - level.leaves.data());
        if (c + 1 < childCount(mask)) {
          EXPECT_EQ(index.entries[node.first_child + static_cast<unsigned>(c) + 1].node,
                    static_cast<std::uint32_t>(cursor - level.nodes.data()));
        }
      }
    };
    check(check, 0, 0);
    EXPECT_EQ(checked, storage.size());
  }
}

// The walk through the index (nearest first above its bottom) hands over exactly the leaves, at
// exactly the positions, of the walk in stream order.
TEST(UpperTreeIndex, IndexedWalkHandsOverWhatTheStreamOrderWalkDoes) {
  const LevelView& level = detailModel().finestLevel();
  std::vector<UpperTreeNode> storage(upperTreeEntries(level));
  const UpperTreeIndex index = buildUpperTreeIndex(level, storage);
  int reordered = 0;
  for (const DetailView& v : detailViews()) {
    SCOPED_TRACE(v.name);
    const PerspectiveView view = detailViewOf(v.camera);
    const PerspectiveWalkTables tables =
        perspectiveWalkTables(view, level.depth, std::int64_t{1} << (kDefaultFractionBits - 2));
    using Handed = std::tuple<std::size_t, std::int64_t, std::int64_t, std::int64_t>;
    std::vector<Handed> in_order, indexed;
    auto record_in_order = [&](const PerspectiveLeaf& l) {
      in_order.emplace_back(l.index, l.x, l.y, l.z);
    };
    auto record_indexed = [&](const PerspectiveLeaf& l) {
      indexed.emplace_back(l.index, l.x, l.y, l.z);
    };
    PerspectiveWalk<decltype(record_in_order)> plain(level, view, tables, record_in_order);
    ASSERT_TRUE(plain.run());
    PerspectiveWalkParts parts;
    parts.index = &index;
    PerspectiveWalk<decltype(record_indexed)> through_index(level, view, tables, record_indexed,
                                                            nullptr, parts);
    ASSERT_TRUE(through_index.run());
    EXPECT_GT(in_order.size(), 1000u);
    reordered += !std::is_sorted(indexed.begin(), indexed.end());
    std::sort(indexed.begin(), indexed.end());
    EXPECT_EQ(in_order, indexed);
  }
  EXPECT_GT(reordered, 0);  // nearest first is not the stream's order
}

// Each layer's walk, with detail by distance, hands over voxels of its depth; every finest voxel
// in view lies in exactly one handed-over voxel of some depth, and none in two (no part drawn
// twice, none left out); each voxel handed over is drawn at the depth its own distance asks for
// (in double precision: a coarser one than the finest spans at most a pixel at its nearest
// point, and its ancestor at the next coarser depth more than a pixel at its own).
// `coarser`: each part that many stored depths coarser than its distance asks (the viewer's
// coarse frames), so the rule's pixel bounds do not hold, but the cover does.
void expectEveryPointDrawnOnce(int coarser) {
  const ModelView& model = detailModel();
  std::vector<int> depths;
  std::vector<std::vector<GridVoxel>> voxels;
  std::vector<std::vector<UpperTreeNode>> storage;
  std::vector<UpperTreeIndex> indexes;
  for (int i = 0; i < model.levelCount(); ++i) {
    depths.push_back(model.level(i).depth);
    voxels.push_back(gridVoxelsOf(model.level(i)));
    storage.emplace_back(upperTreeEntries(model.level(i)));
    indexes.push_back(buildUpperTreeIndex(model.level(i), storage.back()));
  }
  const int finest = depths.back();
  const std::size_t layers = depths.size();
  for (const DetailView& v : detailViews()) {
    SCOPED_TRACE(v.name);
    const PerspectiveView view = detailViewOf(v.camera);
    const PerspectiveDetail detail = perspectiveDetail(view, depths, coarser);
    const double f = focalOf(v.camera);
    // Handed-over voxels by depth and grid key.
    std::unordered_map<std::int64_t, int> drawn;  // key -> times handed over
    const auto key = [](int depth, const GridVoxel& g) {
      return (((static_cast<std::int64_t>(depth) << 16 | g.x) << 16 | g.y) << 16) | g.z;
    };
    std::vector<std::size_t> drawn_per_layer(layers, 0);
    for (std::size_t j = 0; j < layers; ++j) {
      const LevelView& level = model.level(static_cast<int>(j));
      const PerspectiveWalkTables tables =
          perspectiveWalkTables(view, level.depth, std::int64_t{1} << (kDefaultFractionBits - 2));
      PerspectiveWalkParts parts;
      parts.index = j % 2 == 0 ? &indexes[j] : nullptr;  // either way the same voxels
      parts.detail = {&detail, static_cast<int>(j), j == 0 ? -1 : depths[j - 1]};
      const double edge = kUnit / static_cast<double>(std::int64_t{1} << level.depth);
      auto record = [&](const PerspectiveLeaf& leaf) {
        const GridVoxel& g = voxels[j][leaf.index];
        ++drawn[key(level.depth, g)];
        ++drawn_per_layer[j];
        // Depth auto's rule at the voxel's nearest point: fine enough unless it is the finest.
        const double reach = edge * std::sqrt(3.0) / 2;
        if (coarser == 0 && j + 1 < layers) {
          EXPECT_LE(f * edge / (cameraCentreOf(v.camera, g, level.depth)[2] - reach), 1.001)
              << "depth " << level.depth;
        }
        if (coarser == 0 && j > 0) {  // and its ancestor at the next coarser depth was not
          const int up = level.depth - depths[j - 1];
          const GridVoxel a{g.x >> up, g.y >> up, g.z >> up};
          const double coarse_edge = edge * static_cast<double>(1 << up);
          EXPECT_GT(f * coarse_edge /
                        (cameraCentreOf(v.camera, a, depths[j - 1])[2] -
                         coarse_edge * std::sqrt(3.0) / 2),
                    0.999)
              << "depth " << level.depth;
        }
      };
      PerspectiveWalk<decltype(record)> walk(level, view, tables, record, nullptr, parts);
      ASSERT_TRUE(walk.run());
    }
    if (coarser > 0) {
      EXPECT_EQ(drawn_per_layer[layers - 1], 0u) << "the finest is never asked for";
    }
    // With the model far away the coarsest depth draws most; near, the finest.
    if (coarser == 0 && v.name == "outside, far") {
      EXPECT_GT(drawn_per_layer[0], 100u);
      EXPECT_EQ(drawn_per_layer[layers - 1], 0u);
    }
    if (coarser == 0 && v.name == "at the table's edge") {
      EXPECT_GT(drawn_per_layer[layers - 2], 100u);
      EXPECT_GT(drawn_per_layer[layers - 1], 10 * drawn_per_layer[layers - 2]);
    }
    std::size_t in_view = 0;
    for (const GridVoxel& g : voxels.back()) {
      int covering = 0;
      for (std::size_t j = 0; j < layers; ++j) {
        const int up = finest - depths[j];
        const auto found = drawn.find(key(depths[j], {g.x >> up, g.y >> up, g.z >> up}));
        if (found != drawn.end()) covering += found->second;
      }
      ASSERT_LE(covering, 1) << "a voxel drawn twice at " << g.x << "," << g.y << "," << g.z;
      const std::array<double, 3> c = cameraCentreOf(v.camera, g, finest);
      if (c[2] < static_cast<double>(v.camera.near) + kUnit / 256) continue;
      const Projected p = exactProjection(v.camera, c[0], c[1], c[2]);
      if (p.x < 0 || p.y < 0 || p.x >= v.camera.width || p.y >= v.camera.height) continue;
      ++in_view;
      ASSERT_EQ(covering, 1) << "a voxel in view left out at " << g.x << "," << g.y << "," << g.z;
    }
    EXPECT_GT(in_view, 1000u);
  }
}

TEST(PerspectiveDetail, EveryPointInViewIsDrawnByExactlyOneDepthChosenByItsDistance) {
  expectEveryPointDrawnOnce(0);
}

// The viewer's coarse frames (octopoint-view's walk mode, thread L): a stored depth coarser.
TEST(PerspectiveDetail, ADepthCoarserStillDrawsEveryPointInViewOnce) {
  expectEveryPointDrawnOnce(1);
}

struct DetailFrames {
  Framebuffer finest, by_distance;
  PerspectiveDrawStats finest_stats, by_distance_stats;
};

DetailFrames drawDetailFrames(const PerspectiveCamera& camera) {
  const ModelView& model = detailModel();
  PerspectiveRenderer renderer(model);
  const PerspectiveView view = detailViewOf(camera);
  DetailFrames frames{
      Framebuffer(camera.width, camera.height), Framebuffer(camera.width, camera.height), {}, {}};
  frames.finest.clear();
  frames.by_distance.clear();
  PerspectiveRenderer::Options one_depth;
  one_depth.depth = model.finestLevel().depth;
  EXPECT_TRUE(renderer.draw(view, one_depth, frames.finest, &frames.finest_stats));
  EXPECT_TRUE(renderer.draw(view, {}, frames.by_distance, &frames.by_distance_stats));
  return frames;
}

// The frame drawn with detail by distance covers what the finest depth's frame covers (its empty
// share of that silhouette, as docs/tradeoff.md measures it, is at most 1%), with fewer leaves.
TEST(PerspectiveDetail, FrameCoversTheFinestDepthsSilhouetteWithFewerLeaves) {
  for (const DetailView& v : detailViews()) {
    SCOPED_TRACE(v.name);
    const DetailFrames frames = drawDetailFrames(v.camera);
    std::int64_t silhouette = 0, empty = 0;
    for (std::int32_t y = 0; y < v.camera.height; ++y) {
      for (std::int32_t x = 0; x < v.camera.width; ++x) {
        if (!frames.finest.covered(x, y)) continue;
        ++silhouette;
        empty += !frames.by_distance.covered(x, y);
      }
    }
    EXPECT_GT(silhouette, 1000);
    EXPECT_LE(empty * 100, silhouette) << empty << " of " << silhouette << " pixels empty";
    if (v.recedes) {
      EXPECT_LT(frames.by_distance_stats.leaves, frames.finest_stats.leaves);
    } else {  // the same leaves
      EXPECT_EQ(frames.by_distance_stats.leaves, frames.finest_stats.leaves);
    }
  }
}

// The frames' checksums (CRC-32 of the pixel words, little-endian): the same on every build, so
// that scripts/test-armel checks an ARMv5 draws the same frames. A change of the rule or the walk
// that moves a pixel changes them (then check the new frames and update them).
TEST(PerspectiveDetail, FramesHaveTheirFixedChecksums) {
  const std::uint32_t expected[] = {0x05f2a33d, 0xc1683551, 0xa01de5da,
                                    0xba6e4892, 0xd5dc1bc1, 0x3109f9af};
  const std::vector<DetailView> views = detailViews();
  ASSERT_EQ(views.size(), std::size(expected));
  for (std::size_t i = 0; i < views.size(); ++i) {
    const DetailFrames frames = drawDetailFrames(views[i].camera);
    std::vector<std::uint8_t> bytes;
    for (const std::uint32_t word : frames.by_distance.pixels()) {
      for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<std::uint8_t>(word >> (8 * b)));
    }
    EXPECT_EQ(crc32(std::span<const std::uint8_t>(bytes)), expected[i])
        << views[i].name << std::hex << ": 0x" << crc32(std::span<const std::uint8_t>(bytes));
  }
}

}  // namespace
}  // namespace octopoint
