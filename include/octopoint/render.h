#pragma once
// octopoint/render.h: Drawing a model into a framebuffer: variants, depth auto, abort flag, hole
// filling. The manual of the whole library is octopoint/octopoint.h.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"

// Aborting a frame from another thread (docs/design.md section 5): the fine render thread is
// stopped the moment the user moves again. Decoders poll a std::atomic<bool> at one tree level
// only.

namespace octopoint {

// The tree level at which a decoder polls its abort flag: at most 8^3 = 512 polls a frame, each a
// relaxed load, and a subtree below it is small enough to finish well within the latency target.
inline constexpr int kAbortCheckLevel = 3;

}  // namespace octopoint

// Drawing a model level into a framebuffer, by named variant (docs/splats.md). All fixed variants
// draw bit-identical frames while a voxel projects to at most one pixel; beyond that fixed_fast and
// fixed_simd draw footprint splats (identical to each other), the paper's variants one pixel per
// leaf.

namespace octopoint {

enum class Variant {
  kFixedBaseline,  // Algorithm 1: recursion down to the leaf, the leaf sets the pixel
  kFixedLeafCall,  // Algorithm 2: the leaf parent sets its children's pixels
  kFixedUnrolled,  // Algorithm 2 with the 8-way child loop unrolled
  kFixedSetBits,   // Algorithm 2 visiting only the set bits of each mask
  kFixedClipped,   // set bits + hierarchical clipping: no bounds checks for subtrees on screen
  kFixedFast,      // clipped, state in registers, no call per leaf parent: the fastest portable one
  kFixedDelta,     // fast's walk, leaves from per-child pixel-index deltas: the fastest with few
                   // registers (Cortex-M0+)
  kFixedSimd,  // clipped walk, three levels per call, eight children at once in AVX2 lanes, batched
               // min plot
  kFloatBaseline,  // floating point reference of Algorithm 1
  kFloatLeafCall,  // floating point reference of Algorithm 2
  kFloatUnrolled,  // floating point reference of Algorithm 2, unrolled
};

struct VariantInfo {
  Variant variant;
  std::string_view name;  // the name users pass to `octopoint-render --variant`
  std::string_view summary;
};

// The variants this machine runs: fixed_simd only where the CPU has AVX2 (simdDecoderAvailable).
std::span<const VariantInfo> allVariants();
[[nodiscard]] std::optional<Variant> variantFromName(std::string_view name);
// The default variant wherever a frame is drawn: the fastest this CPU runs, fixed_simd where it
// has AVX2, else fixed_fast. Both draw footprint splats (FrameSetup::splat).
Variant defaultVariant();
// Whether a variant draws the set-up's footprint splats; the others set one pixel per leaf.
bool drawsSplats(Variant variant);
// Whether the variant draws frames that carry normals (PixelPayload::kColourNormal, for the lit and
// creased styles of octopoint/styles.h): all but fixed_delta, which draws colour frames only and
// refuses the others (nothing drawn, false).
bool drawsNormals(Variant variant);

// Draws `level` with the set-up of one frame into `frame` (which it does not clear, so several
// models can share a frame). The frame must have the set-up's width and height (make it with
// Framebuffer(setup)) and the level the set-up's depth; arguments that do not fit together are
// refused in O(1), also in release builds: false, nothing drawn (checkRender in
// octopoint/render.h says why). When `abort` is given and becomes true while drawing, the
// decoder stops at its next poll and returns false: the frame is then incomplete and must not be
// shown. Returns true for a complete frame.
[[nodiscard]] bool renderLevel(Variant variant, const LevelView& level, const FrameSetup& setup,
                               FrameView& frame, const std::atomic<bool>* abort = nullptr);

// Whether a variant uses integer arithmetic only (the float_* ones are references).
bool isFixedPoint(Variant variant);

// The variants one by one (renderLevel dispatches to them); each refuses what renderLevel refuses.
[[nodiscard]] bool renderFixedBaseline(const LevelView&, const FrameSetup&, FrameView&,
                                       const std::atomic<bool>* abort);
[[nodiscard]] bool renderFixedLeafCall(const LevelView&, const FrameSetup&, FrameView&,
                                       const std::atomic<bool>* abort);
[[nodiscard]] bool renderFixedUnrolled(const LevelView&, const FrameSetup&, FrameView&,
                                       const std::atomic<bool>* abort);
[[nodiscard]] bool renderFixedSetBits(const LevelView&, const FrameSetup&, FrameView&,
                                      const std::atomic<bool>* abort);
[[nodiscard]] bool renderFixedClipped(const LevelView&, const FrameSetup&, FrameView&,
                                      const std::atomic<bool>* abort);
[[nodiscard]] bool renderFixedFast(const LevelView&, const FrameSetup&, FrameView&,
                                   const std::atomic<bool>* abort);
[[nodiscard]] bool renderFixedDelta(const LevelView&, const FrameSetup&, FrameView&,
                                    const std::atomic<bool>* abort);
[[nodiscard]] bool renderFixedSimd(const LevelView&, const FrameSetup&, FrameView&,
                                   const std::atomic<bool>* abort);
bool simdDecoderAvailable();  // an x86-64 CPU with AVX2
[[nodiscard]] bool renderFloatBaseline(const LevelView&, const FrameSetup&, FrameView&,
                                       const std::atomic<bool>* abort);
[[nodiscard]] bool renderFloatLeafCall(const LevelView&, const FrameSetup&, FrameView&,
                                       const std::atomic<bool>* abort);
[[nodiscard]] bool renderFloatUnrolled(const LevelView&, const FrameSetup&, FrameView&,
                                       const std::atomic<bool>* abort);

}  // namespace octopoint

// What every drawing entry point checks before it touches a framebuffer, in release builds too:
// the decoders trust their arguments (no bounds check for a subtree the set-up says is on screen),
// so a framebuffer of another size, a level of another depth or a set-up buildFrameSetup would not
// have made must be refused, not drawn. All checks are O(1): at most format::kMaxDepth x 8 offsets.
//
// What cannot be checked in O(1) is a LevelView's stream itself: take levels from a ModelView
// (ModelView::fromBytes / fromEmbedded validate them), never build one by hand from untrusted
// bytes.

namespace octopoint {

enum class RenderError : std::uint8_t {
  kNone,
  kBadSetup,  // not a set-up buildFrameSetup makes: depth, fraction bits, size or sample reach
              // out of range, or offsets and splat that could overflow 32 bits
  kFrameSizeMismatch,  // the framebuffer's width or height differs from the set-up's
  kDepthMismatch,      // the level's depth differs from the set-up's
  kImplausibleLevel,   // no nodes or leaves, or node bytes and leaf count no tree of its depth has
  kLevelWithoutNormals,  // the frame was cleared to carry normals (PixelPayload::kColourNormal) and
                         // the level has none
};

// A short, stable English description, for one-line messages.
const char* describe(RenderError error);

// Whether `setup` is safe to draw: sizes, depth and fraction bits in range, and no position a
// decoder computes (root plus one offset per level, plus the splat's pixel range) can wrap 32
// bits, as buildFrameSetup proves for what it makes. Band set-ups (a smaller height, a shifted
// root, a subtree's depth) and a splat reset to SplatFootprint{} pass.
[[nodiscard]] RenderError checkFrameSetup(const FrameSetup& setup);

// checkFrameSetup, then whether `level` and `frame` fit it. renderLevel and every variant's
// function return false without drawing when this is not kNone.
[[nodiscard]] RenderError checkRender(const LevelView& level, const FrameSetup& setup,
                                      const FrameView& frame);

}  // namespace octopoint

// Scanline hole filling (docs/design.md section 6; pictures and exact definitions in
// docs/holefill.md).
//
// A point-based frame has background pixels between the projected voxel centres wherever a voxel
// covers more than one pixel (zoom) or the grid is seen at an angle. After decoding, one top-to-
// bottom scanline pass fills an empty pixel P = (x, y) when covered pixels bound it on both sides
// (C = covered, . = empty, P = the pixel filled):
//   type 1, horizontal single gap:  C P C in the row
//   type 2, vertical single gap:    C above P and C below P
//   type 3, diagonal single gap:    all four diagonal neighbours of P covered (an X around P)
//   type 4, two-pixel gap:          C P . C or C . P C, in the row or in the column
// The first type that matches, in the order 1, 2, 3, 4, fills P; for types 1 to 3 P takes the
// colour and depth of the nearest bounding pixel (the front surface wins; ties: left, then up),
// for type 4 those of the bounding pixel next to it. A pair bounds a gap only when its depths
// differ by at most `max_bridge_depth` (a silhouette in front of a farther surface is never
// bridged). Everything else, in particular the object's outer border (type 5: gaps open to the
// background on one side, wider gaps, inner corners of the outline), stays empty.
//
// Every decision reads the frame as the decoder left it: a filled pixel never bounds another
// gap, so one pass cannot creep across the background. The filler keeps the original depths of
// the five rows around the current one in a padded ring; it allocates them once, at set-up.

namespace octopoint {

// Neighbours across a gap may differ in depth by this many voxel edges (see bridgeDepthLimit).
// Measured on the default model (yaw 30, zoom 2, depth 8; docs/holefill.md): the table, seen at a
// grazing angle, recedes by up to about 3 voxel edges per pixel row, so a limit of 2 leaves 35% of
// the holes inside the object open and 4 leaves 14%; the objects stand centimetres (tens of
// voxels) in front of what lies behind them, far beyond 4.
inline constexpr std::int32_t kBridgeDepthVoxelEdges = 4;

// The depth limit for a frame set-up, in the frame's depth-key units (FrameSetup::depthKey):
// kBridgeDepthVoxelEdges times the edge of one voxel on screen, which is the length of the rotated
// displacement between a leaf-parent's children 0 and 4 (exact integer square root in Q(32-F).F
// pixels; the length does not depend on the rotation), shifted right by setup.depth_shift.
std::uint32_t bridgeDepthLimit(const FrameSetup& setup);

// The bridge rule of a perspective frame (renderer/perspective_renderer.h; docs/perspective.md,
// "Styles and hole filling"): its words' depth is camera-space z, and a pixel spans z / f across,
// so the depth step a surface makes between two pixels grows with their depth. A pair of covered
// pixels bounds a gap when their depths differ by at most
//     max(least, z * per_depth_q16 >> 16) + (z >> 11)
// with z the nearer one's depth (2^-18 cube edge units, both payloads; the last term is the depth
// code's step in a frame that carries normals): kBridgeDepthVoxelEdges pixels across at that depth,
// or as many voxel edges of the finest depth drawn where those are larger (near the eye).
struct PerspectiveBridge {
  std::uint64_t least = 0;          // 2^-18 cube edge units
  std::uint64_t per_depth_q16 = 0;  // kBridgeDepthVoxelEdges / f, Q.16
};

struct HoleFillCounts {
  std::int32_t type1 = 0, type2 = 0, type3 = 0, type4 = 0;
  bool refused = false;  // the frame, rows or history did not fit: nothing was filled
  std::int32_t total() const { return type1 + type2 + type3 + type4; }
};

// Rows of history and padding columns the filler keeps: a decision about row y reads the decoder's
// words of rows y - 2 .. y + 2 and columns x - 2 .. x + 2.
inline constexpr std::int32_t kHoleFillReachRows = 2;
inline constexpr std::int32_t kHoleFillHistoryRows = 2 * kHoleFillReachRows + 1;
inline constexpr std::int32_t kHoleFillPadColumns = 2;

// Words of history fillHoleRows needs for frames `width` pixels wide.
std::size_t holeFillHistoryWords(std::int32_t width);

// The row-range entry point (band rendering, octopoint/bands.h): fills the gaps of rows
// [row_begin, row_end) of `window`, reading rows row_begin - 2 .. row_end + 1 of it as the decoder
// left them; rows outside the window read as empty. So when `window` holds rows [y0, y0 + h) of a
// frame, the result equals the whole-frame fill's rows exactly if the window also holds every frame
// row within kHoleFillReachRows of the filled ones. `history` (holeFillHistoryWords) is scratch.
// A row range outside the window or a history too small is refused (counts.refused, nothing
// changed), also in release builds.
[[nodiscard]] HoleFillCounts fillHoleRows(FrameView& window, std::int32_t row_begin,
                                          std::int32_t row_end, std::uint32_t max_bridge_depth,
                                          std::span<std::uint32_t> history);
// The same for a perspective frame: the same gap types, each pair judged by `bridge`.
[[nodiscard]] HoleFillCounts fillHoleRows(FrameView& window, std::int32_t row_begin,
                                          std::int32_t row_end, const PerspectiveBridge& bridge,
                                          std::span<std::uint32_t> history);

class HoleFiller {
 public:
  // Allocates the row history for frames `width` pixels wide (1..kMaxViewportSide; any other width
  // makes a filler that refuses every frame).
  explicit HoleFiller(std::int32_t width);
  // For frames as wide as `frame`: the size given once.
  explicit HoleFiller(const FrameView& frame) : HoleFiller(frame.width()) {}

  // Fills the gaps of types 1 to 4 in `frame` in place. A frame of another width than the
  // filler's is refused (counts.refused, nothing changed), also in release builds.
  // `max_bridge_depth` is in the frame's depth-key units (bridgeDepthLimit). Never allocates.
  [[nodiscard]] HoleFillCounts fill(FrameView& frame, std::uint32_t max_bridge_depth);
  // A perspective frame (PerspectiveBridge).
  [[nodiscard]] HoleFillCounts fill(FrameView& frame, const PerspectiveBridge& bridge);

  std::int32_t width() const { return width_; }

 private:
  std::int32_t width_;
  std::vector<std::uint32_t> history_;  // holeFillHistoryWords(width_) original pixel words
};

// For measuring (docs/holefill.md): the empty pixels of `frame` that lie inside the object as
// `outline` shows it, where a pixel is inside when `outline` has covered pixels at most `window`
// pixels from it on both sides in its row (left and right) or on both sides in its column (above
// and below). With the unfilled frame as both arguments this counts the holes before filling;
// with the unfilled frame as `outline` and the filled one as `frame`, the holes left after it.
// -1 when the two frames differ in size.
std::int32_t countEnclosedEmptyPixels(const Framebuffer& outline, const Framebuffer& frame,
                                      std::int32_t window);

}  // namespace octopoint
