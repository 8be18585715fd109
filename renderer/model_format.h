#pragma once
// The octopoint model format, version 1: the layout shared by the preparer that writes it, the
// `.oct` reader and the validator. All integers are little-endian.
//
//   offset  size        field
//   0       4           magic "OCTP"
//   4       2           format version (kFormatVersion)
//   6       1           level count L, 1..kMaxLevels
//   7       1           reserved, 0
//   8       4           cube edge in micrometres (the metric size of the model cube)
//   12      2           palette colour count, 1..256
//   14      2           reserved, 0
//   16      768         palette: 256 x RGB888; entries past the count are 0
//   784     12 * L      level table, one row per level, depths strictly ascending:
//                         u8 depth (1..kMaxDepth), u8[3] reserved 0, u32 node bytes, u32 leaf count
//   then, level by level: the node bytes, then the leaf palette indices (one byte per leaf).
//
// The node bytes of a level are its octree in depth-first order: each inner node is one child mask
// byte, bit k set when child k = (x << 2) | (y << 1) | z is occupied, followed by the subtrees of its
// occupied children in order k = 0..7. A node at depth `depth - 1` is a leaf parent: its children are
// leaves, which have no byte in the node stream; their palette indices are in the leaf array in the
// order the depth-first walk meets them. This is PCL's OctreePointCloud::serializeTree order.

#include <cstddef>
#include <cstdint>

namespace octopoint::format {

inline constexpr char kMagic[4] = {'O', 'C', 'T', 'P'};
inline constexpr std::uint16_t kFormatVersion = 1;
inline constexpr int kMaxDepth = 16;     // 2^16 voxels per axis: far past any range scan's detail
inline constexpr int kMaxLevels = 8;     // streams of one scan at different depths
inline constexpr int kPaletteEntries = 256;

inline constexpr std::size_t kHeaderBytes = 784;     // up to and including the palette
inline constexpr std::size_t kPaletteOffset = 16;
inline constexpr std::size_t kLevelRowBytes = 12;

}  // namespace octopoint::format
