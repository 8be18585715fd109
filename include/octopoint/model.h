#pragma once
// octopoint/model.h: Models: the format's constants, embedded models, and the validated ModelView
// every renderer draws. The manual of the whole library is octopoint/octopoint.h.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

// The octopoint model format: the layouts shared by the preparer that writes them, the `.oct`
// reader and the validators (docs/format.md explains them). All integers are little-endian. The
// preparer writes version 6; versions 1, 2 and 4 stay readable.
//
// Version 6 (kVersion6): version 4 with each level's sample reach in its level table row: byte 1
// of the row (the first of version 4's reserved bytes) is the reach in sixteenths of a voxel
// footprint (Q4), kOneSampleReachQ4..kMaxSampleReachQ4 (docs/splats.md, "Samples coarser than the
// voxel"); bytes 2 and 3 stay reserved 0. Older versions read as one footprint.
//
// Version 4 (kVersion4): version 2 with the cube's placement (CubePlacement, below): the same
// fields, and after the normal palette (at 788 + 6 N) format::kCubePlacementBytes bytes, then the
// level table and the levels as in version 2.
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
// byte, bit k set when child k = (x << 2) | (y << 1) | z is occupied, followed by the subtrees of
// its occupied children in order k = 0..7. A node at depth `depth - 1` is a leaf parent: its
// children are leaves, which have no byte in the node stream; their palette (and normal) indices
// are in the leaf arrays in the order the depth-first walk meets them. This is PCL's
// OctreePointCloud::serializeTree order.

namespace octopoint::format {

inline constexpr char kMagic[4] = {'O', 'C', 'T', 'P'};
inline constexpr std::uint16_t kVersion1 = 1;
inline constexpr std::uint16_t kVersion2 = 2;
inline constexpr std::uint16_t kVersion4 = 4;  // version 2 and the cube's placement
inline constexpr std::uint16_t kVersion6 = 6;  // version 4 and each level's sample reach
inline constexpr std::uint16_t kFormatVersion = kVersion6;  // what the preparer writes

// A level's sample reach (version 6's level table, octopoint/camera.h's buildFrameSetup): how wide
// its splats are drawn, in sixteenths of a voxel footprint (Q4): one footprint (what versions 1 to
// 4 mean) to 8 (samples 8 voxels apart). A stored 0, or more than 8 footprints, is refused.
inline constexpr std::uint8_t kOneSampleReachQ4 = 16;
inline constexpr std::uint8_t kMaxSampleReachQ4 = 128;

inline constexpr int kMaxDepth = 16;  // 2^16 voxels per axis: far past any range scan's detail
inline constexpr int kMaxLevels = 8;  // streams of one scan at different depths
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

// The cube's placement block (versions 4 and 5; CubePlacement): f64 corner x, y, z, f64 edge,
// u8 scan axes (kScanAxesYDown or kScanAxesYUp), 7 reserved bytes 0.
inline constexpr std::size_t kCubePlacementBytes = 40;
inline constexpr std::uint8_t kScanAxesYDown = 0;  // the scan's axes are the model's
inline constexpr std::uint8_t kScanAxesYUp = 1;    // the model is the scan turned 180 deg about x

}  // namespace octopoint::format

namespace octopoint {

// Where the model cube lies in the scan it was made from (format versions 4 and 5): its lowest
// corner and its edge in the scan's own units and axes, the frame octopoint-prepare's --crop
// takes, so that a user can relate a point of the scan to the model (octopoint-render --info,
// --eye). Stored as the bit patterns of IEEE-754 binary64 numbers (little-endian u64s): exact for
// any scan the preparer reads (LAS coordinates reach 10^7 and more), and carried by the integer
// renderer without computing with them; a tool converts them (std::bit_cast). The model's axes
// (x right, y down, z away) are the scan's, or with kScanAxesYUp the scan's turned 180 degrees
// about x (model = (x, -y, -z) of the scan). Not recorded (versions 1 to 3, or a model made by
// hand): every field 0.
struct CubePlacement {
  std::uint64_t corner_bits[3] = {0, 0, 0};  // binary64: the corner of the lowest x, y and z
  std::uint64_t edge_bits = 0;               // binary64: the edge, > 0; 0 when not recorded
  std::uint8_t scan_axes = format::kScanAxesYDown;

  bool recorded() const { return edge_bits != 0; }
  bool operator==(const CubePlacement&) const = default;
};

// Whether `cube` is one a file may hold: not recorded (all zero), or finite corner coordinates, an
// edge above 0 and finite, and known axes. Integer tests of the bits only (no float arithmetic).
[[nodiscard]] bool validCubePlacement(const CubePlacement& cube);

}  // namespace octopoint

// The shape of a model compiled into an app: plain aggregates of pointers to const arrays, so the
// preparer's generated sources initialise them at compile time (no constructor runs, no file I/O).
// Use it through ModelView::fromEmbedded, which validates it once. The fields mean what the same
// fields of a version 2 `.oct` file mean (octopoint/model.h).

namespace octopoint {

struct EmbeddedLevel {
  std::uint8_t depth;
  const std::uint8_t* nodes;  // depth-first child mask bytes
  std::uint32_t node_bytes;
  const std::uint8_t* leaves;  // palette index per leaf
  std::uint32_t leaf_count;
  const std::uint8_t* normals = nullptr;  // normal index per leaf; nullptr: no normals
  // Version 6: the level's sample reach in sixteenths of a footprint (format::kOneSampleReachQ4..
  // kMaxSampleReachQ4); older versions end before it and leave it 0 (one footprint).
  std::uint8_t sample_reach = 0;
};

struct EmbeddedModel {
  const char* name;
  // The format version the generated arrays follow (format::kVersion6; kVersion4 for sources
  // generated before the levels' sample reach, kVersion2 before the cube's placement); a source
  // generated for another layout fails to compile or is refused (kUnsupportedVersion).
  std::uint16_t format_version;
  std::uint8_t flags;          // format::v2::kFlag*
  std::uint64_t cube_edge_pm;  // the model cube's edge in picometres; 0: not recorded
  std::uint16_t palette_count;
  const std::uint8_t* palette_rgb;  // 256 x RGB888
  std::uint16_t normal_count;       // 0 without normals
  const std::int16_t* normal_xyz;   // normal_count x (x, y, z) in Q1.14, or nullptr
  std::uint8_t level_count;
  const EmbeddedLevel* levels;  // depths strictly ascending
  // Version 4: where the cube lies in the scan (octopoint/model.h); version 2 sources, which end
  // before it, leave it unrecorded.
  CubePlacement cube = {};
};

}  // namespace octopoint

// Where the subtrees of one tree level end in a level's depth-first stream: what lets fixed_fast
// and fixed_simd step over an off-screen subtree without reading its bytes (renderer/skip_runs.h,
// skipSubtreeIndexed).
//
// A depth-first stream has no index: zoomed in, most of a frame's subtrees are off screen, and
// passing one meant reading all its mask bytes to find where the next begins (lms400 at depth 9,
// 176x208 zoom 4: 27% of the frame's instructions). The index records, for every node of one tree
// level in stream order, the offsets just past its subtree in the node stream and in the leaves. A
// walk that counts the nodes of that level it passes knows which entry is next; an off-screen
// subtree at that level is then one look-up, one above it costs only its nodes above that level.
//
// It depends on the model only, not on the camera: ModelView builds it once when it validates a
// model, on the heap (hosted builds; a bare-metal build has none and keeps the byte walk), 8 bytes
// per node of the indexed level, the leaves' great-grandparents. Each of those has at least 3 mask
// bytes below and at it, so the index is at most 8/3 of a level's node bytes; measured, 6% of the
// nodes: 55 KB for lms400 at depths 6..9 (a 404 KB file), 16 KB for the default model (125 KB).
// It is built from a validated stream only, so a corrupt one fails validation before. Frames are
// the same bit for bit with the index or without it.

namespace octopoint {

struct LevelView;

struct SubtreeEnd {
  std::uint32_t node;  // node stream offset just past the subtree
  std::uint32_t leaf;  // leaf offset just past it (its last leaf's index + 1)
};

#if !defined(OCTOPOINT_BARE_METAL)
struct SkipIndex {
  int level = 0;                     // the indexed tree level, >= 1; 0: no index
  std::span<const SubtreeEnd> ends;  // one per node at `level`, in stream order
};
#else
// A bare-metal build has no index: an empty type, which costs a LevelView no RAM
// ([[no_unique_address]]); the decoders' indexed branch is never taken.
struct SkipIndex {
  static constexpr int level = 0;
  static constexpr std::span<const SubtreeEnd> ends{};
};
#endif

// The tree level ModelView indexes in a level of `depth`: the leaves' great-grandparents
// (depth - 3), or 0 (none) for depths below 4, whose subtrees are a few bytes.
int skipIndexLevel(int depth);

// The number of entries the index of `level` needs (its nodes at skipIndexLevel), 0 when none;
// also 0 when an offset would not fit 32 bits.
std::size_t skipIndexEntries(const LevelView& level);

// Fills `storage` (at least skipIndexEntries(level) entries) and returns the index, or no index
// (level 0) when `level` has none or the storage is too small. `level` must be validated
// (ModelView): the walk trusts its stream.
SkipIndex buildSkipIndex(const LevelView& level, std::span<SubtreeEnd> storage);

}  // namespace octopoint

// A validated, read-only view of a model: the palette and one octree stream per depth. The bytes
// belong to someone else (const arrays compiled into the app, or a file buffer); the view never
// copies them. A ModelView can only be made by validation, so the decoders may trust it: every
// walk of a level reads exactly its node bytes and its leaf indices, never past them. What it
// owns is derived from them once, at validation: each level's skip index (octopoint/model.h),
// shared by the view's copies (hosted builds).

namespace octopoint {

enum class ModelError : std::uint8_t {
  kNone,
  kTruncatedHeader,       // fewer bytes than the header and level table need
  kBadMagic,              // not an octopoint model
  kUnsupportedVersion,    // a version this reader does not know
  kBadLevelCount,         // 0 or more than format::kMaxLevels levels
  kBadReservedField,      // a reserved field is not zero
  kBadPaletteCount,       // 0 or more than 256 colours
  kBadDepth,              // a depth outside 1..format::kMaxDepth
  kDepthsNotAscending,    // the same depth twice, or depths out of order
  kSizeMismatch,          // the declared sizes do not add up to the buffer length
  kEmptyLevel,            // a level without nodes or leaves
  kEmptyNode,             // a child mask byte of 0: an inner node without children
  kStreamTruncated,       // the tree needs more node bytes than declared
  kTrailingNodeBytes,     // the tree ends before the declared node bytes do
  kLeafCountMismatch,     // the tree has a different number of leaves than declared
  kLeafOutsidePalette,    // a leaf names a colour past the palette count
  kImplausibleLevelSize,  // node bytes and leaf count no tree of that depth can have
  kBadNormalCount,        // normals flagged without entries, entries without the flag, or > 255
  kBadNormalVector,       // a normal palette entry that is not a unit vector in Q1.14
  kNormalOutsidePalette,  // a leaf names a normal past the normal palette count
  kBadCubePlacement,      // the cube's placement is not finite, its edge not above 0, or bad axes
  kBadSampleReach,        // version 6: a level's sample reach outside 16..128 (Q4 footprints)
};

// A short, stable English description of an error, for one-line messages.
const char* describe(ModelError error);

struct ModelIssue {
  ModelError error = ModelError::kNone;
  // Where it was found: from fromBytes, the byte of the model image (the `.oct` file) at fault, be
  // it in the header, the level table or a stream; otherwise (fromEmbedded, validateLevelStream)
  // the byte of the level's node stream, or the leaf's index for a leaf colour.
  std::size_t offset = 0;
  int depth = 0;                // the level concerned, 0 when the header is at fault
  bool offset_in_file = false;  // offset counts from the start of the model image
};

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

struct LevelView {
  int depth = 0;
  std::span<const std::uint8_t> nodes;
  std::span<const std::uint8_t> leaves;     // one palette index per leaf, in depth-first order
  std::span<const std::uint8_t> normals{};  // one normal index per leaf, or empty (no normals)
  // Where the subtrees of one tree level end (octopoint/model.h), or none: ModelView sets it.
  // It must describe exactly this stream; fixed_fast and fixed_simd trust it as they trust nodes.
  // It points into the ModelView's own memory (shared by its copies): a LevelView taken from a
  // ModelView must not outlive the last copy of that view. A view of part of a stream (a band
  // renderer's subtree, a chunk) is built without it.
  [[no_unique_address]] SkipIndex skip{};
};

// A normal palette entry: a unit vector in Q1.14 (format::kNormalOne is 1.0), in the model's axes
// (x right, y down, z away from the sensor).
struct NormalQ14 {
  std::int16_t x = 0, y = 0, z = 0;
  bool operator==(const NormalQ14&) const = default;
};

class ModelView {
 public:
  // Validates a model image in the format of model_format.h (a whole `.oct` file, version 1, 2,
  // 4 or 6).
  // The view points into `bytes`, which must outlive it.
  [[nodiscard]] static std::optional<ModelView> fromBytes(std::span<const std::uint8_t> bytes,
                                                          ModelIssue* issue);
  // The checks of fromBytes that need no level data, for a reader that has only the image's first
  // bytes (`head`: at least the header and the level table, at most 2,454 bytes; more are
  // ignored) and its size (`image_bytes`): the header; the level table's sizes adding up to
  // exactly `image_bytes`; each level's depth, and its sizes possible for a tree of that depth.
  // So a file whose header lies is refused before its body is read. False with the issue (as
  // fromBytes would report it) otherwise.
  [[nodiscard]] static bool checkDeclaredSizes(std::span<const std::uint8_t> head,
                                               std::uint64_t image_bytes, ModelIssue* issue);
  // Validates a model compiled into the app by the preparer's generated sources.
  [[nodiscard]] static std::optional<ModelView> fromEmbedded(const EmbeddedModel& model,
                                                             ModelIssue* issue);

  int formatVersion() const { return format_version_; }
  // The model cube's edge in picometres (0: not recorded). Version 1 files stored micrometres.
  std::uint64_t cubeEdgePicometres() const { return cube_edge_pm_; }
  // Where the cube lies in the scan (versions 4 and 5); not recorded in older models.
  const CubePlacement& cubePlacement() const { return cube_; }
  int paletteCount() const { return palette_count_; }
  Rgb paletteColour(int index) const;
  // True when the scan had no colour and the palette is a shade the preparer made up (a depth
  // shade): styles that light the model then draw it grey.
  bool colourIsSynthetic() const { return colour_is_synthetic_; }
  bool hasNormals() const { return normal_count_ > 0; }
  int normalCount() const { return normal_count_; }  // 0 without normals
  NormalQ14 normal(int index) const;
  int levelCount() const { return level_count_; }
  const LevelView& level(int i) const { return levels_[static_cast<std::size_t>(i)]; }
  // The level of exactly this depth, or nullptr.
  const LevelView* levelOfDepth(int depth) const;
  // How wide level i's splats are drawn, in sixteenths of a voxel footprint (Q4, the sample_reach
  // of buildFrameSetup, octopoint/camera.h): stored by version 6 (format::kOneSampleReachQ4..
  // kMaxSampleReachQ4), one footprint (16) in older models.
  std::int32_t sampleReach(int i) const { return reaches_[static_cast<std::size_t>(i)]; }
  // The reach of the level of exactly this depth; one footprint when the model has no such level.
  std::int32_t sampleReachOfDepth(int depth) const;
  const LevelView& finestLevel() const { return level(level_count_ - 1); }

 private:
  ModelView() = default;
  // One header reader per format version (renderer/model_read_v1.cpp, model_read_v2.cpp): each
  // checks its header and returns where the level table starts, or 0 after recording the issue.
  static std::size_t readHeaderV1(std::span<const std::uint8_t> bytes, ModelView& view,
                                  ModelIssue* issue);
  // Versions 2, 4 and 6 (4 and 6: the placement block follows the normal palette).
  static std::size_t readHeaderV2(std::span<const std::uint8_t> bytes, ModelView& view,
                                  ModelIssue* issue, std::uint16_t version);
  // Magic and version, then the header of that version: where the level table starts, or 0.
  static std::size_t readHeader(std::span<const std::uint8_t> bytes, ModelView& view,
                                ModelIssue* issue);
  // The level table at `table_at` in `head` (reserved bytes, and sizes adding up to exactly
  // `image_bytes`), without reading any level data.
  static bool checkLevelTable(std::span<const std::uint8_t> head, std::size_t table_at,
                              std::uint64_t image_bytes, const ModelView& view, ModelIssue* issue);
  // The level table and the level data that follow it (the same in both versions, with the normal
  // indices only where the header announced normals).
  static bool readLevels(std::span<const std::uint8_t> bytes, std::size_t table_at, ModelView& view,
                         ModelIssue* issue);
  // `file`: the start of the image for fromBytes (whose level table starts at `table_at`), so that
  // offsets are the file's; else nullptr.
  static bool validateLevels(ModelView& view, ModelIssue* issue, const std::uint8_t* file,
                             std::size_t table_at);
  static bool validateNormalPalette(const ModelView& view, ModelIssue* issue, std::size_t offset);
  // After validation: builds every level's skip index (LevelView::skip) into one allocation the
  // view shares with its copies. A bare-metal build has no heap: its levels keep no index.
  void indexSubtrees();
  static constexpr std::array<std::uint8_t, format::kMaxLevels> oneFootprintEach() {
    std::array<std::uint8_t, format::kMaxLevels> reaches{};
    reaches.fill(format::kOneSampleReachQ4);
    return reaches;
  }

  std::uint64_t cube_edge_pm_ = 0;
  CubePlacement cube_{};
  int palette_count_ = 0;
  const std::uint8_t* palette_rgb_ = nullptr;  // format::kPaletteEntries x RGB888
  int normal_count_ = 0;
  const std::uint8_t* normal_bytes_ = nullptr;   // .oct: normal_count_ x 3 little-endian i16
  const std::int16_t* normal_values_ = nullptr;  // embedded: normal_count_ x 3 i16
  int level_count_ = 0;
  std::array<LevelView, format::kMaxLevels> levels_{};
  // Small fields together, where a 32-bit device's alignment would otherwise pad each.
  std::uint16_t format_version_ = 0;
  bool colour_is_synthetic_ = false;
  std::array<std::uint8_t, format::kMaxLevels> reaches_ = oneFootprintEach();
#if !defined(OCTOPOINT_BARE_METAL)
  std::shared_ptr<const std::vector<SubtreeEnd>> skip_ends_;  // what levels_[i].skip point into
#endif
};

// Walks one level's stream without drawing and checks that it is exactly as long as declared:
// first, in constant time, that the declared sizes are possible for the depth at all; then
// no zero mask byte, no truncation, no trailing bytes, the leaf count as declared, every leaf
// inside the palette and, when `normal_count` > 0, one normal index per leaf, each below it (with
// `normal_count` 0 the level must have no normals). Exposed for tests and tools; ModelView runs it
// on every level.
[[nodiscard]] ModelIssue validateLevelStream(const LevelView& level, int palette_count,
                                             int normal_count = 0);

// The constant-time part of that: whether some tree of `depth` levels has `nodes` node bytes and
// `leaves` leaves (depth <= nodes <= depth * leaves, leaves <= 8 * nodes, and a full tree's
// counts). False for a depth outside 1..format::kMaxDepth or an empty level.
[[nodiscard]] bool plausibleLevelSize(int depth, std::uint64_t nodes, std::uint64_t leaves);

}  // namespace octopoint
