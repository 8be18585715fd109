#pragma once
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

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "renderer/camera.h"
#include "renderer/framebuffer.h"

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

// The row-range entry point (band rendering, renderer/band_renderer.h): fills the gaps of rows
// [row_begin, row_end) of `window`, reading rows row_begin - 2 .. row_end + 1 of it as the decoder
// left them; rows outside the window read as empty. So when `window` holds rows [y0, y0 + h) of a
// frame, the result equals the whole-frame fill's rows exactly if the window also holds every frame
// row within kHoleFillReachRows of the filled ones. `history` (holeFillHistoryWords) is scratch.
// A row range outside the window or a history too small is refused (counts.refused, nothing
// changed), also in release builds.
HoleFillCounts fillHoleRows(FrameView& window, std::int32_t row_begin, std::int32_t row_end,
                            std::uint32_t max_bridge_depth, std::span<std::uint32_t> history);

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
  HoleFillCounts fill(FrameView& frame, std::uint32_t max_bridge_depth);

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
