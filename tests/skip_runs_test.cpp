// skipSubtreeByRuns (renderer/skip_runs.h), fixed_fast's and fixed_simd's step over an off-screen
// subtree, leaves both cursors where skipSubtree (the byte walk) does, for every node of random
// trees of depth 1 to 10, sparse and dense, including subtrees that end at the stream's last byte.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "renderer/decode_algorithms.h"
#include "renderer/leaf_cursor.h"
#include "renderer/skip_runs.h"

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
        ASSERT_EQ(run, walked) << "depth " << depth << ", node at " << node.at << " (level " << node.level << ")";
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

}  // namespace
}  // namespace octopoint
