#pragma once
// COPC (the cloud-optimized point cloud, copc.io): a LAZ 1.4 file of point formats 6 to 8 whose
// variable chunks are the nodes of an octree. Its info VLR ("copc", record 1, the first VLR) gives
// the root cube (centre and half size, in the scan's units) and where the root hierarchy page
// lies; a hierarchy page is a run of 32-byte entries, each an octree key (level, x, y, z, as EPT
// names nodes) with the offset, byte size and point count of the node's chunk, or, with a point
// count of -1, the offset and size of another page that holds that node and those below it.
//
// The chunk table says where the chunks lie; the hierarchy adds where their points lie, so that a
// crop reads only the chunks whose cubes meet it (codegen/laz_reader.cpp). Everything is checked
// against the file before it is used; each failure is one PrepareError line naming the page and
// the entry.

#include <array>
#include <cstdint>
#include <vector>

#include "codegen/file_io.h"
#include "codegen/las_reader.h"

namespace octopoint::prepare {

// The deepest octree level a COPC key may have (a node 2^-24 of the root cube wide: far below any
// scan's precision; writers stop near 20).
inline constexpr std::int32_t kMaxCopcLevel = 24;

struct CopcKey {
  std::int32_t level = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::int32_t z = 0;
  friend bool operator==(const CopcKey&, const CopcKey&) = default;
};

// A node that has points: its key, its chunk, and its cube in the scan's coordinates.
struct CopcNode {
  CopcKey key;
  std::uint64_t offset = 0;  // the chunk's first byte
  std::uint64_t bytes = 0;
  std::uint64_t points = 0;
  std::array<double, 3> low{};
  std::array<double, 3> high{};
};

struct CopcHierarchy {
  std::array<double, 3> centre{};
  double halfsize = 0;
  std::uint64_t pages = 0;
  std::vector<CopcNode> nodes;  // every node with points, in the order the pages list them
};

// Reads and checks the info VLR and every hierarchy page of the COPC file `file` (its header has
// copc_vlr_offset set). The nodes' chunks lie in [data_start, data_end) (the chunk table and the
// EVLRs after it are the pages' place).
CopcHierarchy readCopcHierarchy(const InputFile& file, const LasHeader& header,
                                std::uint64_t data_start, std::uint64_t data_end);

// "level-x-y-z", as EPT and COPC name a node.
std::string copcKeyName(const CopcKey& key);

}  // namespace octopoint::prepare
