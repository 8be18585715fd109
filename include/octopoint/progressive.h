#pragma once
// octopoint/progressive.h: the progressive model: a chunked model (its format: octopoint/chunked.h)
// whose bytes arrive while it is drawn, every frame complete. The manual of the whole library is
// octopoint/octopoint.h.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/chunked.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"

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

  // draw from a snapshot, then its pieces blended by smooth splats (octopoint/smooth.h, docs/
  // splats.md "Smooth splats"): what the model holds, each piece's leaves with its own depth's
  // kernel, into `smooth` (made for the frame's size) with `palette`; then smooth.resolveToRgb or
  // pixelBlend. Holding every chunk the view needs, the frame is renderSmooth's of the whole
  // model at that depth, bit for bit. False where draw is, or where blending refuses the frame
  // (a variant without splats while there are splats). Allocates nothing.
  [[nodiscard]] bool drawSmooth(ProgressiveFrame& snapshot, const Camera& camera, Variant variant,
                                FrameView& frame, SmoothSplats& smooth, const PaletteRgb& palette,
                                ProgressiveDrawStats* stats = nullptr,
                                const std::atomic<bool>* abort = nullptr,
                                int coarser_levels = 0) const;
  // The same without a snapshot, as draw(camera, ...): with the point budget setPointBudget set.
  [[nodiscard]] bool drawSmooth(const Camera& camera, Variant variant, FrameView& frame,
                                SmoothSplats& smooth, const PaletteRgb& palette,
                                ProgressiveDrawStats* stats = nullptr);

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
