// COPC's info VLR and hierarchy pages (codegen/copc_hierarchy.h), read and checked.

#include "codegen/copc_hierarchy.h"

#include <cmath>
#include <cstring>
#include <deque>
#include <sstream>
#include <string>
#include <unordered_set>

#include "codegen/little_endian.h"
#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

constexpr std::size_t kInfoBytes = 160;
constexpr std::uint64_t kEntryBytes = 32;
// The root cube's centre and half size are coordinates: no larger than a crop box's corners.
constexpr double kMaxCopcCoordinate = 1e13;

struct KeyHash {
  std::size_t operator()(const CopcKey& key) const {
    const std::uint64_t packed =
        (std::uint64_t(std::uint32_t(key.x)) << 40) ^ (std::uint64_t(std::uint32_t(key.y)) << 20) ^
        std::uint64_t(std::uint32_t(key.z)) ^ (std::uint64_t(std::uint32_t(key.level)) << 59);
    return static_cast<std::size_t>(packed * 0x9e3779b97f4a7c15ull);
  }
};

// A page still to read: the key of the node it starts at, and its bytes.
struct Page {
  CopcKey key;
  std::uint64_t offset = 0;
  std::uint64_t bytes = 0;
};

bool isUnder(const CopcKey& key, const CopcKey& top) {
  if (key.level < top.level) return false;
  const int shift = key.level - top.level;
  return (key.x >> shift) == top.x && (key.y >> shift) == top.y && (key.z >> shift) == top.z;
}

}  // namespace

std::string copcKeyName(const CopcKey& key) {
  return std::to_string(key.level) + "-" + std::to_string(key.x) + "-" + std::to_string(key.y) +
         "-" + std::to_string(key.z);
}

CopcHierarchy readCopcHierarchy(const InputFile& file, const LasHeader& header,
                                std::uint64_t data_start, std::uint64_t data_end) {
  const auto& path = file.path();
  const std::string info_where = "COPC info VLR at byte " + std::to_string(header.copc_vlr_offset);
  if (header.copc_vlr_bytes != kInfoBytes) {
    fail(path,
         "the COPC info VLR has " + std::to_string(header.copc_vlr_bytes) + " bytes, not " +
             std::to_string(kInfoBytes),
         info_where);
  }
  std::uint8_t info[kInfoBytes];
  file.readAt(header.copc_vlr_offset, info, info_where);
  CopcHierarchy hierarchy;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    hierarchy.centre[axis] = readLittle<double>(info + 8 * axis);
  }
  hierarchy.halfsize = readLittle<double>(info + 24);
  for (std::size_t axis = 0; axis < 4; ++axis) {
    const double value = axis < 3 ? hierarchy.centre[axis] : hierarchy.halfsize;
    if (!(std::fabs(value) <= kMaxCopcCoordinate) || (axis == 3 && !(value > 0))) {
      std::ostringstream what;
      what << "absurd COPC root cube: " << (axis < 3 ? "centre " : "half size ") << value
           << " (expected " << (axis < 3 ? "a finite value within +-" : "above 0, at most ")
           << kMaxCopcCoordinate << ")";
      fail(path, what.str(), info_where);
    }
  }
  if (!(header.point_format >= 6 && header.point_format <= 8)) {
    fail(path,
         "COPC holds point formats 6 to 8, this file has format " +
             std::to_string(header.point_format),
         info_where);
  }

  std::deque<Page> pages;
  pages.push_back(
      {CopcKey{}, readLittle<std::uint64_t>(info + 40), readLittle<std::uint64_t>(info + 48)});
  std::unordered_set<std::uint64_t> page_offsets;
  std::unordered_set<CopcKey, KeyHash> keys;
  std::uint64_t page_bytes_read = 0;
  std::vector<std::uint8_t> bytes;
  while (!pages.empty()) {
    const Page page = pages.front();
    pages.pop_front();
    const std::string where = "COPC hierarchy page at byte " + std::to_string(page.offset) +
                              " (node " + copcKeyName(page.key) + ")";
    if (page.bytes == 0 || page.bytes % kEntryBytes != 0 || page.offset > file.size() ||
        page.bytes > file.size() - page.offset) {
      fail(path,
           "a hierarchy page of " + std::to_string(page.bytes) + " bytes at byte " +
               std::to_string(page.offset) + " (whole 32-byte entries, inside the file's " +
               std::to_string(file.size()) + " bytes)",
           where);
    }
    // Each page is read once: a page listed twice (a cycle) would be read forever, and pages
    // overlapping each other could make the reader read more than the file.
    if (!page_offsets.insert(page.offset).second) {
      fail(path, "the hierarchy page at byte " + std::to_string(page.offset) + " is listed twice",
           where);
    }
    page_bytes_read += page.bytes;
    if (page_bytes_read > file.size()) {
      fail(path,
           "the hierarchy pages add up to more than the file's " + std::to_string(file.size()) +
               " bytes",
           where);
    }
    ++hierarchy.pages;
    bytes.resize(static_cast<std::size_t>(page.bytes));
    file.readAt(page.offset, bytes, where);
    for (std::uint64_t e = 0; e < page.bytes / kEntryBytes; ++e) {
      const std::uint8_t* entry = bytes.data() + e * kEntryBytes;
      const CopcKey key{readLittle<std::int32_t>(entry), readLittle<std::int32_t>(entry + 4),
                        readLittle<std::int32_t>(entry + 8), readLittle<std::int32_t>(entry + 12)};
      const auto offset = readLittle<std::uint64_t>(entry + 16);
      const auto byte_size = readLittle<std::int32_t>(entry + 24);
      const auto point_count = readLittle<std::int32_t>(entry + 28);
      const std::string entry_where = "entry " + std::to_string(e + 1) + " of " +
                                      std::to_string(page.bytes / kEntryBytes) + ", node " +
                                      copcKeyName(key) + ", " + where;
      const auto refuse = [&](const std::string& what) { fail(path, what, entry_where); };
      if (key.level < 0 || key.level > kMaxCopcLevel) {
        refuse("octree level " + std::to_string(key.level) + " (0 to " +
               std::to_string(kMaxCopcLevel) + " are read)");
      }
      const std::int64_t cells = std::int64_t{1} << key.level;
      if (key.x < 0 || key.y < 0 || key.z < 0 || key.x >= cells || key.y >= cells ||
          key.z >= cells) {
        refuse("the key lies outside the octree (x, y and z 0 to " + std::to_string(cells - 1) +
               " at level " + std::to_string(key.level) + ")");
      }
      if (!isUnder(key, page.key)) {
        refuse("the node is not under the page's node " + copcKeyName(page.key));
      }
      if (point_count == -1) {
        if (byte_size <= 0) refuse("a child page of " + std::to_string(byte_size) + " bytes");
        pages.push_back({key, offset, static_cast<std::uint64_t>(byte_size)});
        continue;
      }
      if (point_count < -1) refuse("a point count of " + std::to_string(point_count));
      if (!keys.insert(key).second) refuse("the node is listed twice");
      if (point_count == 0) continue;  // a node without points, above nodes with them
      if (byte_size <= 0 || offset < data_start || offset > data_end ||
          static_cast<std::uint64_t>(byte_size) > data_end - offset) {
        refuse("the node's chunk of " + std::to_string(byte_size) + " bytes at byte " +
               std::to_string(offset) + " lies outside the point data (" +
               std::to_string(data_start) + " to " + std::to_string(data_end) + ")");
      }
      CopcNode node{key, offset, static_cast<std::uint64_t>(byte_size),
                    static_cast<std::uint64_t>(point_count)};
      const double side = std::ldexp(2 * hierarchy.halfsize, -key.level);
      const std::array<std::int32_t, 3> at = {key.x, key.y, key.z};
      for (std::size_t axis = 0; axis < 3; ++axis) {
        node.low[axis] = hierarchy.centre[axis] - hierarchy.halfsize + at[axis] * side;
        node.high[axis] = node.low[axis] + side;
      }
      hierarchy.nodes.push_back(node);
    }
  }
  return hierarchy;
}

}  // namespace octopoint::prepare
