#include "renderer/perspective_walk.h"

#include <algorithm>
#include <cassert>
#include <tuple>

#include "renderer/perspective_splat.h"

namespace octopoint {

namespace {

constexpr std::int64_t kOneQ30 = std::int64_t{1} << 30;

// divShiftRound(numerator, denominator, shift), the same bits, by one division (the hardware's;
// on a Cortex-M longDivide: no helper) where numerator * 2^shift fits 63 bits, both are positive:
// the tables run several bisections a frame and depth (and a scene's per instance), and
// divShiftRound's loop of one quotient bit per step was most of their cost.
std::optional<std::int64_t> divShiftRoundQuick(std::int64_t numerator, std::int64_t denominator,
                                               int shift) {
  if (numerator < 0 || denominator <= 0 || numerator >= (std::int64_t{1} << (62 - shift))) {
    return divShiftRound(numerator, denominator, shift);
  }
  const auto d = static_cast<std::uint64_t>(denominator);
  const UnsignedDivision division =
      divideUnsigned(static_cast<std::uint64_t>(numerator) << shift, d);
  // Ties toward +infinity, as divShiftRound rounds a positive quotient.
  return static_cast<std::int64_t>(division.quotient + (2 * division.remainder >= d ? 1 : 0));
}

// A box of reach r about c holds points c + d with d.z^2 <= r^2 and |d|^2 <= (9/8) r^2 (a leaf's
// centre lies within sqrt(3) (h + depth) of its node's: h half the node's edge, and a unit of
// rounding per level on each axis; reach = rotatedCubeReach(h) + depth, and 3 (h + depth)^2 <=
// (9/8) reach^2 at every level of every depth up to 16: tested). The projection's error
// f |d.z (c.x d.z - d.x c.z)| / (c.z^2 (c.z + d.z)) is then at most f (r^2 |c.x| + (9/16) r^2 c.z)
// / (c.z^2 (c.z - r)), as |d.x d.z| <= (d.x^2 + d.z^2) / 2: the depth's term is 9/16 of
// affineErrorBound's, which takes |d.x d.z| <= r^2. Q.30.
constexpr std::int64_t kDepthTermQ30 = 9 * (kOneQ30 >> 4);

// The largest q = r / z (Q.30, below 1) for which every box of reach r at depth z whose centre
// has max(|c.x|, |c.y|) <= m is within `max_error` (Q(32-F).F) of its affine map, its bound
// f * r^2 * (m + (9/16) z) / (z^2 * (z - r)) being at most g(q) = f * q^2 * spread(q) / (1 - q),
// with spread(q) (Q.30) an upper bound of (m + (9/16) z) / z. g grows with q: bisection on q,
// every step rounded up (by the quick products and division: the same bits, a few times faster).
template <typename Spread>
std::int64_t largestAffineRatio(const PerspectiveView& view, const Spread& spread_of,
                                std::int64_t max_error) {
  const int f = view.fraction_bits;
  const std::int64_t limit_q16 = f >= 16 ? max_error >> (f - 16) : max_error << (16 - f);
  const auto within = [&](std::int64_t q) {
    const std::optional<std::int64_t> spread = spread_of(q);
    if (!spread) return false;
    const std::optional<std::int64_t> q2 = mulShiftRoundQuick(q, q, 30);
    if (!q2) return false;
    const std::optional<std::int64_t> a = mulShiftRoundQuick(view.focal_q16, *q2 + 1, 30);
    if (!a) return false;
    const std::optional<std::int64_t> b = mulShiftRoundQuick(*a + 1, *spread, 30);
    if (!b) return false;
    const std::optional<std::int64_t> g = divShiftRoundQuick(*b + 1, kOneQ30 - q, 30);
    return g && *g + 1 <= limit_q16;
  };
  std::int64_t low = 0, high = kOneQ30 - 1;  // within(low) holds (g(0) = 0 <= limit)
  while (low < high) {
    const std::int64_t mid = low + (high - low + 1) / 2;
    if (within(mid)) {
      low = mid;
    } else {
      high = mid - 1;
    }
  }
  return low;
}

}  // namespace

std::int64_t perspectiveSplatMargin(int depth, std::int32_t sample_reach) {
  if (sample_reach == kOneSampleReach) return 0;
  // A widened splat is the shadow of the leaf's cube grown reach / 16 times (the subtree's growth
  // and the padding a little more): the reach of that whole grown cube bounds what lies beyond
  // the leaf's own, with room for both.
  const std::int64_t leaf_half = std::int64_t{1} << (kPerspectiveUnitBits - 1 - depth);
  return rotatedCubeReach((leaf_half * sample_reach + 15) >> 4) + 1;
}

PerspectiveWalkTables perspectiveWalkTables(const PerspectiveView& view, int depth,
                                            std::int64_t max_error, std::int32_t sample_reach) {
  assert(depth >= 1 && depth <= kMaxRenderDepth && max_error >= 0);
  assert(sample_reach >= kOneSampleReach && sample_reach <= kMaxSampleReach);
  PerspectiveWalkTables tables;
  tables.depth = depth;
  tables.max_error = max_error;
  tables.sample_reach = sample_reach;
  tables.splat_margin = perspectiveSplatMargin(depth, sample_reach);
  const auto& m = view.world_to_camera.m_q30;
  for (int level = 0; level < depth; ++level) {
    // A child of a node of `level` lies 2^-(level+2) cube edges = 2^(22-level) units from it along
    // each model axis: the rotated sum in Q1.30, shifted once to the walk's units, Q.(24 + S).
    for (unsigned k = 0; k < 8; ++k) {
      const std::int64_t s[3] = {(k & 4) ? 1 : -1, (k & 2) ? 1 : -1, (k & 1) ? 1 : -1};
      std::int64_t c[3];
      for (int row = 0; row < 3; ++row) {
        c[row] = roundShiftRight(m[row][0] * s[0] + m[row][1] * s[1] + m[row][2] * s[2],
                                 30 - (kPerspectiveUnitBits - 2 - level + view.walk_bits));
      }
      tables.child_offset[static_cast<std::size_t>(level)][k] = {c[0], c[1], c[2]};
    }
  }
  for (int level = 0; level <= depth; ++level) {
    // Half a node's edge, rotated, plus the rounding its centre gathered on the way (half a unit
    // per level and the rotation's few Q30 ulp: one unit per level).
    const std::int64_t half = std::int64_t{1} << (kPerspectiveUnitBits - 1 - level);
    tables.reach[static_cast<std::size_t>(level)] = rotatedCubeReach(half) + depth;
    // kDepthTermQ30's premise: 3 (half + depth)^2 <= (9/8) reach^2.
    assert(24 * (half + depth) * (half + depth) <=
           9 * tables.reach[static_cast<std::size_t>(level)] *
               tables.reach[static_cast<std::size_t>(level)]);
  }
  // Pixels Q(32-F).F over f Q.16, to Q2.30: shifted by 30 + 16 - F. Centred (no pan) each side is
  // (width / 2) / f exactly as (width << 15) / f would give.
  const int shift = 46 - view.fraction_bits;
  const auto slope = [&](std::int64_t pixels) {
    return divShiftRound(pixels, view.focal_q16, shift).value_or(INT64_MAX);
  };
  const std::int64_t width = std::int64_t{view.camera.width} << view.fraction_bits;
  const std::int64_t height = std::int64_t{view.camera.height} << view.fraction_bits;
  tables.left_q30 = slope(view.centre_x);
  tables.right_q30 = slope(width - view.centre_x);
  tables.top_q30 = slope(view.centre_y);
  tables.bottom_q30 = slope(height - view.centre_y);
  tables.left_limit = smallProductLimit(tables.left_q30);
  tables.right_limit = smallProductLimit(tables.right_q30);
  tables.top_limit = smallProductLimit(tables.top_q30);
  tables.bottom_limit = smallProductLimit(tables.bottom_q30);
  const auto widest = [](std::int64_t a, std::int64_t b) {
    if (a == INT64_MAX || b == INT64_MAX) return INT64_MAX;
    return std::max(a < 0 ? -a : a, b < 0 ? -b : b);
  };
  tables.slope_x_q30 = widest(tables.left_q30, tables.right_q30);
  tables.slope_y_q30 = widest(tables.top_q30, tables.bottom_q30);
  // Bucket 0: any box that meets the frustum, whose centre has |c.x| <= s * (z + r) + r for the
  // larger side slope s (spread s * (1 + q) + q + 9/16). Bucket b >= 1: a centre with
  // max(|c.x|, |c.y|) <= z / 2^(b - 1), nearer the view's axis (spread 2^(1 - b) + 9/16); never
  // a larger depth than bucket 0's, which holds for it too.
  const std::int64_t frustum_slope = std::max(tables.slope_x_q30, tables.slope_y_q30);
  for (int bucket = 0; bucket < PerspectiveWalkTables::kAffineBuckets; ++bucket) {
    const std::int64_t ratio = bucket == 0
                                   ? largestAffineRatio(
                                         view,
                                         [&](std::int64_t q) -> std::optional<std::int64_t> {
                                           const std::optional<std::int64_t> sides =
                                               mulShiftRoundQuick(frustum_slope, kOneQ30 + q, 30);
                                           if (!sides) return std::nullopt;
                                           return *sides + q + kDepthTermQ30 + 1;
                                         },
                                         max_error)
                                   : largestAffineRatio(
                                         view,
                                         [&](std::int64_t) -> std::optional<std::int64_t> {
                                           return kDepthTermQ30 + (kOneQ30 >> (bucket - 1));
                                         },
                                         max_error);
    auto& affine_depth = tables.affine_depth[static_cast<std::size_t>(bucket)];
    auto& growth_q16 = tables.growth_q16[static_cast<std::size_t>(bucket)];
    for (int level = 0; level <= depth; ++level) {
      const auto l = static_cast<std::size_t>(level);
      const std::int64_t reach = tables.reach[l];
      // z >= r / q, rounded up; no depth at all when even the smallest ratio fails.
      std::int64_t depth_needed =
          ratio == 0 ? INT64_MAX : divShiftRoundQuick(reach, ratio, 30).value_or(INT64_MAX - 1) + 1;
      if (bucket > 0) depth_needed = std::min(depth_needed, tables.affine_depth[0][l]);
      affine_depth[l] = depth_needed;
      // z / (z - reach) falls as z grows: at most its value at the least depth drawn so, rounded
      // up (1 where no depth the eye can see is that far: no subtree of the level is drawn so).
      growth_q16[l] = depth_needed >= (INT64_MAX >> 17) || depth_needed <= reach
                          ? std::int64_t{1} << 16
                          : divShiftRoundQuick(depth_needed, depth_needed - reach, 16)
                                    .value_or(INT64_MAX >> 24) +
                                1;
    }
  }
  return tables;
}

namespace {

// Writes each leaf's splat (pixelSpan on both axes) with its packed word, nearer wins. Inside a
// subtree drawn from one affine map whose every splat lies on the screen (enterAffine), a leaf's
// pixels are two additions and shifts from its position, without clipping. A kColourNormal frame
// (the styles that light or outline) takes each leaf's normal index too, and the depth code of
// renderer/perspective_depth.h.
template <PixelPayload kPayload>
class PerspectivePlot {
 public:
  PerspectivePlot(const LevelView& level, FrameView& frame, int fraction_bits, std::int64_t padding,
                  int depth_shift, OcclusionTiles* occlusion = nullptr)
      : colours_(level.leaves.data()),
        normals_(level.normals.data()),
        pixels_(frame.pixelData()),
        row_stride_(static_cast<std::size_t>(frame.width())),
        width_(frame.width()),
        height_(frame.height()),
        fraction_bits_(fraction_bits),
        padding_(padding),
        depth_shift_(depth_shift),
        occlusion_(occlusion) {}

  // Occlusion culling (with tiles): whether every pixel the subtree's leaves could write already
  // holds a nearer word than any of them would (then none of them changes the frame).
  bool hidden(const AffineSubtree& subtree) {
    const std::int64_t nearest = subtree.centre.z - subtree.reach_z;  // Q.24, every leaf's z >= it
    if (nearest < 0) return false;
    const PixelBox box = pixelsOf(subtree);
    // A leaf's key grows with its z; its word is at least that key's with payload 0.
    const std::uint32_t word = wordOf(nearest, 0);
    // Wholly off the screen, it writes nothing (the frustum test let it through by its margin).
    if (box.empty() || occlusion_->hidden(box.x0, box.x1, box.y0, box.y1, word)) {
      ++hidden_subtrees_;
      return true;
    }
    return false;
  }
  // Whether none of the subtree's leaves writes a pixel of this frame (or band).
  bool offScreen(const AffineSubtree& subtree) const { return pixelsOf(subtree).empty(); }
  // The subtree's leaves may have written their pixels.
  void drawn(const AffineSubtree& subtree) {
    const PixelBox box = pixelsOf(subtree);
    if (!box.empty()) occlusion_->touched(box.x0, box.x1, box.y0, box.y1);
  }

  void enterAffine(const AffineSubtree& subtree) {
    in_affine_ = true;
    const std::int64_t one = std::int64_t{1} << fraction_bits_, mid = one >> 1;
    const std::int64_t half_x = subtree.half_x + padding_, half_y = subtree.half_y + padding_;
    // pixelSpan's bounds with this half extent: [(p + low) >> F, (p + high) >> F].
    low_x_ = -half_x - mid + one - 1;
    high_x_ = half_x - mid;
    low_y_ = -half_y - mid + one - 1;
    high_y_ = half_y - mid;
    enterPart(subtree);
  }
  // A part of the subtree entered (a node of it: every leaf of the part within `part`'s reaches
  // of its centre): whether its leaves may come unchecked_, corners_ and narrow_ (narrowLeaf),
  // which it returns; enterAffine's subtree is its own first part. A part entered inside a
  // clipped subtree is left by leavePart, which restores the subtree's flags.
  bool enterPart(const AffineSubtree& part) {
    saved_ = {unchecked_, corners_, narrow_};
    const std::int64_t one = std::int64_t{1} << fraction_bits_;
    const std::int64_t half_x = part.half_x + padding_, half_y = part.half_y + padding_;
    // Every leaf's splat (p +- half, or p's own pixel) on the screen, its depth key below the
    // largest: each is within the reaches of the centre.
    const std::int64_t x = part.centre.x, y = part.centre.y, z = part.centre.z;
    const std::int64_t margin_x = part.reach_x + half_x + one;
    const std::int64_t margin_y = part.reach_y + half_y + one;
    unchecked_ = x - margin_x >= 0 && x + margin_x < (std::int64_t{width_} << fraction_bits_) &&
                 y - margin_y >= 0 && y + margin_y < (std::int64_t{height_} << fraction_bits_) &&
                 z - part.reach_z >= 0 &&
                 (z + part.reach_z) >> depth_shift_ <= FrameView::kMaxDepthKey;
    // Where high - low < 1 pixel, no leaf's span is more than two pixels on that axis: then every
    // leaf takes the four-corner path, without the test per leaf which path (a coin toss where
    // spans of two and three pixels mix).
    corners_ = unchecked_ && high_x_ - low_x_ < one && high_y_ - low_y_ < one;
    // In 32 bits (narrowLeaf) where every position of the part and every span bound lies in
    // [0, 2^31): unchecked_ puts x and y, each +- reach and half extent, within [0, W << F) and
    // [0, H << F), below 2^31 where the frame's Q(32-F).F sides are (all but F > 18 on the largest
    // frames); the depth takes z + reach_z below 2^31 too (Q.24: 128 cube edges).
    narrow_ = unchecked_ && (std::int64_t{width_} << fraction_bits_) <= INT32_MAX &&
              (std::int64_t{height_} << fraction_bits_) <= INT32_MAX &&
              z + part.reach_z <= INT32_MAX;
    if (narrow_) {
      low_x32_ = static_cast<std::int32_t>(low_x_);
      high_x32_ = static_cast<std::int32_t>(high_x_);
      low_y32_ = static_cast<std::int32_t>(low_y_);
      high_y32_ = static_cast<std::int32_t>(high_y_);
    }
    return narrow_;
  }
  void leavePart() { std::tie(unchecked_, corners_, narrow_) = saved_; }
  void leaveAffine() { unchecked_ = corners_ = narrow_ = in_affine_ = false; }
  bool narrowAffine() const { return narrow_; }

  // operator()'s unchecked path in 32 bits, for a leaf of a subtree narrowAffine holds for (its
  // half extents the subtree's): the same shifts of the same values, so the same pixels and word.
  __attribute__((always_inline)) void narrowLeaf(std::size_t index, std::int32_t x, std::int32_t y,
                                                 std::int32_t z) {
    ++leaves_;
    const std::uint32_t word =
        kPayload == PixelPayload::kColour
            ? FrameView::pack(static_cast<std::uint32_t>(z) >> depth_shift_, colours_[index])
            : wordOf(z, payloadOf(index));
    const auto f = static_cast<int>(fraction_bits_);
    std::int32_t first_x = (x + low_x32_) >> f, last_x = (x + high_x32_) >> f;
    if (last_x < first_x) first_x = last_x = x >> f;
    std::int32_t first_y = (y + low_y32_) >> f, last_y = (y + high_y32_) >> f;
    if (last_y < first_y) first_y = last_y = y >> f;
    if (corners_) {
      corners(first_x, last_x, first_y, last_y, word);
    } else {
      fill(first_x, last_x, first_y, last_y, word);
    }
  }

  // Inlined into the walk's leaf loop: a call per leaf, its leaf passed through memory, was a
  // fifth of a frame's instructions (callgrind).
  __attribute__((always_inline)) void operator()(const PerspectiveLeaf& leaf) {
    ++leaves_;
    if (unchecked_) {
      // unchecked_: the key is below kMaxDepthKey without the clamp (enterAffine).
      const std::uint32_t word =
          kPayload == PixelPayload::kColour
              ? FrameView::pack(static_cast<std::uint32_t>(leaf.z >> depth_shift_),
                                colours_[leaf.index])
              : wordOf(leaf.z, payloadOf(leaf.index));
      const auto f = static_cast<int>(fraction_bits_);
      std::int64_t first_x = (leaf.x + low_x_) >> f, last_x = (leaf.x + high_x_) >> f;
      if (last_x < first_x) first_x = last_x = leaf.x >> f;
      std::int64_t first_y = (leaf.y + low_y_) >> f, last_y = (leaf.y + high_y_) >> f;
      if (last_y < first_y) first_y = last_y = leaf.y >> f;
      if (corners_) {
        corners(first_x, last_x, first_y, last_y, word);
      } else {
        fill(first_x, last_x, first_y, last_y, word);
      }
      return;
    }
    const auto f = static_cast<int>(fraction_bits_);
    const PixelSpan columns = pixelSpan(leaf.x, leaf.half_x + padding_, f, width_);
    const PixelSpan rows = pixelSpan(leaf.y, leaf.half_y + padding_, f, height_);
    if (columns.first > columns.last || rows.first > rows.last) return;  // off the screen
    fill(columns.first, columns.last, rows.first, rows.last, wordOf(leaf.z, payloadOf(leaf.index)));
    if (occlusion_ != nullptr && !in_affine_) {
      occlusion_->touched(
          static_cast<std::int32_t>(columns.first), static_cast<std::int32_t>(columns.last),
          static_cast<std::int32_t>(rows.first), static_cast<std::int32_t>(rows.last));
    }
  }

  std::uint64_t leaves() const { return leaves_; }
  std::uint64_t hiddenSubtrees() const { return hidden_subtrees_; }

 private:
  // What a leaf's word carries besides its depth: its palette index, and in a kColourNormal
  // frame its normal index << 8.
  __attribute__((always_inline)) std::uint32_t payloadOf(std::size_t index) const {
    if constexpr (kPayload == PixelPayload::kColour) {
      return colours_[index];
    } else {
      return colours_[index] | std::uint32_t{normals_[index]} << 8;
    }
  }
  // The word of depth z (Q.24) with `payload`; with payload 0, the least word a leaf at z writes.
  // A scaled instance of a scene (depth_shift_ other than kPerspectiveDepthShift) has its z in its
  // own units: the normal frame's code takes it in the scene's.
  __attribute__((always_inline)) std::uint32_t wordOf(std::int64_t z, std::uint32_t payload) const {
    if constexpr (kPayload == PixelPayload::kColour) {
      return FrameView::pack(static_cast<std::uint32_t>(std::min<std::int64_t>(
                                 z >> depth_shift_, FrameView::kMaxDepthKey)),
                             static_cast<std::uint8_t>(payload));
    } else {
      const std::int64_t scene_z = depth_shift_ >= kPerspectiveDepthShift
                                       ? z >> (depth_shift_ - kPerspectiveDepthShift)
                                       : z << (kPerspectiveDepthShift - depth_shift_);
      return FrameView::packColourNormal(perspectiveNormalDepthKey(scene_z), payload);
    }
  }

  struct PixelBox {
    std::int32_t x0, x1, y0, y1;  // inclusive, on the screen
    bool empty() const { return x0 > x1 || y0 > y1; }
  };
  // The pixels a subtree's leaves may write: they lie within its reaches of its centre, and each
  // writes the pixels within its half extent and the padding of its position, or its own pixel;
  // a pixel more each way is room for the rounding. Clipped to the screen.
  PixelBox pixelsOf(const AffineSubtree& subtree) const {
    const auto f = static_cast<int>(fraction_bits_);
    const std::int64_t reach_x = subtree.reach_x + subtree.half_x + padding_;
    const std::int64_t reach_y = subtree.reach_y + subtree.half_y + padding_;
    // Clamped to [0, size] and [-1, size - 1]: empty where it lies wholly off the screen.
    const auto low = [f](std::int64_t v, std::int32_t size) {
      return static_cast<std::int32_t>(std::clamp<std::int64_t>((v >> f) - 1, 0, size));
    };
    const auto high = [f](std::int64_t v, std::int32_t size) {
      return static_cast<std::int32_t>(std::clamp<std::int64_t>((v >> f) + 1, -1, size - 1));
    };
    return {low(subtree.centre.x - reach_x, width_), high(subtree.centre.x + reach_x, width_),
            low(subtree.centre.y - reach_y, height_), high(subtree.centre.y + reach_y, height_)};
  }

  // Columns [first_x, last_x] of rows [first_y, last_y], on the screen: the nearer word wins,
  // branch-free (which one is nearer is a coin toss where splats overlap). Splats of up to 2 x 2
  // pixels, most of them where a voxel is about a pixel, write their four corners, and up to 3 x 3
  // their nine (a pixel twice where the splat is narrower: the min is the same): the loops,
  // vectorised for long rows, cost some 15 instructions per pixel of such short ones (callgrind).
  // Int: int64, or int32 from narrowLeaf (the loops' counters in one register on a Cortex-M).
  template <typename Int>
  void fill(Int first_x, Int last_x, Int first_y, Int last_y, std::uint32_t word) {
    const std::size_t width = row_stride_;
    if (last_x - first_x <= 1 && last_y - first_y <= 1) {
      corners(first_x, last_x, first_y, last_y, word);
      return;
    }
    if (last_x - first_x <= 2 && last_y - first_y <= 2) {
      // Up to 3 x 3 (voxels of about two pixels, padded): the middle column and row are the
      // first's next, clamped to the last.
      const Int middle_x = std::min<Int>(first_x + 1, last_x);
      const Int rows[3] = {first_y, std::min<Int>(first_y + 1, last_y), last_y};
      for (const Int y : rows) {
        std::uint32_t* const row = pixels_ + static_cast<std::size_t>(y) * width;
        row[first_x] = std::min(row[first_x], word);
        row[middle_x] = std::min(row[middle_x], word);
        row[last_x] = std::min(row[last_x], word);
      }
      return;
    }
    for (Int y = first_y; y <= last_y; ++y) {
      std::uint32_t* const row = pixels_ + static_cast<std::size_t>(y) * width;
      for (Int x = first_x; x <= last_x; ++x) row[x] = std::min(row[x], word);
    }
  }

  // A splat of at most 2 x 2 pixels: its four corners (a pixel twice where it is narrower).
  template <typename Int>
  __attribute__((always_inline)) void corners(Int first_x, Int last_x, Int first_y, Int last_y,
                                              std::uint32_t word) {
    std::uint32_t* const top = pixels_ + static_cast<std::size_t>(first_y) * row_stride_;
    std::uint32_t* const bottom = pixels_ + static_cast<std::size_t>(last_y) * row_stride_;
    top[first_x] = std::min(top[first_x], word);
    top[last_x] = std::min(top[last_x], word);
    bottom[first_x] = std::min(bottom[first_x], word);
    bottom[last_x] = std::min(bottom[last_x], word);
  }

  // 64-bit fields where a 32-bit one would be reloaded after every pixel written (a uint32 store
  // may alias an int32 field).
  const std::uint8_t* colours_;
  const std::uint8_t* normals_;  // kColourNormal: the level's normal index per leaf
  std::uint32_t* pixels_;  // the whole frame: a perspective view has no cube-sized bound to give
  std::size_t row_stride_;
  std::int32_t width_, height_;
  std::int64_t fraction_bits_;
  std::int64_t padding_;
  std::int64_t depth_shift_;  // PerspectiveView::depth_shift
  bool unchecked_ = false;
  bool corners_ = false;  // unchecked_, and no span of the subtree wider than 2 x 2 pixels
  bool narrow_ = false;   // unchecked_, and the subtree's positions within 32 bits (enterAffine)
  std::tuple<bool, bool, bool> saved_{};  // the three above as enterPart found them
  std::int64_t low_x_ = 0, high_x_ = 0, low_y_ = 0, high_y_ = 0;
  std::int32_t low_x32_ = 0, high_x32_ = 0, low_y32_ = 0, high_y32_ = 0;  // the same, narrow_
  OcclusionTiles* occlusion_;
  bool in_affine_ = false;  // inside enterAffine .. leaveAffine: the walk marks its tiles
  std::uint64_t leaves_ = 0;
  std::uint64_t hidden_subtrees_ = 0;
};

template <PixelPayload kPayload>
bool drawLayers(std::span<const PerspectiveLayer> layers, const PerspectiveDetail* detail,
                const PerspectiveView& view, FrameView& frame, OcclusionTiles* occlusion,
                PerspectiveDrawStats* stats, const PerspectiveBand* band,
                const std::atomic<bool>* abort) {
  bool complete = true;
  // The finest depth's parts first: they are the nearest, and hide most of what lies behind.
  for (std::size_t i = layers.size(); i-- > 0 && complete;) {
    const PerspectiveLayer& layer = layers[i];
    PerspectiveWalkParts parts;
    parts.index = layer.index;
    parts.cull = occlusion != nullptr;
    parts.band = band;
    if (layers.size() > 1) {
      parts.detail = {detail, static_cast<int>(i), i == 0 ? -1 : layers[i - 1].level->depth};
    }
    PerspectivePlot<kPayload> plot(*layer.level, frame, view.fraction_bits,
                                   splatPadding(*layer.tables), view.depth_shift, occlusion);
    PerspectiveWalk<PerspectivePlot<kPayload>> walk(*layer.level, view, *layer.tables, plot, abort,
                                                    parts);
    complete = walk.run();
    if (stats != nullptr) {
      stats->leaves += plot.leaves();
      stats->hidden_subtrees += plot.hiddenSubtrees();
    }
  }
  return complete;
}

// Whether every layer has the normal index per leaf a kColourNormal frame takes.
bool layersHaveNormals(std::span<const PerspectiveLayer> layers) {
  return std::all_of(layers.begin(), layers.end(), [](const PerspectiveLayer& layer) {
    return layer.level->normals.size() == layer.level->leaves.size();
  });
}

}  // namespace

bool drawPerspective(const LevelView& level, const PerspectiveView& view,
                     const PerspectiveWalkTables& tables, FrameView& frame,
                     const std::atomic<bool>* abort) {
  const PerspectiveLayer layer{&level, &tables, nullptr};
  return drawPerspectiveLayers({&layer, 1}, nullptr, view, frame, nullptr, nullptr, nullptr, abort);
}

bool drawPerspectiveLayers(std::span<const PerspectiveLayer> layers,
                           const PerspectiveDetail* detail, const PerspectiveView& view,
                           FrameView& frame, OcclusionTiles* occlusion, PerspectiveDrawStats* stats,
                           const PerspectiveBand* band, const std::atomic<bool>* abort) {
  // A part of a partly held model (renderer/chunked_assembly.h) has layers for the coarsest of
  // the whole model's detail depths only, and its detail's `finest` caps the ask at its own.
  assert(!layers.empty() &&
         (layers.size() == 1 ||
          (detail != nullptr && detail->count >= static_cast<int>(layers.size()) &&
           detail->finest < static_cast<int>(layers.size()))));
  assert(occlusion == nullptr ||
         (occlusion->width() == frame.width() && occlusion->height() == frame.height()));
  if (frame.payload() == PixelPayload::kColour) {
    return drawLayers<PixelPayload::kColour>(layers, detail, view, frame, occlusion, stats, band,
                                             abort);
  }
  if (!layersHaveNormals(layers)) return false;
  return drawLayers<PixelPayload::kColourNormal>(layers, detail, view, frame, occlusion, stats,
                                                 band, abort);
}

}  // namespace octopoint
