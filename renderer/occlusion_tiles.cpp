#include "renderer/occlusion_tiles.h"

#include <algorithm>
#include <cassert>

namespace octopoint {

std::size_t occlusionTileCount(std::int32_t width, std::int32_t height, int shift) {
  const std::int32_t side = std::int32_t{1} << shift;
  return static_cast<std::size_t>((width + side - 1) >> shift) *
         static_cast<std::size_t>((height + side - 1) >> shift);
}

OcclusionTiles::OcclusionTiles(const FrameView& frame, std::span<OcclusionTile> tiles, int shift)
    : pixels_(frame.pixels().data()),
      width_(frame.width()),
      height_(frame.height()),
      shift_(shift),
      columns_(static_cast<std::size_t>((frame.width() + (1 << shift) - 1) >> shift)),
      rows_(static_cast<std::size_t>((frame.height() + (1 << shift) - 1) >> shift)),
      tiles_(tiles.data()) {
  assert(shift >= 1 && shift <= 6 && tiles.size() >= columns_ * rows_);
}

void OcclusionTiles::reset() { std::fill(tiles_, tiles_ + columns_ * rows_, OcclusionTile{}); }

std::uint32_t OcclusionTiles::farthestIn(std::int32_t tx, std::int32_t ty) const {
  const std::int32_t x0 = tx << shift_, y0 = ty << shift_;
  const std::int32_t x1 = std::min(width_, x0 + (1 << shift_));
  const std::int32_t y1 = std::min(height_, y0 + (1 << shift_));
  std::uint32_t farthest = 0;
  for (std::int32_t y = y0; y < y1; ++y) {
    const std::uint32_t* row =
        pixels_ + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
    for (std::int32_t x = x0; x < x1; ++x) farthest = std::max(farthest, row[x]);
  }
  return farthest;
}

bool OcclusionTiles::hidden(std::int32_t x0, std::int32_t x1, std::int32_t y0, std::int32_t y1,
                            std::uint32_t word) {
  for (std::int32_t ty = y0 >> shift_; ty <= y1 >> shift_; ++ty) {
    OcclusionTile* row = tiles_ + static_cast<std::size_t>(ty) * columns_;
    for (std::int32_t tx = x0 >> shift_; tx <= x1 >> shift_; ++tx) {
      OcclusionTile& tile = row[tx];
      if (tile.stale != 0) {
        tile.farthest = farthestIn(tx, ty);
        tile.stale = 0;
      }
      if (tile.farthest >= word) return false;
    }
  }
  return true;
}

}  // namespace octopoint
