#pragma once
// A validated, read-only view of a model: the palette and one octree stream per depth. The bytes
// belong to someone else (const arrays compiled into the app, or a file buffer); the view never
// copies them. A ModelView can only be made by validation, so the decoders may trust it: every
// walk of a level reads exactly its node bytes and its leaf indices, never past them.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "renderer/embedded_model.h"
#include "renderer/model_format.h"

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
  std::span<const std::uint8_t> leaves;  // one palette index per leaf, in depth-first order
};

class ModelView {
 public:
  // Validates a model image in the format of model_format.h (a whole `.oct` file). The view points
  // into `bytes`, which must outlive it.
  static std::optional<ModelView> fromBytes(std::span<const std::uint8_t> bytes, ModelIssue* issue);
  // Validates a model compiled into the app by the preparer's generated sources.
  static std::optional<ModelView> fromEmbedded(const EmbeddedModel& model, ModelIssue* issue);

  std::uint32_t cubeEdgeMicrometres() const { return cube_edge_um_; }
  int paletteCount() const { return palette_count_; }
  Rgb paletteColour(int index) const;
  int levelCount() const { return level_count_; }
  const LevelView& level(int i) const { return levels_[static_cast<std::size_t>(i)]; }
  // The level of exactly this depth, or nullptr.
  const LevelView* levelOfDepth(int depth) const;
  const LevelView& finestLevel() const { return level(level_count_ - 1); }

 private:
  ModelView() = default;
  // `file`: the start of the image for fromBytes, so that offsets are the file's; else nullptr.
  static bool validateLevels(ModelView& view, ModelIssue* issue, const std::uint8_t* file);

  std::uint32_t cube_edge_um_ = 0;
  int palette_count_ = 0;
  const std::uint8_t* palette_rgb_ = nullptr;  // format::kPaletteEntries x RGB888
  int level_count_ = 0;
  std::array<LevelView, format::kMaxLevels> levels_{};
};

// Walks one level's stream without drawing and checks that it is exactly as long as declared:
// first, in constant time, that the declared sizes are possible for the depth at all; then
// no zero mask byte, no truncation, no trailing bytes, the leaf count as declared, every leaf
// inside the palette. Exposed for tests and tools; ModelView runs it on every level.
ModelIssue validateLevelStream(const LevelView& level, int palette_count);

// The constant-time part of that: whether some tree of `depth` levels has `nodes` node bytes and
// `leaves` leaves (depth <= nodes <= depth * leaves, leaves <= 8 * nodes, and a full tree's
// counts). False for a depth outside 1..format::kMaxDepth or an empty level.
bool plausibleLevelSize(int depth, std::uint64_t nodes, std::uint64_t leaves);

}  // namespace octopoint
