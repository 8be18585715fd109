#include <algorithm>
#include <cstring>
#include <limits>

#include "octopoint/render.h"
#include "renderer/perspective_depth.h"

namespace octopoint {
namespace {

constexpr std::uint32_t kEmpty = Framebuffer::kEmpty;

HoleFillCounts refusedFill() {
  HoleFillCounts refused;
  refused.refused = true;
  return refused;
}

// Two covered pixels (packed words) whose depth keys are at most `limit` apart: a surface, not a
// step.
bool bridgeable(std::uint32_t a, std::uint32_t b, std::uint32_t limit) {
  if (a == kEmpty || b == kEmpty) return false;
  const std::uint32_t key_a = Framebuffer::depthKeyOf(a), key_b = Framebuffer::depthKeyOf(b);
  return (key_a > key_b ? key_a - key_b : key_b - key_a) <= limit;
}

// The nearer of two bounding pixels by depth key; on equal keys the first (left, then up).
std::uint32_t nearer(std::uint32_t a, std::uint32_t b) {
  return Framebuffer::depthKeyOf(b) < Framebuffer::depthKeyOf(a) ? b : a;
}

// The orthographic rule: depth keys at most `limit` apart.
struct KeyBridge {
  std::uint32_t limit;
  bool operator()(std::uint32_t a, std::uint32_t b) const { return bridgeable(a, b, limit); }
};

// A perspective frame's rule (PerspectiveBridge), for words of `kPayload`.
template <PixelPayload kPayload>
struct DepthBridge {
  PerspectiveBridge rule;
  bool operator()(std::uint32_t a, std::uint32_t b) const {
    if (a == kEmpty || b == kEmpty) return false;
    const std::uint64_t depth_a = perspectiveWordDepth(a, kPayload);
    const std::uint64_t depth_b = perspectiveWordDepth(b, kPayload);
    const std::uint64_t near = std::min(depth_a, depth_b);  // < 2^28: the products fit
    const std::uint64_t limit = std::max(rule.least, (near * rule.per_depth_q16) >> 16) +
                                (near >> kNormalDepthMantissaBits);
    return (depth_a > depth_b ? depth_a - depth_b : depth_b - depth_a) <= limit;
  }
};

// Fills the holes of row y of `pixels` from the original words of rows y - 2 .. y + 2 (each
// readable two columns either side of the row); counts each fill by its type. `bridges(a, b)`:
// whether covered pixels a and b are one surface.
template <typename Bridge>
__attribute__((always_inline)) inline void fillHoleRow(
    std::uint32_t* pixels, std::int32_t y, std::int32_t width, const std::uint32_t* up2,
    const std::uint32_t* up1, const std::uint32_t* row, const std::uint32_t* down1,
    const std::uint32_t* down2, const Bridge& bridges, HoleFillCounts& counts) {
  for (std::int32_t x = 0; x < width; ++x) {
    if (row[x] != kEmpty) continue;
    // Every type needs one of these covered (the left, right, upper or lower neighbour, or the
    // upper left one for type 3): most background pixels stop here.
    if (row[x - 1] == kEmpty && row[x + 1] == kEmpty && up1[x] == kEmpty && down1[x] == kEmpty &&
        up1[x - 1] == kEmpty) {
      continue;
    }
    // P takes the bounding pixel's word: its depth key and its colour.
    const auto fillFrom = [&](std::uint32_t source, std::int32_t& type_count) {
      pixels[static_cast<std::ptrdiff_t>(y) * width + x] = source;
      ++type_count;
    };
    // Type 1: C P C in the row.
    if (bridges(row[x - 1], row[x + 1])) {
      fillFrom(nearer(row[x - 1], row[x + 1]), counts.type1);
      continue;
    }
    // Type 2: C above P, C below P.
    if (bridges(up1[x], down1[x])) {
      fillFrom(nearer(up1[x], down1[x]), counts.type2);
      continue;
    }
    // Type 3: the four diagonal neighbours covered, each diagonal pair a surface.
    if (bridges(up1[x - 1], down1[x + 1]) && bridges(up1[x + 1], down1[x - 1])) {
      const std::uint32_t first = nearer(up1[x - 1], up1[x + 1]);
      const std::uint32_t second = nearer(down1[x - 1], down1[x + 1]);
      fillFrom(nearer(first, second), counts.type3);
      continue;
    }
    // Type 4: a two-pixel gap, P next to its bounding pixel: C P . C, C . P C, and the same in
    // the column.
    if (row[x + 1] == kEmpty && bridges(row[x - 1], row[x + 2])) {
      fillFrom(row[x - 1], counts.type4);
    } else if (row[x - 1] == kEmpty && bridges(row[x - 2], row[x + 1])) {
      fillFrom(row[x + 1], counts.type4);
    } else if (down1[x] == kEmpty && bridges(up1[x], down2[x])) {
      fillFrom(up1[x], counts.type4);
    } else if (up1[x] == kEmpty && bridges(up2[x], down1[x])) {
      fillFrom(down1[x], counts.type4);
    }
  }
}

template <typename Bridge>
HoleFillCounts fillRows(FrameView& window, std::int32_t row_begin, std::int32_t row_end,
                        const Bridge& bridges, std::span<std::uint32_t> history) {
  const std::int32_t width = window.width();
  const std::int32_t height = window.height();
  if (row_begin < 0 || row_begin > row_end || row_end > height || width < 1 ||
      history.size() < holeFillHistoryWords(width)) {
    return refusedFill();
  }
  constexpr std::int32_t kRows = kHoleFillHistoryRows;
  constexpr std::int32_t kPad = kHoleFillPadColumns;
  // A pixel is filled only between covered pixels, so inside the window's drawn rectangle.
  std::uint32_t* const pixels = window.pixelsToDraw(window.drawnRect());
  const std::ptrdiff_t stride = width + 2 * kPad;
  // The original words of rows y - 2 .. y + 2 live in a ring of kRows slots, kPad columns in; rows
  // outside the window and the padding columns are empty, so no read needs a bounds check. The
  // ring turns by rotating slot pointers, not by a remainder: a device without a divide
  // instruction would call a helper for it.
  std::fill_n(history.begin(), holeFillHistoryWords(width), kEmpty);
  std::uint32_t* slot_of[kRows];  // slot_of[i]: the slot of row row_begin - 2 + i, in ring order
  const auto load = [&](std::uint32_t* row, std::int32_t r) {
    if (r >= 0 && r < height) {
      std::memcpy(row, pixels + static_cast<std::ptrdiff_t>(r) * width,
                  static_cast<std::size_t>(width) * 4);
    } else {
      std::fill(row, row + width, kEmpty);
    }
  };
  for (std::int32_t i = 0; i < kRows; ++i) slot_of[i] = history.data() + i * stride + kPad;
  for (std::int32_t i = 0; i < kRows - 1; ++i) load(slot_of[i], row_begin - 2 + i);
  HoleFillCounts counts;
  for (std::int32_t y = row_begin; y < row_end; ++y) {
    const std::uint32_t* up2 = slot_of[0];
    const std::uint32_t* up1 = slot_of[1];
    const std::uint32_t* row = slot_of[2];
    const std::uint32_t* down1 = slot_of[3];
    std::uint32_t* const down2_slot = slot_of[4];
    load(down2_slot, y + 2);
    const std::uint32_t* down2 = down2_slot;
    fillHoleRow(pixels, y, width, up2, up1, row, down1, down2, bridges, counts);
    // Row y - 2's slot takes row y + 3 next.
    std::uint32_t* const oldest = slot_of[0];
    for (std::int32_t i = 0; i + 1 < kRows; ++i) slot_of[i] = slot_of[i + 1];
    slot_of[kRows - 1] = oldest;
  }
  return counts;
}

}  // namespace

std::uint32_t bridgeDepthLimit(const FrameSetup& setup) {
  if (setup.depth < 1 || setup.depth > kMaxRenderDepth || setup.depth_shift < 0 ||
      setup.depth_shift > 63) {
    return 0;  // not a set-up buildFrameSetup makes: bridge nothing
  }
  const std::uint64_t edge = voxelEdgeOnScreen(setup);  // Q(32-F).F screen pixels
  // In depth-key units (FrameSetup::depthKey): keys are depths shifted right by depth_shift.
  const std::uint64_t limit =
      (edge * static_cast<std::uint64_t>(kBridgeDepthVoxelEdges)) >> setup.depth_shift;
  return static_cast<std::uint32_t>(std::min<std::uint64_t>(limit, Framebuffer::kMaxDepthKey));
}

HoleFiller::HoleFiller(std::int32_t width)
    : width_(width >= 1 && width <= kMaxViewportSide ? width : 0),
      history_(holeFillHistoryWords(width_), kEmpty) {}

HoleFillCounts HoleFiller::fill(FrameView& frame, std::uint32_t max_bridge_depth) {
  if (frame.width() != width_ || width_ == 0) {
    return refusedFill();
  }
  return fillHoleRows(frame, 0, frame.height(), max_bridge_depth, history_);
}

HoleFillCounts HoleFiller::fill(FrameView& frame, const PerspectiveBridge& bridge) {
  if (frame.width() != width_ || width_ == 0) {
    return refusedFill();
  }
  return fillHoleRows(frame, 0, frame.height(), bridge, history_);
}

std::size_t holeFillHistoryWords(std::int32_t width) {
  return static_cast<std::size_t>(width + 2 * kHoleFillPadColumns) * kHoleFillHistoryRows;
}

HoleFillCounts fillHoleRows(FrameView& window, std::int32_t row_begin, std::int32_t row_end,
                            std::uint32_t max_bridge_depth, std::span<std::uint32_t> history) {
  return fillRows(window, row_begin, row_end, KeyBridge{max_bridge_depth}, history);
}

HoleFillCounts fillHoleRows(FrameView& window, std::int32_t row_begin, std::int32_t row_end,
                            const PerspectiveBridge& bridge, std::span<std::uint32_t> history) {
  if (window.payload() == PixelPayload::kColourNormal) {
    return fillRows(window, row_begin, row_end, DepthBridge<PixelPayload::kColourNormal>{bridge},
                    history);
  }
  return fillRows(window, row_begin, row_end, DepthBridge<PixelPayload::kColour>{bridge}, history);
}

std::int32_t countEnclosedEmptyPixels(const Framebuffer& outline, const Framebuffer& frame,
                                      std::int32_t window) {
  if (outline.width() != frame.width() || outline.height() != frame.height()) return -1;
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
