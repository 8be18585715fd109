#include "tests/support/copc_octree.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace octopoint::testing {
namespace {

constexpr std::size_t kEntryBytes = 32;

std::uint64_t packKey(int level, std::uint64_t x, std::uint64_t y, std::uint64_t z) {
  return std::uint64_t(level) << 48 | x << 32 | y << 16 | z;
}

template <typename T>
void put(std::vector<std::uint8_t>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

void putEntry(std::vector<std::uint8_t>& page, const CopcWriterNode& node, std::uint64_t offset,
              std::int32_t bytes, std::int32_t points) {
  const std::size_t at = page.size();
  page.resize(at + kEntryBytes);
  put<std::int32_t>(page, at, node.level);
  put<std::int32_t>(page, at + 4, node.x);
  put<std::int32_t>(page, at + 8, node.y);
  put<std::int32_t>(page, at + 12, node.z);
  put<std::uint64_t>(page, at + 16, offset);
  put<std::int32_t>(page, at + 24, bytes);
  put<std::int32_t>(page, at + 28, points);
}

bool under(const CopcWriterNode& node, const CopcWriterNode& top) {
  const int shift = node.level - top.level;
  return shift >= 0 && (node.x >> shift) == top.x && (node.y >> shift) == top.y &&
         (node.z >> shift) == top.z;
}

}  // namespace

CopcOctree buildCopcOctree(const std::uint8_t* records, std::size_t record_bytes, std::size_t count,
                           const std::array<double, 3>& scale, const std::array<double, 3>& offset,
                           const std::array<double, 3>& low, const std::array<double, 3>& high,
                           std::size_t capacity) {
  CopcOctree octree;
  double extent = 0;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    octree.centre[axis] = (low[axis] + high[axis]) / 2;
    extent = std::max(extent, high[axis] - low[axis]);
  }
  octree.halfsize = extent / 2 + std::max({scale[0], scale[1], scale[2]});
  // Each point's node: the first on its way down from the root that has room.
  std::vector<std::uint64_t> keys(count);
  octree.order.resize(count);
  for (std::size_t i = 0; i < count; ++i) octree.order[i] = static_cast<std::uint32_t>(i);
  std::sort(octree.order.begin(), octree.order.end(), [](std::uint32_t a, std::uint32_t b) {
    return std::uint64_t{a} * 0x9e3779b97f4a7c15ull < std::uint64_t{b} * 0x9e3779b97f4a7c15ull;
  });
  std::unordered_map<std::uint64_t, std::size_t> filled;
  for (const std::uint32_t i : octree.order) {
    std::array<double, 3> t{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      std::int32_t raw;
      std::memcpy(&raw, records + std::size_t{i} * record_bytes + 4 * axis, 4);
      const double v = raw * scale[axis] + offset[axis];
      t[axis] = (v - (octree.centre[axis] - octree.halfsize)) / (2 * octree.halfsize);
    }
    for (int level = 0;; ++level) {
      const double cells = std::ldexp(1.0, level);
      std::array<std::uint64_t, 3> cell{};
      for (std::size_t axis = 0; axis < 3; ++axis) {
        cell[axis] =
            static_cast<std::uint64_t>(std::clamp(std::floor(t[axis] * cells), 0.0, cells - 1));
      }
      const std::uint64_t key = packKey(level, cell[0], cell[1], cell[2]);
      std::size_t& n = filled[key];
      if (n < capacity || level == kCopcWriterLevels) {
        ++n;
        keys[i] = key;
        break;
      }
    }
  }
  std::sort(octree.order.begin(), octree.order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return keys[a] != keys[b] ? keys[a] < keys[b] : a < b;
  });
  for (std::size_t at = 0; at < count;) {
    const std::uint64_t key = keys[octree.order[at]];
    std::size_t end = at;
    while (end < count && keys[octree.order[end]] == key) ++end;
    octree.nodes.push_back({static_cast<std::int32_t>(key >> 48),
                            static_cast<std::int32_t>(key >> 32 & 0xffff),
                            static_cast<std::int32_t>(key >> 16 & 0xffff),
                            static_cast<std::int32_t>(key & 0xffff), at, end - at});
    at = end;
  }
  return octree;
}

std::vector<std::uint8_t> copcHierarchyPages(const CopcOctree& octree,
                                             const std::vector<CopcChunkPlace>& chunks,
                                             std::uint64_t at, std::uint64_t& root_bytes) {
  const auto entry = [&](std::vector<std::uint8_t>& page, std::size_t i) {
    putEntry(page, octree.nodes[i], chunks[i].offset, static_cast<std::int32_t>(chunks[i].bytes),
             static_cast<std::int32_t>(octree.nodes[i].count));
  };
  std::vector<std::uint8_t> root;
  if (octree.nodes.size() <= kCopcRootPageNodes) {
    for (std::size_t i = 0; i < octree.nodes.size(); ++i) entry(root, i);
    root_bytes = root.size();
    return root;
  }
  // The root page: the root, and a child page for each node of level 1 (its entry and below).
  std::vector<std::size_t> tops;
  for (std::size_t i = 0; i < octree.nodes.size(); ++i) {
    if (octree.nodes[i].level == 0) entry(root, i);
    if (octree.nodes[i].level == 1) tops.push_back(i);
  }
  std::vector<std::vector<std::uint8_t>> children;
  for (const std::size_t top : tops) {
    std::vector<std::uint8_t> page;
    for (std::size_t i = 0; i < octree.nodes.size(); ++i) {
      if (under(octree.nodes[i], octree.nodes[top])) entry(page, i);
    }
    children.push_back(std::move(page));
  }
  root_bytes = (root.size() / kEntryBytes + tops.size()) * kEntryBytes;
  std::uint64_t next = at + root_bytes;
  for (std::size_t t = 0; t < tops.size(); ++t) {
    putEntry(root, octree.nodes[tops[t]], next, static_cast<std::int32_t>(children[t].size()), -1);
    next += children[t].size();
  }
  for (const auto& page : children) root.insert(root.end(), page.begin(), page.end());
  return root;
}

std::vector<std::uint8_t> copcInfoPayload(const CopcOctree& octree, std::uint64_t root_offset,
                                          std::uint64_t root_bytes) {
  std::vector<std::uint8_t> info(160, 0);
  for (std::size_t axis = 0; axis < 3; ++axis) put<double>(info, 8 * axis, octree.centre[axis]);
  put<double>(info, 24, octree.halfsize);
  put<double>(info, 32, octree.halfsize / 64);  // the root's point spacing, roughly
  put<std::uint64_t>(info, 40, root_offset);
  put<std::uint64_t>(info, 48, root_bytes);
  return info;
}

}  // namespace octopoint::testing
