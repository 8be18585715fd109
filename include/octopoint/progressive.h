#pragma once
// octopoint/progressive.h: Chunked models and the progressive model: bytes arrive, every frame is
// complete. The manual of the whole library is octopoint/octopoint.h.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/render.h"

// What can be wrong with a chunked model (octopoint/progressive.h): its head, a record table, or
// one chunk. Each failure has its own error and a one-line description; the offset says where in
// the file it was found.

namespace octopoint {

enum class ChunkedError : std::uint8_t {
  kNone,
  // The head.
  kTruncatedHead,       // fewer bytes than the fixed header or the head size says
  kBadMagic,            // not an octopoint model
  kUnsupportedVersion,  // not version 3
  kBadLevelCount,       // fewer than 2 or more than kMaxChunkedLevels levels
  kBadFlags,            // a flag this reader does not know
  kBadReservedField,    // a reserved field is not zero
  kBadPaletteCount,     // 0 or more than 256 colours
  kBadHeadSize,         // the head size does not match the palette, level table and base
  kBadFileSize,         // the file size does not fit the head, the tables and the level offsets
  kBadHeadCrc,          // the head's CRC-32 does not match
  kBadDepth,            // a depth outside 1..16
  kDepthsNotAscending,  // the same depth twice, or out of order
  kBadRegionLevel,      // region levels decreasing, too deep, or not coarser than the level refined
  kTooManyChunks,       // a chunk count of 0, more than the regions there are, or past kMaxChunks
  kBadBase,             // the base stream is not a valid octree stream (see its ModelError)
  // A record table.
  kTableOutOfOrder,      // a level's table offered before the table of the level above it
  kBadTableSize,         // not exactly 20 bytes per chunk
  kBadTableCrc,          // the table's CRC-32 does not match the level table
  kRegionsNotAscending,  // the same region twice, or out of order
  kRegionOutsideLevel,   // a region code with more bits than the region level has
  kNoCoarserChunk,       // a region inside no chunk of the level above
  kCoarseCountMismatch,  // the chunks inside a coarser chunk refine a different number of voxels
  kImplausibleChunk,     // chunk bytes, point and coarse counts no refinement can have
  kChunkBytesMismatch,   // a level's chunk bytes do not fill its part of the file
  // One chunk.
  kUnknownChunk,             // no such chunk, or its level's table is not known yet
  kWrongChunkLength,         // not the chunk's declared number of bytes
  kBadChunkCrc,              // the chunk's CRC-32 does not match its record
  kChunkTruncated,           // the refinement needs more mask bytes than the chunk has
  kChunkEmptyNode,           // a zero mask below the first level of a refinement
  kChunkTrailingBytes,       // mask bytes left after the last refinement
  kChunkLeafCountMismatch,   // the refinements have a different number of leaves than declared
  kChunkLeafOutsidePalette,  // a leaf names a colour past the palette count
  kChunkDisagrees,    // the chunk's voxels do not match the regions the next level's table lists
  kBadCubePlacement,  // version 5: the cube's placement is not one a file may hold
};

// A short, stable English description, for one-line messages.
const char* describe(ChunkedError error);

struct ChunkedIssue {
  ChunkedError error = ChunkedError::kNone;
  std::uint64_t offset = 0;  // file offset (head, tables) or offset inside the chunk
  int level = 0;             // the level concerned; 0 for the head and the base
};

}  // namespace octopoint

// The chunked model format, version 3 (docs/format.md): one model cut into chunks that can be
// fetched, checked and drawn one by one, and a file that refines the whole model coarse to fine
// when read front to back. All integers are little-endian.
//
// Levels. A chunked model has L levels: level 0, the base, holds the whole model at a coarse depth
// d0 as one ordinary octree stream (octopoint/model.h); levels 1..L-1 hold ever finer depths
// d1 < d2 < ... Level j cuts the cube into regions at tree level r_j (its region level) and holds
// one chunk per region that contains some voxel of level j-1. A chunk is a refinement: for every
// voxel of level j-1 inside its region, in depth-first order, the subtree that voxel becomes at
// depth d_j (d_j - d_{j-1} tree levels of child masks); then the palette index of every new leaf.
// So a chunk repeats nothing its coarser level already said, and it can be drawn only once the
// chunk it refines is held.
//
// Layout:
//   head     fixed header (kFixedHeaderBytes), palette, level table, base stream, head CRC
//   tables   one record table per level 1..L-1, kRecordBytes per chunk, regions ascending
//   chunks   level 1's chunks in record order, then level 2's, ...; the file ends after the last
//
// Fixed header:
//   offset size field
//   0      4    magic "OCTP"
//   4      2    format version, 3 or 5 (5: version 3 with the cube's placement, below)
//   6      1    level count L, 2..kMaxChunkedLevels
//   7      1    flags, as in version 2: bit 1 synthetic colour (the scan had none: the palette is a
//                depth shade); bit 0 (per-leaf normals: a normal palette after the colour palette
//                and each chunk's normal indices after its colour indices) is kept for a later
//                reader and refused by this one; other bits 0
//   8      8    cube edge in picometres (the metric size of the model cube; 0: not recorded)
//   16     2    palette colour count P, 1..256
//   18     2    normal count, 0 (until normals are read)
//   20     4    head bytes H: from offset 0 to the end of the head CRC
//   24     8    file bytes: the whole file
//   32     4    base node bytes
//   36     4    base leaf count
//   40     3 P  palette, RGB888
//   then   20 L level table: u8 depth, u8 region level, u16 reserved 0, u32 chunk count,
//                u32 CRC-32 of the level's record table, u64 file offset of the level's first
//                chunk. Row 0 is the base: region level, chunk count, CRC and offset 0.
//   then        base node bytes, base leaf palette indices
//   then   40   version 5 only: the cube's placement in the scan (format::kCubePlacementBytes,
//                octopoint/model.h's CubePlacement); version 3 has none
//   H - 4  4    CRC-32 of bytes [0, H - 4)
//
// Record (kRecordBytes), one per chunk:
//   0  4  region: Morton code of the region at the level's region level r (3 r bits, the child
//         index k = (x << 2) | (y << 1) | z of each tree level from the root, the root's highest)
//   4  4  chunk bytes
//   8  4  point count: the chunk's leaves (voxels of depth d_j)
//   12 4  coarse count: the voxels of level j-1 in the region, which the chunk refines
//   16 4  CRC-32 of the chunk's bytes
//
// Chunk bytes: the refinement masks (a voxel whose refinement's first mask is 0 has nothing at the
// finer depth; masks below the first are never 0), then `point count` palette indices.
//
// Rules a valid file obeys (the reader checks every one): depths strictly ascending in 1..16;
// region levels non-decreasing, r_j < d_{j-1} (a region is larger than a voxel of the level it
// refines), r_j <= kMaxRegionLevel; regions of a level strictly ascending, each inside a region of
// the level before (level 1: inside the root); the coarse counts of the chunks inside one coarser
// chunk add up to its point count (level 1: to the base's leaf count); the record tables follow the
// head back to back, level 1's chunks follow the last table, each level's chunks fill exactly the
// bytes from its offset to the next level's (the last: to the end of the file).

namespace octopoint::chunked {

inline constexpr std::uint16_t kVersion3 = 3;
inline constexpr std::uint16_t kVersion5 = 5;               // version 3 and the cube's placement
inline constexpr std::uint16_t kFormatVersion = kVersion5;  // what the preparer writes
inline constexpr int kMaxChunkedLevels = format::kMaxLevels + 1;  // the base and up to 8 depths
inline constexpr int kMaxRegionLevel = 10;                        // 30-bit Morton codes
inline constexpr std::size_t kFixedHeaderBytes = 40;
inline constexpr std::size_t kLevelRowBytes = 20;
inline constexpr std::size_t kRecordBytes = 20;
inline constexpr std::size_t kHeadCrcBytes = 4;
// Bounds that keep what a reader allocates proportional to what it was sent: no more chunks in a
// model than this, and no file larger than this.
inline constexpr std::uint64_t kMaxChunks = std::uint64_t{1} << 22;
inline constexpr std::uint64_t kMaxFileBytes = std::uint64_t{1} << 40;

// Header flags (the same bits as format version 2).
inline constexpr std::uint8_t kFlagNormals = 1u << 0;          // not read yet: refused
inline constexpr std::uint8_t kFlagSyntheticColour = 1u << 1;  // the palette is a depth shade

// Where each part of the fixed header is.
namespace offset {
inline constexpr std::size_t kVersion = 4;
inline constexpr std::size_t kLevelCount = 6;
inline constexpr std::size_t kFlags = 7;
inline constexpr std::size_t kCubeEdge = 8;
inline constexpr std::size_t kPaletteCount = 16;
inline constexpr std::size_t kNormalCount = 18;
inline constexpr std::size_t kHeadBytes = 20;
inline constexpr std::size_t kFileBytes = 24;
inline constexpr std::size_t kBaseNodeBytes = 32;
inline constexpr std::size_t kBaseLeafCount = 36;
inline constexpr std::size_t kPalette = 40;
}  // namespace offset

}  // namespace octopoint::chunked

// Reading the head of a chunked model (octopoint/progressive.h): the fixed header, palette, level
// table and base stream, checked against the head's CRC-32 and the format's rules before anything
// is kept. The head is everything a reader needs before its first picture: the base draws the whole
// model at a coarse depth.

namespace octopoint {

struct ChunkedLevel {
  int depth = 0;
  int region_level = 0;  // the tree level of this level's regions (0 for the base)
  std::uint32_t chunk_count = 0;
  std::uint32_t table_crc = 0;
  std::uint64_t table_offset = 0;   // file offset of the level's record table
  std::uint64_t chunks_offset = 0;  // file offset of its first chunk
  std::uint64_t chunks_end = 0;  // where its chunks end: the next level's offset, or the file's end
};

struct ChunkedHead {
  int format_version = 0;          // chunked::kVersion3 or kVersion5
  std::uint64_t cube_edge_pm = 0;  // picometres; 0: not recorded
  CubePlacement cube{};            // version 5; not recorded in version 3
  std::uint8_t flags = 0;          // chunked::kFlagSyntheticColour or 0
  int palette_count = 0;
  std::array<std::uint8_t, 3 * format::kPaletteEntries> palette_rgb{};  // zero past the count
  std::uint64_t head_bytes = 0;
  std::uint64_t file_bytes = 0;
  int level_count = 0;  // the base and the chunked levels
  std::array<ChunkedLevel, chunked::kMaxChunkedLevels> levels{};
  std::vector<std::uint8_t> base_nodes;  // the base: an octree stream of depth levels[0].depth
  std::vector<std::uint8_t> base_leaves;
};

// The largest head a reader accepts: a few kilobytes in files the preparer writes.
inline constexpr std::uint64_t kMaxHeadBytes = std::uint64_t{1} << 24;

// Whether `bytes` begin like a chunked model, version 3 or 5 (magic and version), so that a reader
// of both kinds can tell them apart from the first 6 bytes.
[[nodiscard]] bool looksChunked(std::span<const std::uint8_t> bytes);

// The head's size in bytes, read from the fixed header (the first chunked::kFixedHeaderBytes of
// the file); nullopt with the issue when those bytes already show a bad model.
[[nodiscard]] std::optional<std::uint64_t> chunkedHeadBytes(
    std::span<const std::uint8_t> fixed_header, ChunkedIssue* issue);

// Parses and checks the head; `bytes` must hold at least the head (any bytes after it are ignored).
// The result owns copies of everything it keeps.
[[nodiscard]] std::optional<ChunkedHead> parseChunkedHead(std::span<const std::uint8_t> bytes,
                                                          ChunkedIssue* issue);

}  // namespace octopoint

// The record tables of a chunked model (octopoint/progressive.h): one record per chunk, saying
// where the chunk is in space (its region) and in the file, how many voxels it refines and holds,
// and its CRC-32. A table is checked against the head and the coarser level's table, so that every
// chunk can afterwards be checked on its own.

namespace octopoint {

struct ChunkRecord {
  std::uint32_t region = 0;         // Morton code at the level's region level
  std::uint32_t bytes = 0;          // chunk size
  std::uint32_t points = 0;         // its voxels (leaves) at the level's depth
  std::uint32_t coarse_points = 0;  // the coarser level's voxels in the region, which it refines
  std::uint32_t crc = 0;            // CRC-32 of the chunk's bytes
  std::uint64_t offset = 0;         // file offset of the chunk (from the table's order)
  std::uint32_t parent =
      0;  // index of the coarser level's chunk it lies in (0 at level 1: the base)
};

// The tree levels a voxel of depth `fine_depth` lies below a voxel of depth `coarse_depth`.
inline int refinementLevels(const ChunkedHead& head, int level) {
  return head.levels[static_cast<std::size_t>(level)].depth -
         head.levels[static_cast<std::size_t>(level - 1)].depth;
}

// Parses and checks the record table of chunked level `level` (1..level_count-1). `coarser` is the
// checked table of the level above (empty for level 1, whose chunks all refine the base).
[[nodiscard]] std::optional<std::vector<ChunkRecord>> parseRecordTable(
    std::span<const std::uint8_t> bytes, const ChunkedHead& head, int level,
    std::span<const ChunkRecord> coarser, ChunkedIssue* issue);

}  // namespace octopoint

// One chunk of a chunked model (octopoint/progressive.h): checking its bytes on their own, and
// turning it, with the coarser stream it refines, into the ordinary octree stream of its region
// that the decoders draw (octopoint/model.h's layout, rooted at the region instead of the
// cube).

namespace octopoint {

// Checks a chunk against its record without anything else: its length and CRC-32, then a walk of
// its `record.coarse_points` refinements of `gap` tree levels each (a first mask may be 0, masks
// below it never are), which must use exactly its mask bytes and have exactly `record.points`
// leaves, each inside the palette. Cost: one pass over the bytes; no allocation.
[[nodiscard]] ChunkedIssue validateChunk(std::span<const std::uint8_t> bytes,
                                         const ChunkRecord& record, int gap, int palette_count);

// Where a region's subtree lies inside a larger depth-first stream: its node bytes and its leaves.
struct StreamRange {
  std::uint32_t node_begin = 0, node_end = 0;
  std::uint32_t leaf_begin = 0, leaf_end = 0;
  std::uint32_t leafCount() const { return leaf_end - leaf_begin; }
};

// Builds a region's stream at the finer depth. `coarse_nodes` is the region's (validated) stream at
// the coarser depth, `coarse_levels` >= 1 tree levels deep; `chunk` is its validated refinement by
// `gap` levels, whose coarse count is the coarse stream's leaf count. Voxels whose refinement is
// empty disappear, and so do nodes left without children. Appends the result to `nodes` and
// `leaves` (the chunk's palette indices, which keep their order).
void refineRegion(std::span<const std::uint8_t> coarse_nodes, int coarse_levels,
                  std::span<const std::uint8_t> chunk, std::uint32_t points, int gap,
                  std::vector<std::uint8_t>& nodes, std::vector<std::uint8_t>& leaves);

// Calls `visit(code, range)`, in ascending order of code, for every node `level_below` tree levels
// under the root of a validated stream `levels` deep (level_below < levels): `code` is the node's
// Morton code relative to the stream's root (3 bits per level), `range` where its subtree lies.
// level_below = 0 visits the whole stream as code 0.
void forEachSubregion(
    std::span<const std::uint8_t> nodes, std::span<const std::uint8_t> leaves, int levels,
    int level_below,
    const std::function<void(std::uint32_t code, const StreamRange& range)>& visit);

}  // namespace octopoint

// A chunked model (octopoint/progressive.h) that fills in while its bytes arrive, drawn at every
// moment from what it holds. It does no I/O: a caller (net/ for HTTP, a file reader, a radio link)
// asks it what to fetch next for the current view, and hands it each record table and chunk as it
// arrives. Every chunk is checked on its own (CRC-32 and a walk of its refinements) before it is
// kept; a chunk that fails is refused and may be offered again, up to kMaxChunkAttempts times.
//
// Drawing: each visible region is drawn at the finest depth held, up to the depth the view needs;
// where a chunk is missing, the coarser chunk it refines is drawn in its place (its part of that
// region only), so the picture is always complete, coarser where data is missing, never holey. The
// base (in the head) covers the whole model from the start. A view drawn from every chunk it needs
// is exactly the frame of a single-file model holding those depths (tested).
//
// Memory: the head is copied (a few kB); a record table costs 20 bytes per chunk in the file and
// about 100 here; a chunk is kept as the octree stream of its region at its depth (node bytes and
// one byte per leaf), which is what a version-1 file spends on the same region and depth: so a
// model holding everything takes at most the size of a version-1 file of its depths, plus the
// records. A chunk that arrives before the one it refines waits as its raw bytes. This memory is
// allocated when bytes arrive; drawing and fetchPriority allocate nothing.
//
// Threads: feeding (accept, acceptBytes), asking (fetchPriority, viewComplete, chunkState, ...) and
// snapshot() need one thread or a caller's lock. Drawing need not hold that lock for a frame's
// length: a drawing thread takes a snapshot of which chunks are drawable into its own
// ProgressiveFrame under the lock (a copy of one byte per chunk), then draws that snapshot with
// draw(ProgressiveFrame&, ...) without the lock, while chunks keep arriving. A chunk's stream is
// written before the chunk becomes drawable and never changed or freed afterwards, and record
// tables are written once, before their level becomes known; so a snapshot reads only bytes no
// feeder writes any more, and draws exactly the model as it was when the snapshot was taken
// (tested under ThreadSanitizer with real threads).

namespace octopoint {

enum class ChunkState : std::uint8_t {
  kMissing,      // not received (or refused, fewer than kMaxChunkAttempts times)
  kWaiting,      // received and valid, waiting for the coarser chunk it refines
  kHeld,         // drawable
  kUnavailable,  // refused kMaxChunkAttempts times, or its data contradicts the directory
};

// One byte range to fetch: a level's record table or one chunk.
struct FetchItem {
  enum class Kind : std::uint8_t { kRecordTable, kChunk };
  Kind kind = Kind::kChunk;
  int level = 0;             // 1..levelCount()-1
  std::uint32_t index = 0;   // the chunk's index in its level (kChunk)
  std::uint64_t offset = 0;  // first byte in the file
  std::uint64_t bytes = 0;
  bool visible = true;  // whether the current view shows it (chunks)
  bool operator==(const FetchItem&) const = default;
};

// Which levels' record tables a model knows, with each level's voxel count (the base's leaves;
// a level's: the sum of its chunks' point counts) and where its chunks start in the one-byte-per-
// chunk drawable table. Levels' tables arrive in order, so the known ones are a prefix.
struct ProgressiveTables {
  int known_levels = 1;  // the base and the levels whose tables are known
  std::array<std::uint64_t, chunked::kMaxChunkedLevels> points{};
  std::array<std::uint32_t, chunked::kMaxChunkedLevels> first_chunk{};
};

struct ProgressiveDrawStats {
  int wanted_depth = 0;      // the depth the view needs (octopoint/progressive.h: wantedDepth)
  int drawn_depth = 0;       // the finest stored depth drawn (coarser under a point budget)
  int pieces = 0;            // region streams drawn
  int coarser_pieces = 0;    // of those, drawn coarser than drawn_depth (data missing, or budget)
  std::uint64_t points = 0;  // leaves in the streams drawn
  // Under a point budget (ProgressiveFrame::setPointBudget): the visible chunks of the drawn
  // depth's level drawn one depth coarser to keep within it (0 when the view fits the budget).
  std::uint32_t over_budget_chunks = 0;
};

// What one drawing thread draws from: a snapshot of which chunks a model held when it was taken
// (ProgressiveModel::snapshot), and the thread's own per-frame set-ups. One per drawing thread;
// its contents are the model's business.
class ProgressiveFrame {
 public:
  ProgressiveFrame() = default;

  // The most points (leaves) a frame drawn from this snapshot should draw; 0 (the default): no
  // budget. See ProgressiveModel::draw, "Point budget".
  void setPointBudget(std::uint64_t points) { point_budget_ = points; }
  std::uint64_t pointBudget() const { return point_budget_; }
  // After a draw: whether the budget drew chunk `index` of `level` one depth coarser.
  bool overBudget(int level, std::uint32_t index) const {
    return level == setups_.budget_level && index < kept_.size() && kept_[index] == 0;
  }

 private:
  friend class ProgressiveModel;
  // A visible chunk of the level the budget splits, ranked by what it shows (see
  // ProgressiveModel::applyPointBudget).
  struct BudgetEntry {
    std::uint64_t area;   // on-screen pixels of its region's bounds (clipped to the frame)
    std::int32_t z;       // its region's centre: smaller is nearer
    std::uint32_t index;  // in its level
  };
  // Per frame: set-ups of each level's depth, moved to the level's own regions and to the next
  // level's regions (drawing a coarser chunk in place of a missing finer one).
  struct Setups {
    int wanted_depth = 0;
    std::int32_t width = 0, height = 0;
    int drawn_level = 0;  // the finest level whose depth is not finer than wanted_depth
    std::array<FrameSetup, chunked::kMaxChunkedLevels> full{};  // for whole-model streams
    std::array<FrameSetup, chunked::kMaxChunkedLevels> own{};
    std::array<FrameSetup, chunked::kMaxChunkedLevels> restricted{};
    // Half the on-screen extent (Q(32-F).F) of a region of each level's regions and of the next
    // level's, reaching down to the finest depth drawn: anything drawn for the region lies within.
    std::array<Vec3, chunked::kMaxChunkedLevels> own_reach{};
    std::array<Vec3, chunked::kMaxChunkedLevels> restricted_reach{};
    Vec3 splat_low{}, splat_high{};  // the widest splat's first and last pixel from a leaf (x, y)
    int budget_level = 0;  // the level whose chunks a point budget splits (kept_); 0: none
  };
  ProgressiveTables tables_;
  std::vector<std::uint8_t> drawable_;  // per chunk of the known levels: 1 when drawable
  Setups setups_;
  std::uint64_t point_budget_ = 0;
  // Per frame under a budget, per chunk of the level it splits: 1 when drawn at its own depth.
  // Sized by snapshot(), so that drawing allocates nothing.
  std::vector<std::uint8_t> kept_;
  std::vector<BudgetEntry> budget_order_;
};

class ProgressiveModel {
 public:
  static constexpr int kMaxChunkAttempts = 3;

  // Starts from the file's head: `bytes` holds at least the head's bytes (chunkedHeadBytes says how
  // many); anything after them is ignored (pass it to acceptPrefix to use it).
  [[nodiscard]] static std::optional<ProgressiveModel> fromHead(std::span<const std::uint8_t> bytes,
                                                                ChunkedIssue* issue);

  // Movable: everything the views point into lives on the heap.
  ProgressiveModel(ProgressiveModel&&) noexcept = default;
  ProgressiveModel& operator=(ProgressiveModel&&) noexcept = default;

  const ChunkedHead& head() const { return head_; }
  int levelCount() const { return head_.level_count; }
  int levelDepth(int level) const { return head_.levels[static_cast<std::size_t>(level)].depth; }
  // The palette and the base as an ordinary validated model, for resolveToRgb and friends.
  const ModelView& baseModel() const { return *base_view_; }

  bool hasRecordTable(int level) const {
    return levels_[static_cast<std::size_t>(level)].table_known;
  }
  FetchItem recordTableItem(int level) const;
  std::uint32_t chunkCount(int level) const;  // 0 until the level's record table is accepted
  const ChunkRecord& record(int level, std::uint32_t index) const;
  ChunkState chunkState(int level, std::uint32_t index) const;
  FetchItem chunkItem(int level, std::uint32_t index) const;

  // Takes the bytes fetched for `item`. Record tables must come in level order (each is checked
  // against the one above it). Returns kNone when accepted (or already held); otherwise the chunk
  // or table is refused, nothing else changes, and the issue's offset is a file offset. A table
  // refused kMaxChunkAttempts times is given up, like a chunk: its level is never drawn.
  [[nodiscard]] ChunkedIssue accept(const FetchItem& item, std::span<const std::uint8_t> bytes);

  // Takes every record table and chunk that lies whole in `bytes`, a piece of the file starting at
  // `file_offset` (a file read front to back, a radio broadcast). Returns the file offset up to
  // which everything was taken; stops at the first refused part, with its issue.
  [[nodiscard]] std::uint64_t acceptBytes(std::uint64_t file_offset,
                                          std::span<const std::uint8_t> bytes, ChunkedIssue* issue);

  // The depth this view draws: depth by projected size (renderer/level_of_detail.h, autoDepth)
  // over the model's depths, the base's included; nullopt for a camera refused at every depth.
  [[nodiscard]] std::optional<int> wantedDepth(const Camera& camera) const;

  // Depth by projected size over every stored depth, dense or not (default: only the depths the
  // scan samples densely, renderer/level_of_detail.h). For hand-made models whose few voxels
  // cannot grow kDenseGrowth times per depth.
  void useEveryStoredDepth(bool every) { every_stored_depth_ = every; }

  // What to fetch next for this view, most urgent first: the record tables it needs, then its
  // chunks, visible before invisible (these only with include_invisible), coarse before fine,
  // larger on screen before smaller, then file order. Never a depth finer than the view needs,
  // never a chunk held, waiting or unavailable (or refining one that is unavailable). Writes up to
  // out.size() items and returns how many; `total`, when given, gets how many there are in all.
  // Allocates nothing. Returns 0 for a camera it refuses.
  std::size_t fetchPriority(const Camera& camera, bool include_invisible, std::span<FetchItem> out,
                            std::size_t* total = nullptr);

  // Copies which chunks are drawable now into `frame` (one byte per chunk of the known levels;
  // allocates only when the model has learnt a record table since `frame` last took a snapshot).
  // Needs the feeder's lock; the draw that follows does not.
  void snapshot(ProgressiveFrame& frame) const;

  // Draws the view into `frame` (which it does not clear) with a fixed-point variant (those that
  // draw splats, octopoint/render.h drawsSplats, fill coarse voxels' footprints). Returns false,
  // drawing nothing, for a camera buildFrameSetup refuses, and false, the frame incomplete, when
  // `abort` became true while drawing (polled as renderLevel polls it). `coarser_levels` draws that
  // many stored levels coarser than the view needs (a quick frame while the view moves).
  // Allocates nothing.
  //
  // Point budget (ProgressiveFrame::setPointBudget; setPointBudget here for the draw without a
  // snapshot): depth by projected size bounds a voxel's size on screen, not how many there are,
  // so a model filling the screen at a fine depth costs its millions of points. With a budget B,
  // the frame draws at most B points where it can: counted from the record tables over the
  // visible chunks of the level drawn (each chunk's points at its depth, or its coarse count one
  // depth coarser), while even the coarser counts exceed B the level drawn moves one coarser (not
  // past level 1); then the visible chunks of that level, largest on screen first, then nearest,
  // then in file order, keep their depth while the total stays within B, and the rest are drawn
  // one depth coarser (their coarser chunk's part, with splats), as if they had not arrived. The
  // choice depends only on the view, the budget and the record tables known, never on which chunks
  // have arrived: integer only, deterministic, no allocation.
  [[nodiscard]] bool draw(const Camera& camera, Variant variant, FrameView& frame,
                          ProgressiveDrawStats* stats = nullptr,
                          const std::atomic<bool>* abort = nullptr, int coarser_levels = 0);
  // The same from a snapshot: draws the model as it was when `snapshot` was taken, and may run
  // while another thread accepts chunks (see "Threads" above). Allocates nothing.
  [[nodiscard]] bool draw(ProgressiveFrame& snapshot, const Camera& camera, Variant variant,
                          FrameView& frame, ProgressiveDrawStats* stats = nullptr,
                          const std::atomic<bool>* abort = nullptr, int coarser_levels = 0) const;

  // The point budget of draw(camera, ...) (0, the default: none); see draw.
  void setPointBudget(std::uint64_t points) { own_frame_.setPointBudget(points); }

  // Whether this view's picture is final: every visible region drawn at the depth the view needs
  // (whatever the point budget).
  [[nodiscard]] bool viewComplete(const Camera& camera);

  // The octree stream of held chunk `index` of `level` at the level's depth, rooted at its region
  // (level 0, index 0: the base, rooted at the cube); empty spans for a chunk not held. Its bytes
  // never change once held.
  struct RegionStream {
    std::span<const std::uint8_t> nodes, leaves;
  };
  RegionStream regionStream(int level, std::uint32_t index) const {
    if (chunkState(level, index) != ChunkState::kHeld) return {};
    const Slot& slot = levels_[static_cast<std::size_t>(level)].slots[index];
    return {slot.nodes, slot.leaves};
  }

  // Bytes held for chunks (assembled streams, waiting chunks) and records.
  std::uint64_t heldBytes() const;
  // Chunks by state, over the levels whose tables are known.
  std::uint32_t chunksIn(ChunkState state) const;

 private:
  struct Slot {
    ChunkState state = ChunkState::kMissing;
    std::uint8_t refusals = 0;
    bool range_known = false;  // in_parent is set
    bool blocked = false;  // fetchPriority scratch: it or a coarser chunk it needs is unavailable
    StreamRange in_parent{};  // the region's part of the coarser chunk's stream
    std::uint32_t child_begin = 0, child_end = 0;  // its regions in the next level (table known)
    std::vector<std::uint8_t> raw;                 // while waiting
    std::vector<std::uint8_t> nodes, leaves;       // the region's stream at the level's depth
  };
  struct Level {
    bool table_known = false;
    std::uint8_t table_refusals = 0;  // kMaxChunkAttempts of them: the level is given up
    bool table_unavailable = false;
    std::vector<ChunkRecord> records;
    std::vector<Slot> slots;
  };
  struct Priority {
    std::uint64_t key;  // visibility, level, screen area, order (see fetchPriority)
    FetchItem item;
  };

  ProgressiveModel() = default;
  [[nodiscard]] bool acceptRecordTable(int level, std::span<const std::uint8_t> bytes,
                                       ChunkedIssue* issue);
  [[nodiscard]] ChunkedIssue acceptChunk(int level, std::uint32_t index,
                                         std::span<const std::uint8_t> bytes);
  void linkChildren(int level, std::uint32_t index);
  void becomeHeld(int level, std::uint32_t index);
  using Setups = ProgressiveFrame::Setups;
  [[nodiscard]] std::optional<int> wantedDepth(const ProgressiveTables& tables,
                                               const Camera& camera) const;
  [[nodiscard]] bool prepareFrame(const ProgressiveTables& tables, const Camera& camera,
                                  int coarser_levels, Setups& frame) const;
  Vec3 regionCentre(const Setups& frame, int level, std::uint32_t region) const;
  Vec3 reachBelow(const Setups& frame, int tree_level) const;
  static bool offScreen(const Setups& frame, const Vec3& centre, const Vec3& reach);
  static std::uint64_t screenArea(const Setups& frame, const Vec3& centre, const Vec3& reach);
  struct BudgetCost {
    std::uint64_t own = 0, coarser = 0;  // visible chunks' points at their depth, one coarser
  };
  BudgetCost visibleCost(const ProgressiveFrame& snapshot, int level) const;
  [[nodiscard]] bool applyPointBudget(ProgressiveFrame& snapshot, const Camera& camera,
                                      int coarser_levels) const;
  template <typename PieceVisitor>
  void visitPieces(ProgressiveFrame& snapshot, int level, std::uint32_t index,
                   PieceVisitor& visitor) const;
  void setDrawable(int level, std::uint32_t index, bool drawable);

  ChunkedHead head_;
  std::vector<std::uint8_t> base_palette_;  // 256 x RGB888 for base_view_ (on the heap: movable)
  std::optional<ModelView> base_view_;
  std::array<Level, chunked::kMaxChunkedLevels> levels_{};
  ProgressiveTables tables_;            // what snapshots copy, with drawable_
  std::vector<std::uint8_t> drawable_;  // per chunk of the known levels: 1 when drawable
  bool every_stored_depth_ = false;
  ProgressiveFrame own_frame_;  // for draw without a snapshot, fetchPriority, viewComplete
  std::vector<Priority> priority_scratch_;
};

// Reads a model from the front of a file (or any prefix of one): the head, then every record table
// and chunk lying whole in `bytes`. nullopt (with the issue) when the head is bad or incomplete; a
// later bad part only stops the reading there (`issue` says what), the model keeps what came
// before.
[[nodiscard]] std::optional<ProgressiveModel> progressiveModelFromPrefix(
    std::span<const std::uint8_t> bytes, ChunkedIssue* issue);

}  // namespace octopoint
