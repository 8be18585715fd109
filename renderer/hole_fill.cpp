#include "renderer/hole_fill.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <limits>

namespace octopoint {
namespace {

constexpr std::int32_t kEmpty = Framebuffer::kEmptyDepth;

// floor(sqrt(value)), bit by bit: integer only.
std::uint64_t integerSquareRoot(std::uint64_t value) {
  std::uint64_t root = 0;
  std::uint64_t bit = std::uint64_t{1} << 62;
  while (bit > value) bit >>= 2;
  while (bit != 0) {
    if (value >= root + bit) {
      value -= root + bit;
      root = (root >> 1) + bit;
    } else {
      root >>= 1;
    }
    bit >>= 2;
  }
  return root;
}

// Two covered pixels whose depths (Q(32-F).F) are at most `limit` apart: a surface, not a step.
bool bridgeable(std::int32_t a, std::int32_t b, std::int32_t limit) {
  if (a == kEmpty || b == kEmpty) return false;
  const std::int64_t difference = std::int64_t{a} - std::int64_t{b};
  return (difference < 0 ? -difference : difference) <= limit;
}

// One bounding pixel of a gap: its depth and where to read its colour.
struct Source {
  std::int32_t depth;
  std::int32_t x, y;
};

Source nearer(const Source& a, const Source& b) { return b.depth < a.depth ? b : a; }

}  // namespace

std::int32_t bridgeDepthLimit(const FrameSetup& setup) {
  assert(setup.depth >= 1);
  // Children 4 and 0 of a leaf-parent differ by one voxel edge along the model's x axis, rotated.
  const auto& offsets = setup.child_offset[static_cast<std::size_t>(setup.depth - 1)];
  std::uint64_t squared = 0;
  for (const std::int64_t component :
       {std::int64_t{offsets[4].x} - offsets[0].x, std::int64_t{offsets[4].y} - offsets[0].y,
        std::int64_t{offsets[4].z} - offsets[0].z}) {
    squared += static_cast<std::uint64_t>(component * component);  // each < 2^62, sum < 2^64
  }
  const std::uint64_t edge = integerSquareRoot(squared);  // Q(32-F).F screen pixels
  const std::uint64_t limit = edge * static_cast<std::uint64_t>(kBridgeDepthVoxelEdges);
  constexpr std::uint64_t kMax = std::numeric_limits<std::int32_t>::max() - 1;
  return static_cast<std::int32_t>(std::min(limit, kMax));
}

HoleFiller::HoleFiller(std::int32_t width)
    : width_(width), history_(static_cast<std::size_t>(width + 2 * kPad) * kRows, kEmpty) {
  assert(width > 0);
}

HoleFillCounts HoleFiller::fill(Framebuffer& frame, std::int32_t max_bridge_depth) {
  assert(frame.width() == width_ && max_bridge_depth >= 0);
  const std::int32_t width = width_;
  const std::int32_t height = frame.height();
  const std::int32_t* depths = frame.depths().data();
  const std::uint8_t* colours = frame.colourIndices().data();  // covered pixels never change
  const std::ptrdiff_t stride = width + 2 * kPad;
  // Frame row r (-2 <= r < height + 2) lives in slot (r + kRows) % kRows, kPad columns in; rows
  // outside the frame and the padding columns are empty, so no read needs a bounds check.
  const auto slot = [&](std::int32_t r) {
    return history_.data() + ((r + kRows) % kRows) * stride + kPad;
  };
  const auto load = [&](std::int32_t r) {
    std::int32_t* row = slot(r);
    if (r >= 0 && r < height) {
      std::memcpy(row, depths + static_cast<std::ptrdiff_t>(r) * width,
                  static_cast<std::size_t>(width) * 4);
    } else {
      std::fill(row, row + width, kEmpty);
    }
  };
  for (std::int32_t r = -2; r < 2; ++r) load(r);
  HoleFillCounts counts;
  for (std::int32_t y = 0; y < height; ++y) {
    load(y + 2);  // into the slot of row y - 3, which no decision needs any more
    const std::int32_t* up2 = slot(y - 2);
    const std::int32_t* up1 = slot(y - 1);
    const std::int32_t* row = slot(y);
    const std::int32_t* down1 = slot(y + 1);
    const std::int32_t* down2 = slot(y + 2);
    for (std::int32_t x = 0; x < width; ++x) {
      if (row[x] != kEmpty) continue;
      // Every type needs one of these covered (the left, right, upper or lower neighbour, or the
      // upper left one for type 3): most background pixels stop here.
      if (row[x - 1] == kEmpty && row[x + 1] == kEmpty && up1[x] == kEmpty && down1[x] == kEmpty &&
          up1[x - 1] == kEmpty) {
        continue;
      }
      const auto fillFrom = [&](const Source& source, std::int32_t& type_count) {
        frame.plot(x, y, source.depth,
                   colours[static_cast<std::ptrdiff_t>(source.y) * width + source.x]);
        ++type_count;
      };
      // Type 1: C P C in the row.
      if (bridgeable(row[x - 1], row[x + 1], max_bridge_depth)) {
        fillFrom(nearer({row[x - 1], x - 1, y}, {row[x + 1], x + 1, y}), counts.type1);
        continue;
      }
      // Type 2: C above P, C below P.
      if (bridgeable(up1[x], down1[x], max_bridge_depth)) {
        fillFrom(nearer({up1[x], x, y - 1}, {down1[x], x, y + 1}), counts.type2);
        continue;
      }
      // Type 3: the four diagonal neighbours covered, each diagonal pair a surface.
      if (bridgeable(up1[x - 1], down1[x + 1], max_bridge_depth) &&
          bridgeable(up1[x + 1], down1[x - 1], max_bridge_depth)) {
        const Source first = nearer({up1[x - 1], x - 1, y - 1}, {up1[x + 1], x + 1, y - 1});
        const Source second = nearer({down1[x - 1], x - 1, y + 1}, {down1[x + 1], x + 1, y + 1});
        fillFrom(nearer(first, second), counts.type3);
        continue;
      }
      // Type 4: a two-pixel gap, P next to its bounding pixel: C P . C, C . P C, and the same in
      // the column.
      if (row[x + 1] == kEmpty && bridgeable(row[x - 1], row[x + 2], max_bridge_depth)) {
        fillFrom({row[x - 1], x - 1, y}, counts.type4);
      } else if (row[x - 1] == kEmpty && bridgeable(row[x - 2], row[x + 1], max_bridge_depth)) {
        fillFrom({row[x + 1], x + 1, y}, counts.type4);
      } else if (down1[x] == kEmpty && bridgeable(up1[x], down2[x], max_bridge_depth)) {
        fillFrom({up1[x], x, y - 1}, counts.type4);
      } else if (up1[x] == kEmpty && bridgeable(up2[x], down1[x], max_bridge_depth)) {
        fillFrom({down1[x], x, y + 1}, counts.type4);
      }
    }
  }
  return counts;
}

std::int32_t countEnclosedEmptyPixels(const Framebuffer& outline, const Framebuffer& frame,
                                      std::int32_t window) {
  assert(outline.width() == frame.width() && outline.height() == frame.height());
  const std::int32_t width = frame.width(), height = frame.height();
  // Whether a covered pixel lies within `window` steps of (x, y) in direction (dx, dy).
  const auto coveredWithin = [&](std::int32_t x, std::int32_t y, std::int32_t dx, std::int32_t dy) {
    for (std::int32_t step = 1; step <= window; ++step) {
      const std::int32_t px = x + dx * step, py = y + dy * step;
      if (px < 0 || py < 0 || px >= width || py >= height) return false;
      if (outline.covered(px, py)) return true;
    }
    return false;
  };
  std::int32_t count = 0;
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      const bool in_row = coveredWithin(x, y, -1, 0) && coveredWithin(x, y, 1, 0);
      const bool in_column = coveredWithin(x, y, 0, -1) && coveredWithin(x, y, 0, 1);
      if (!frame.covered(x, y) && (in_row || in_column)) {
        ++count;
      }
    }
  }
  return count;
}

}  // namespace octopoint
