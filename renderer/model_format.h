#pragma once
// The octopoint model format: the layouts shared by the preparer that writes them, the `.oct`
// reader and the validators (docs/format.md explains them). All integers are little-endian. The
// preparer writes version 2; version 1 files stay readable.
//
// Version 2 (kVersion2):
//   offset   size     field
//   0        4        magic "OCTP"
//   4        2        format version, 2
//   6        1        level count L, 1..kMaxLevels
//   7        1        flags: v2::kFlagNormals, v2::kFlagSyntheticColour; other bits 0
//   8        8        cube edge in picometres (the metric size of the model cube; 0: not recorded)
//   16       2        palette colour count C, 1..256
//   18       2        normal count N: 0 without kFlagNormals, else 1..kMaxNormals
//   20       768      palette: 256 x RGB888; entries past C are 0
//   788      6 N      normal palette: N x (i16 x, i16 y, i16 z), unit vectors in Q1.14
//   788+6N   12 L     level table, one row per level, depths strictly ascending:
//                       u8 depth (1..kMaxDepth), u8[3] reserved 0, u32 node bytes, u32 leaf count
//   then, level by level: the node bytes, the palette index of each leaf (one byte per leaf) and,
//   with kFlagNormals, the normal index of each leaf (one byte per leaf, < N).
//
// Version 1 (kVersion1): the same without flags and normals, the cube edge in micrometres (u32):
//   0 magic, 4 version 1, 6 level count, 7 reserved 0, 8 u32 cube edge in micrometres,
//   12 u16 palette colour count, 14 u16 reserved 0, 16 palette (768 bytes), 784 level table,
//   then per level the node bytes and the palette index of each leaf.
//
// The node bytes of a level are its octree in depth-first order: each inner node is one child mask
// byte, bit k set when child k = (x << 2) | (y << 1) | z is occupied, followed by the subtrees of its
// occupied children in order k = 0..7. A node at depth `depth - 1` is a leaf parent: its children are
// leaves, which have no byte in the node stream; their palette (and normal) indices are in the leaf
// arrays in the order the depth-first walk meets them. This is PCL's OctreePointCloud::serializeTree
// order.

#include <cstddef>
#include <cstdint>

namespace octopoint::format {

inline constexpr char kMagic[4] = {'O', 'C', 'T', 'P'};
inline constexpr std::uint16_t kVersion1 = 1;
inline constexpr std::uint16_t kVersion2 = 2;
inline constexpr std::uint16_t kFormatVersion = kVersion2;  // what the preparer writes

inline constexpr int kMaxDepth = 16;     // 2^16 voxels per axis: far past any range scan's detail
inline constexpr int kMaxLevels = 8;     // streams of one scan at different depths
inline constexpr int kPaletteEntries = 256;
inline constexpr std::size_t kPaletteBytes = 3 * kPaletteEntries;
inline constexpr std::size_t kLevelRowBytes = 12;

// A normal index is one byte; 255 (not 256) entries at most, so that a pixel word carrying a
// normal index (Framebuffer, PixelPayload::kColourNormal) never equals the empty pixel's.
inline constexpr int kMaxNormals = 255;
// Normal palette entries are unit vectors in Q1.14: 1.0 is 2^14, so a dot product of two fits
// 32 bits (Q2.28). A stored entry's squared length must be within kNormalLengthTolerance of 2^28
// (rounding each component to Q1.14 moves it by at most about 2^15).
inline constexpr std::int32_t kNormalOne = 1 << 14;
inline constexpr std::int64_t kNormalLengthTolerance = 1 << 16;

namespace v1 {
inline constexpr std::size_t kPaletteOffset = 16;
inline constexpr std::size_t kHeaderBytes = 784;  // up to and including the palette
}  // namespace v1

namespace v2 {
inline constexpr std::uint8_t kFlagNormals = 1;          // normal palette and per-leaf normals
inline constexpr std::uint8_t kFlagSyntheticColour = 2;  // no scan colour: the palette is a shade
inline constexpr std::uint8_t kKnownFlags = kFlagNormals | kFlagSyntheticColour;
inline constexpr std::size_t kPaletteOffset = 20;
inline constexpr std::size_t kNormalPaletteOffset = 788;
inline constexpr std::size_t kNormalEntryBytes = 6;
inline constexpr std::size_t kFixedHeaderBytes = 788;  // before the normal palette
}  // namespace v2

}  // namespace octopoint::format
