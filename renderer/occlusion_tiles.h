#pragma once
// Occlusion culling's coarse depth (docs/perspective.md, "Occlusion culling"): for each tile of
// 2^shift x 2^shift pixels, the farthest pixel word in it (the largest: a word's high bits are its
// depth key, and an empty pixel's word is the largest of all). A subtree whose every word would be
// farther than the farthest word of every tile its pixels lie in cannot change one of them (the
// frame keeps the smaller word), so the walk passes over it and the frame stays the same bit for
// bit. The words only ever fall, so a tile's recorded farthest word stays an upper bound as it is
// drawn over; a tile written to is marked stale and scanned again when it is next asked about.
// Integer only; the tiles are memory the caller provides, once per framebuffer size.

#include <cstddef>
#include <cstdint>
#include <span>

#include "octopoint/framebuffer.h"

namespace octopoint {

struct OcclusionTile {
  std::uint32_t farthest = FrameView::kEmpty;  // at least every word of the tile
  std::uint32_t stale = 0;                     // written to since `farthest` was found
};

// The tiles a frame of width x height needs.
std::size_t occlusionTileCount(std::int32_t width, std::int32_t height, int shift);

class OcclusionTiles {
 public:
  // `tiles`: at least occlusionTileCount(frame's size, shift) of them; shift 1..6.
  OcclusionTiles(const FrameView& frame, std::span<OcclusionTile> tiles, int shift);

  // For a frame just cleared: every tile empty.
  void reset();

  // Whether every pixel of columns [x0, x1] and rows [y0, y1] (within the frame) holds a word
  // smaller than `word`. Scans the stale tiles it meets.
  bool hidden(std::int32_t x0, std::int32_t x1, std::int32_t y0, std::int32_t y1,
              std::uint32_t word);

  // Pixels of columns [x0, x1] and rows [y0, y1] (within the frame) may have been written.
  void touched(std::int32_t x0, std::int32_t x1, std::int32_t y0, std::int32_t y1) {
    for (std::int32_t ty = y0 >> shift_; ty <= y1 >> shift_; ++ty) {
      OcclusionTile* row = tiles_ + static_cast<std::size_t>(ty) * columns_;
      for (std::int32_t tx = x0 >> shift_; tx <= x1 >> shift_; ++tx) row[tx].stale = 1;
    }
  }

  std::int32_t width() const { return width_; }
  std::int32_t height() const { return height_; }

 private:
  std::uint32_t farthestIn(std::int32_t tx, std::int32_t ty) const;

  const std::uint32_t* pixels_;
  std::int32_t width_, height_;
  int shift_;
  std::size_t columns_, rows_;
  OcclusionTile* tiles_;
};

}  // namespace octopoint
