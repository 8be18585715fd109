// skipSubtreeByRuns and skipSubtreeIndexed (renderer/skip_runs.h), fixed_fast's and fixed_simd's
// steps over an off-screen subtree, leave both cursors where skipSubtree (the byte walk) does, for
// every node of random trees of depth 1 to 10, sparse and dense, including subtrees that end at the
// stream's last byte; the skip index (octopoint/model.h) is what ModelView attaches.
#include "renderer/skip_runs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/models.h"
#include "renderer/decode_algorithms.h"
#include "renderer/leaf_cursor.h"

namespace octopoint {
namespace {

struct Node {
  std::size_t at;      // its mask byte's offset in the stream
  std::size_t leaves;  // leaves before its subtree
  int level;
};

// A random depth-first stream of `depth` levels (each child present with probability `density`,
// a node keeps at least one), and every node's place in it.
std::vector<std::uint8_t> randomStream(int depth, double density, std::mt19937& random,
                                       std::vector<Node>& nodes) {
  std::bernoulli_distribution present(density);
  std::vector<std::uint8_t> stream;
  std::size_t leaves = 0;
  auto grow = [&](auto& self, int level) -> void {
    unsigned mask = 0;
    while (mask == 0) {
      for (unsigned k = 0; k < 8; ++k) mask |= present(random) ? 1u << k : 0u;
    }
    nodes.push_back({stream.size(), leaves, level});
    stream.push_back(static_cast<std::uint8_t>(mask));
    for (int child = std::popcount(mask); child > 0; --child) {
      if (level + 1 == depth) {
        ++leaves;
      } else {
        self(self, level + 1);
      }
    }
  };
  grow(grow, 0);
  stream.shrink_to_fit();  // under ASan, a load past the stream's last byte fails
  return stream;
}

TEST(SkipRuns, LeavesBothCursorsWhereTheByteWalkDoes) {
  std::mt19937 random(11);
  int compared = 0;
  for (int depth = 1; depth <= 10; ++depth) {
    for (double density : {0.15, 0.45, 0.9}) {
      if (density > 0.5 && depth > 6) continue;  // millions of leaves
      std::vector<Node> nodes;
      const std::vector<std::uint8_t> stream = randomStream(depth, density, random, nodes);
      const std::uint8_t* const end = stream.data() + stream.size();
      const std::vector<std::uint8_t> colours(1, 0);
      for (const Node& node : nodes) {
        const std::uint8_t* walked = stream.data() + node.at;
        const std::uint8_t* walked_leaves = colours.data() + node.leaves;  // never dereferenced
        skipSubtree(walked, walked_leaves, node.level, depth);
        const std::uint8_t* run = stream.data() + node.at;
        ColourLeaves run_leaves{colours.data() + node.leaves};
        skipSubtreeByRuns(run, run_leaves, node.level, depth, end);
        ASSERT_EQ(run, walked) << "depth " << depth << ", node at " << node.at << " (level "
                               << node.level << ")";
        ASSERT_EQ(run_leaves.colour, walked_leaves) << "depth " << depth << ", node at " << node.at;
        ++compared;
      }
      // The root's subtree is the whole stream.
      const std::uint8_t* root = stream.data();
      const std::uint8_t* root_leaves = colours.data();
      skipSubtreeByRuns(root, root_leaves, 0, depth, end);
      EXPECT_EQ(root, end);
    }
  }
  EXPECT_GT(compared, 100000);
}

// Every node at or above the indexed level (the leaves' great-grandparents) of random trees of
// depth 4 to 10: skipSubtreeIndexed leaves both cursors where the byte walk does, and the count of
// index-level nodes passed at the first one after the subtree.
TEST(SkipRuns, IndexedSkipLeavesBothCursorsWhereTheByteWalkDoes) {
  std::mt19937 random(12);
  int compared = 0;
  for (int depth = 4; depth <= 10; ++depth) {
    for (double density : {0.15, 0.45, 0.9}) {
      if (density > 0.5 && depth > 6) continue;  // millions of leaves
      std::vector<Node> nodes;
      const std::vector<std::uint8_t> stream = randomStream(depth, density, random, nodes);
      std::size_t leaf_count = 0;  // the leaf parents' children
      for (const Node& node : nodes) {
        if (node.level + 1 == depth)
          leaf_count += static_cast<std::size_t>(std::popcount(stream[node.at]));
      }
      const std::vector<std::uint8_t> colours(leaf_count, 0);
      const LevelView level{depth, stream, colours};
      const int index_level = skipIndexLevel(depth);
      ASSERT_EQ(index_level, depth - 3);
      std::vector<std::size_t> indexed_at;  // the stream offsets of the index-level nodes, in order
      for (const Node& node : nodes) {
        if (node.level == index_level) indexed_at.push_back(node.at);
      }
      ASSERT_EQ(skipIndexEntries(level), indexed_at.size());
      std::vector<SubtreeEnd> storage(indexed_at.size());
      const SkipIndex index = buildSkipIndex(level, storage);
      ASSERT_EQ(index.level, index_level);
      ASSERT_EQ(index.ends.size(), indexed_at.size());
      // Too little storage: no index.
      EXPECT_EQ(buildSkipIndex(level, std::span(storage).first(storage.size() - 1)).level, 0);
      for (const Node& node : nodes) {
        if (node.level > index_level) continue;
        const std::uint8_t* walked = stream.data() + node.at;
        const std::uint8_t* walked_leaves = colours.data() + node.leaves;
        skipSubtree(walked, walked_leaves, node.level, depth);
        const auto before = [&](std::size_t offset) {  // index-level nodes before `offset`
          return static_cast<std::size_t>(
              std::lower_bound(indexed_at.begin(), indexed_at.end(), offset) - indexed_at.begin());
        };
        std::size_t next = before(node.at);
        const std::uint8_t* jumped = stream.data() + node.at;
        ColourLeaves jumped_leaves{colours.data() + node.leaves};
        skipSubtreeIndexed(jumped, jumped_leaves, next, node.level, index, stream.data(),
                           colours.data());
        ASSERT_EQ(jumped, walked) << "depth " << depth << ", node at " << node.at << " (level "
                                  << node.level << ")";
        ASSERT_EQ(jumped_leaves.colour, walked_leaves)
            << "depth " << depth << ", node at " << node.at;
        ASSERT_EQ(next, before(static_cast<std::size_t>(walked - stream.data())))
            << "depth " << depth << ", node at " << node.at;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 5000);
}

// ModelView attaches an index to every level of depth 4 or more, at the leaves' great-grandparents,
// and a copy of the view keeps it after the view it was copied from is gone.
TEST(SkipRuns, ModelViewIndexesEveryLevelOfDepthFourOrMore) {
  ModelIssue issue;
  std::optional<ModelView> copy;
  {
    const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    ASSERT_TRUE(model.has_value()) << describe(issue.error);
    copy = *model;
  }
  for (int i = 0; i < copy->levelCount(); ++i) {
    const LevelView& level = copy->level(i);
    ASSERT_GE(level.depth, 4);
    ASSERT_EQ(level.skip.level, level.depth - 3);
    ASSERT_EQ(level.skip.ends.size(), skipIndexEntries(level));
    std::vector<SubtreeEnd> rebuilt(skipIndexEntries(level));
    const SkipIndex index = buildSkipIndex(level, rebuilt);
    ASSERT_TRUE(std::ranges::equal(index.ends, level.skip.ends,
                                   [](const SubtreeEnd& a, const SubtreeEnd& b) {
                                     return a.node == b.node && a.leaf == b.leaf;
                                   }))
        << "depth " << level.depth;
    // The last index-level subtree ends where the level does.
    EXPECT_EQ(level.skip.ends.back().node, level.nodes.size());
    EXPECT_EQ(level.skip.ends.back().leaf, level.leaves.size());
  }
}

}  // namespace
}  // namespace octopoint
