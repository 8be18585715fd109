#pragma once
// A validated, read-only view of a model: the palette and one octree stream per depth. The bytes
// belong to someone else (const arrays compiled into the app, or a file buffer); the view never
// copies them. A ModelView can only be made by validation, so the decoders may trust it: every
// walk of a level reads exactly its node bytes and its leaf indices, never past them. What it
// owns is derived from them once, at validation: each level's skip index (renderer/skip_index.h),
// shared by the view's copies (hosted builds).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#if !defined(OCTOPOINT_BARE_METAL)
#include <memory>
#include <vector>
#endif

#include "renderer/embedded_model.h"
#include "renderer/model_format.h"
#include "renderer/skip_index.h"

namespace octopoint {

enum class ModelError : std::uint8_t {
  kNone,
  kTruncatedHeader,      // fewer bytes than the header and level table need
  kBadMagic,             // not an octopoint model
  kUnsupportedVersion,   // a version this reader does not know
  kBadLevelCount,        // 0 or more than format::kMaxLevels levels
  kBadReservedField,     // a reserved field is not zero
  kBadPaletteCount,      // 0 or more than 256 colours
  kBadDepth,             // a depth outside 1..format::kMaxDepth
  kDepthsNotAscending,   // the same depth twice, or depths out of order
  kSizeMismatch,         // the declared sizes do not add up to the buffer length
  kEmptyLevel,           // a level without nodes or leaves
  kEmptyNode,            // a child mask byte of 0: an inner node without children
  kStreamTruncated,      // the tree needs more node bytes than declared
  kTrailingNodeBytes,    // the tree ends before the declared node bytes do
  kLeafCountMismatch,    // the tree has a different number of leaves than declared
  kLeafOutsidePalette,   // a leaf names a colour past the palette count
  kImplausibleLevelSize, // node bytes and leaf count no tree of that depth can have
  kBadNormalCount,       // normals flagged without entries, entries without the flag, or > 255
  kBadNormalVector,      // a normal palette entry that is not a unit vector in Q1.14
  kNormalOutsidePalette, // a leaf names a normal past the normal palette count
};

// A short, stable English description of an error, for one-line messages.
const char* describe(ModelError error);

struct ModelIssue {
  ModelError error = ModelError::kNone;
  // Where it was found: from fromBytes, the byte of the model image (the `.oct` file) at fault, be
  // it in the header, the level table or a stream; otherwise (fromEmbedded, validateLevelStream)
  // the byte of the level's node stream, or the leaf's index for a leaf colour.
  std::size_t offset = 0;
  int depth = 0;  // the level concerned, 0 when the header is at fault
  bool offset_in_file = false;  // offset counts from the start of the model image
};

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

struct LevelView {
  int depth = 0;
  std::span<const std::uint8_t> nodes;
  std::span<const std::uint8_t> leaves;   // one palette index per leaf, in depth-first order
  std::span<const std::uint8_t> normals{};  // one normal index per leaf, or empty (no normals)
  // Where the subtrees of one tree level end (renderer/skip_index.h), or none: ModelView sets it.
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
  // Validates a model image in the format of model_format.h (a whole `.oct` file, version 1 or 2).
  // The view points into `bytes`, which must outlive it.
  static std::optional<ModelView> fromBytes(std::span<const std::uint8_t> bytes, ModelIssue* issue);
  // Validates a model compiled into the app by the preparer's generated sources.
  static std::optional<ModelView> fromEmbedded(const EmbeddedModel& model, ModelIssue* issue);

  int formatVersion() const { return format_version_; }
  // The model cube's edge in picometres (0: not recorded). Version 1 files stored micrometres.
  std::uint64_t cubeEdgePicometres() const { return cube_edge_pm_; }
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
  const LevelView& finestLevel() const { return level(level_count_ - 1); }

 private:
  ModelView() = default;
  // One header reader per format version (renderer/model_read_v1.cpp, model_read_v2.cpp): each
  // checks its header and returns where the level table starts, or 0 after recording the issue.
  static std::size_t readHeaderV1(std::span<const std::uint8_t> bytes, ModelView& view, ModelIssue* issue);
  static std::size_t readHeaderV2(std::span<const std::uint8_t> bytes, ModelView& view, ModelIssue* issue);
  // The level table and the level data that follow it (the same in both versions, with the normal
  // indices only where the header announced normals).
  static bool readLevels(std::span<const std::uint8_t> bytes, std::size_t table_at, ModelView& view,
                         ModelIssue* issue);
  // `file`: the start of the image for fromBytes (whose level table starts at `table_at`), so that
  // offsets are the file's; else nullptr.
  static bool validateLevels(ModelView& view, ModelIssue* issue, const std::uint8_t* file, std::size_t table_at);
  static bool validateNormalPalette(const ModelView& view, ModelIssue* issue, std::size_t offset);
  // After validation: builds every level's skip index (LevelView::skip) into one allocation the
  // view shares with its copies. A bare-metal build has no heap: its levels keep no index.
  void indexSubtrees();

  int format_version_ = 0;
  std::uint64_t cube_edge_pm_ = 0;
  int palette_count_ = 0;
  const std::uint8_t* palette_rgb_ = nullptr;  // format::kPaletteEntries x RGB888
  bool colour_is_synthetic_ = false;
  int normal_count_ = 0;
  const std::uint8_t* normal_bytes_ = nullptr;   // .oct: normal_count_ x 3 little-endian i16
  const std::int16_t* normal_values_ = nullptr;  // embedded: normal_count_ x 3 i16
  int level_count_ = 0;
  std::array<LevelView, format::kMaxLevels> levels_{};
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
ModelIssue validateLevelStream(const LevelView& level, int palette_count, int normal_count = 0);

// The constant-time part of that: whether some tree of `depth` levels has `nodes` node bytes and
// `leaves` leaves (depth <= nodes <= depth * leaves, leaves <= 8 * nodes, and a full tree's
// counts). False for a depth outside 1..format::kMaxDepth or an empty level.
bool plausibleLevelSize(int depth, std::uint64_t nodes, std::uint64_t leaves);

}  // namespace octopoint
