#pragma once
// A perspective frame drawn in horizontal bands (docs/device.md, "Perspective in bands"), for a
// microcontroller whose RAM holds a band and not a frame: the band renderer of octopoint/bands.h
// for the perspective walk. Each band is the frame's rows [y0, y0 + rows): the view's centre moved
// up by y0 pixels (every position then moves by exactly y0 rows), the frame the band's buffer,
// and the walk passes over subtrees that the eye sees wholly above or below the band (a margin of
// kPerspectiveBandMargin rows each way). Detail by distance and occlusion culling (tiles of the
// band, reset for each) work as in the whole frame, so the concatenated bands are the whole frame
// drawPerspectiveLayers draws, bit for bit. No heap: the caller gives the buffers, the upper tree
// indexes (in the layers) and the tiles.

#include <cstdint>
#include <span>

#include "octopoint/bands.h"
#include "octopoint/framebuffer.h"
#include "renderer/occlusion_tiles.h"
#include "renderer/perspective.h"
#include "renderer/perspective_detail.h"
#include "renderer/perspective_walk.h"

namespace octopoint {

// Rows each side of a band within which a subtree is still walked: room for the splats' padding,
// the affine error and the growth of their half extents beyond the voxels' own projections.
inline constexpr std::int32_t kPerspectiveBandMargin = 2;

struct PerspectiveBandFrame {
  std::span<const PerspectiveLayer> layers;   // ascending depths, as drawPerspectiveLayers takes
  const PerspectiveDetail* detail = nullptr;  // made for the layers' depths (several layers)
  const PerspectiveView* view = nullptr;      // the whole frame's
  // Occlusion culling: at least occlusionTileCount(width, band rows, tile_shift) tiles; empty: no
  // culling (the same frame).
  std::span<OcclusionTile> tiles;
  int tile_shift = 3;
};

// Draws the frame band by band into `buffers` (first, and second for double buffering; each at
// least width * band_rows words; fill_history unused), converts each band to RGB565 with
// `palette` in place and hands it to `sink`, as renderBands. `stats` (may be null) sums the
// bands' points and hidden subtrees. kBadBandRows, kBufferTooSmall, kNoSink, kRefused (no layer,
// no view, too few tiles, a view whose shifted rows leave Q(32-F).F) before anything is drawn.
[[nodiscard]] BandError renderPerspectiveBands(const PerspectiveBandFrame& frame,
                                               std::int32_t band_rows, const Rgb565Palette& palette,
                                               const BandBuffers& buffers, const BandSink& sink,
                                               PerspectiveDrawStats* stats = nullptr);

// The band's rows [y0, y0 + rows) of `view`'s frame widened by kPerspectiveBandMargin, as slopes.
PerspectiveBand perspectiveBand(const PerspectiveView& view, std::int32_t y0, std::int32_t rows);

}  // namespace octopoint
