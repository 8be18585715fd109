#pragma once
// COPC for tests and scale runs (tests/support/las_writer.h writes the file around it): the points
// sorted into an octree of nodes as COPC writers do (copc.io), and the hierarchy pages that name
// each node's chunk. A node keeps up to `capacity` points, taken in a scrambled order so that each
// node holds an even sample of its cube; the rest go to its children, down to kCopcWriterLevels.
// Written independently of the reader (codegen/copc_hierarchy.h), from the specification.

#include <array>
#include <cstdint>
#include <vector>

namespace octopoint::testing {

// The deepest level written: a node at it takes every point that reaches it.
inline constexpr int kCopcWriterLevels = 16;

struct CopcWriterNode {
  std::int32_t level = 0, x = 0, y = 0, z = 0;
  std::size_t first = 0;  // into CopcOctree::order
  std::size_t count = 0;
};

struct CopcOctree {
  std::array<double, 3> centre{};
  double halfsize = 0;
  std::vector<std::uint32_t> order;   // record indices, node by node
  std::vector<CopcWriterNode> nodes;  // by level, then x, y, z
};

// Sorts `count` records (LAS point format 6 to 8: X, Y, Z as int32 at bytes 0, 4, 8) into an
// octree of nodes of at most `capacity` points (but the deepest), the root cube the bounds'.
CopcOctree buildCopcOctree(const std::uint8_t* records, std::size_t record_bytes, std::size_t count,
                           const std::array<double, 3>& scale, const std::array<double, 3>& offset,
                           const std::array<double, 3>& low, const std::array<double, 3>& high,
                           std::size_t capacity);

// Where each node's chunk went (in the order of CopcOctree::nodes).
struct CopcChunkPlace {
  std::uint64_t offset = 0;
  std::uint64_t bytes = 0;
};

// The hierarchy pages, to be written at file offset `at`: the root page first, which lists the
// root and, when there are more than kCopcRootPageNodes nodes, a child page for each node of level
// 1, each listing that node and every node below it. `root_bytes` gets the root page's size.
inline constexpr std::size_t kCopcRootPageNodes = 16;
std::vector<std::uint8_t> copcHierarchyPages(const CopcOctree& octree,
                                             const std::vector<CopcChunkPlace>& chunks,
                                             std::uint64_t at, std::uint64_t& root_bytes);

// The 160 bytes of the COPC info VLR.
std::vector<std::uint8_t> copcInfoPayload(const CopcOctree& octree, std::uint64_t root_offset,
                                          std::uint64_t root_bytes);

}  // namespace octopoint::testing
