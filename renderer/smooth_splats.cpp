// Smooth splats (octopoint/smooth.h, docs/splats.md "Smooth splats"): passes 2 and 3 over a box
// frame. Integers only: weights Q8 per axis, their product Q12, colour sums in 32 bits.

#include <algorithm>
#include <array>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>  // SSE2, which every x86-64 has; AVX2 where the CPU has it
#define OCTOPOINT_SMOOTH_SSE2 1
#endif

#include "octopoint/smooth.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"
#include "renderer/smooth_normalise.h"
#include "renderer/smooth_normals.h"
#include "renderer/smooth_reach.h"
#include "renderer/subtree_clip.h"

namespace octopoint {
namespace {

// The kernel's table: the weight at a distance of i / kKernelSteps of the kernel's radius, Q8
// (256 at the centre, falling to 1 at the last step). The cubic 1 - 3t^2 + 2t^3 sums to one
// between two samples a radius apart, as the tent 1 - t does, but joins them without a crease.
constexpr int kKernelSteps = 256;
constexpr std::array<std::uint16_t, kKernelSteps> kKernel = [] {
  std::array<std::uint16_t, kKernelSteps> table{};
  constexpr std::int64_t kOne = kKernelSteps;  // t = i / kOne
  for (std::int64_t i = 0; i < kKernelSteps; ++i) {
    // 256 (1 - 3t^2 + 2t^3) = (256 kOne^3 - 768 i^2 kOne + 512 i^3) / kOne^3, rounded.
    const std::int64_t scaled = 256 * kOne * kOne * kOne - 768 * i * i * kOne + 512 * i * i * i;
    const std::int64_t weight = (scaled + kOne * kOne * kOne / 2) / (kOne * kOne * kOne);
    table[static_cast<std::size_t>(i)] =
        static_cast<std::uint16_t>(std::max<std::int64_t>(weight, 1));
  }
  return table;
}();

// The kernel's radius, in sixteenths of the voxel's edge on screen (voxelEdgeOnScreen), the
// spacing of neighbouring centres: a radius of one spacing lets every pixel between two centres
// take both. The same on both axes: a turned voxel's footprint is wider than its edge, but its
// neighbours are no farther apart.
constexpr std::int64_t kRadiusSixteenths = 16;
// Contributions whose depth key differs from the pixel's nearest by more than this many voxel
// edges belong to another surface (one behind, or one in front that does not cover the pixel).
// Measured on a dense sphere turned 30 degrees (tests/core/smooth_splats_test.cpp): 2 edges left
// holes up to 1.7 voxels inside its outline, where the surface turns away and neighbouring
// voxels within the kernel's reach lie deeper; 4 leaves none.
constexpr std::uint64_t kDepthToleranceVoxelEdges = 4;
// A pixel is covered where its summed weight (Q12: one leaf's centre is 4096) is at least this.
// On the default model at 480x360 zoom 3, 2048 and 3072 opened cracks the box frame does not
// have where the scan is sparse (a pixel few leaves reach); 1024 keeps the box frame's coverage
// inside a surface and rounds the outline of a turned one (docs/splats.md).
constexpr std::uint32_t kCoverWeight = 1024;

// A leaf's weight product wx * wy (Q16) is kept Q12, so that a contribution, colour times weight,
// is below 2^20: a pixel's sums wrap only past 4,096 full-weight contributions, where the leaves
// within a kernel's reach and the depth tolerance are a few dozen.
constexpr int kProductShift = 4;

// What a walk blends of the leaves' normals: their indices, the palette turned for the frame, and
// the pixels' sums.
struct NormalBlend {
  const std::uint8_t* leaf_normals = nullptr;  // one index per leaf; nullptr: no normals blended
  std::array<BlendNormal, 256> turned{};
  DirectionQ14* sums = nullptr;
};

class BlendWalk {
 public:
  BlendWalk(const LevelView& level, const FrameSetup& setup, const FrameView& frame,
            SmoothSplats::Sums* sums, const PaletteRgb& palette, std::uint16_t* column_weight,
            std::uint16_t* row_weight, const NormalBlend& normals, const std::atomic<bool>* abort)
      : node_(level.nodes.data()),
        leaf_(level.leaves.data()),
        first_leaf_(level.leaves.data()),
        normals_(normals),
        setup_(setup),
        words_(frame.pixels().data()),
        sums_(sums),
        palette_(palette),
        column_weight_(column_weight),
        row_weight_(row_weight),
        abort_(abort),
        radius_x_(smoothReachOf(setup).radius),
        radius_y_(radius_x_),
        // divideUnsigned: no libgcc division on a Cortex-M0+ (docs/device.md), the same bits.
        inverse_x_(
            divideUnsigned(std::uint64_t{kKernelSteps} << 32, static_cast<std::uint64_t>(radius_x_))
                .quotient),
        inverse_y_(
            divideUnsigned(std::uint64_t{kKernelSteps} << 32, static_cast<std::uint64_t>(radius_y_))
                .quotient),
        tolerance_(smoothReachOf(setup).tolerance),
        clip_(setup, kernelReach()) {}

  bool run() {
    visit(0, setup_.root);
    return !aborted_;
  }

 private:
  // The pixels a leaf reaches, as a footprint for SubtreeClip: p - R .. p + R per axis.
  SplatFootprint kernelReach() const {
    SplatFootprint reach;
    reach.offset_x = static_cast<std::int32_t>(-radius_x_);
    reach.offset_y = static_cast<std::int32_t>(-radius_y_);
    reach.span_x = static_cast<std::int32_t>(2 * radius_x_);
    reach.span_y = static_cast<std::int32_t>(2 * radius_y_);
    return reach;
  }

  void visit(int level, const Vec3& centre) {
    if (level == kAbortCheckLevel && abort_ != nullptr && !aborted_) {
      aborted_ = abort_->load(std::memory_order_relaxed);
    }
    if (aborted_) return;
    if (clip_.classify(level, centre) == Clip::kOutside) {
      skipSubtree(node_, leaf_, level, setup_.depth);
      return;
    }
    unsigned mask = *node_++;
    const auto& offsets = setup_.child_offset[static_cast<std::size_t>(level)];
    if (level + 1 == setup_.depth) {
      for (; mask != 0; mask &= mask - 1) add(centre + offsets[lowestChild(mask)], leaf_++);
      return;
    }
    for (; mask != 0; mask &= mask - 1) visit(level + 1, centre + offsets[lowestChild(mask)]);
  }

  // The columns (or rows) whose pixel centre lies within `radius` of `at` (Q(32-F).F), clipped to
  // [0, size), with each one's weight into `weight`: [begin, end).
  using Span = KernelSpan;
  Span weigh(std::int32_t at, std::int64_t radius, std::uint64_t inverse, std::int32_t size,
             std::uint16_t* weight) const {
    const int f = setup_.fraction_bits;
    const std::int64_t half = std::int64_t{1} << (f - 1);
    const auto [begin, end] = kernelSpan(at, radius, f, size);
    // |offset| inverse, offset = c - at (< radius), by one addition a column: offset inverse
    // grows by 2^F inverse (below 2^41 in magnitude: inverse <= 2^40 / radius, radius >= 2^F).
    const auto step = static_cast<std::int64_t>(inverse) << f;
    std::int64_t product =
        ((std::int64_t{begin} << f) + half - at) * static_cast<std::int64_t>(inverse);
    for (std::int32_t i = begin; i < end; ++i, product += step) {
      const auto distance = static_cast<std::uint64_t>(product < 0 ? -product : product);
      weight[i - begin] = kKernel[static_cast<std::size_t>(distance >> 32)];
    }
    return {begin, end};
  }

  void add(const Vec3& p, const std::uint8_t* leaf_at) {
    Span columns = weigh(p.x, radius_x_, inverse_x_, setup_.width, column_weight_);
    if (columns.begin >= columns.end) return;
#ifdef OCTOPOINT_SMOOTH_SSE2
    // The vector steps take whole groups of four: a reach of 4k + 1 .. 4k + 3 columns is widened
    // to the right, inside the frame, by columns of weight 0 (they add nothing), rather than
    // leaving one to three columns of every row to the scalar loop.
    const std::int32_t whole = (columns.end - columns.begin + 3) & ~3;
    if (whole >= 4 && columns.begin + whole <= setup_.width) {
      std::fill(column_weight_ + (columns.end - columns.begin), column_weight_ + whole,
                std::uint16_t{0});
      columns.end = columns.begin + whole;
    }
#endif
    const Span rows = weigh(p.y, radius_y_, inverse_y_, setup_.height, row_weight_);
    const auto width = static_cast<std::size_t>(setup_.width);
    const std::size_t first =
        static_cast<std::size_t>(rows.begin) * width + static_cast<std::size_t>(columns.begin);
    const LeafReach leaf{setup_.depthKey(p.z),
                         tolerance_,
                         palette_[*leaf_at],
                         column_weight_,
                         row_weight_,
                         static_cast<std::size_t>(columns.end - columns.begin),
                         static_cast<std::size_t>(std::max<std::int32_t>(rows.end - rows.begin, 0)),
                         words_ + first,
                         sums_ + first,
                         width};
    if (normals_.leaf_normals != nullptr) {
      const auto index = static_cast<std::size_t>(leaf_at - first_leaf_);
      addWithNormal(leaf, normals_.turned[normals_.leaf_normals[index]], normals_.turned,
                    normals_.sums + first);
      return;
    }
    std::size_t done = 0;  // the columns of every row the vector steps did
#ifdef OCTOPOINT_SMOOTH_SSE2
    if (leaf.columns >= 4) done = avx2_ ? addVectorsAvx2(leaf) : addVectorsSse2(leaf);
#endif
    addScalar(leaf, done);
  }

  // One leaf and the pixels it reaches: pixel (i, r) of its reach is words[r * stride + i], its
  // weight (row_weight[r] * column_weight[i]) >> kProductShift (Q8 x Q8 -> Q12).
  struct LeafReach {
    std::uint32_t key;        // its depth key
    std::uint32_t tolerance;  // depth-key units
    Rgb colour;
    const std::uint16_t* column_weight;
    const std::uint16_t* row_weight;
    std::size_t columns, rows;
    const std::uint32_t* words;
    SmoothSplats::Sums* sums;
    std::size_t stride;
  };

  // Columns [from, columns) of every row: each pixel whose nearest depth is within the tolerance
  // of the leaf's takes its colour with its weight.
  static void addScalar(const LeafReach& leaf, std::size_t from) {
    for (std::size_t r = 0; r < leaf.rows; ++r) {
      const std::uint32_t row_weight = leaf.row_weight[r];
      const std::uint32_t* const words = leaf.words + r * leaf.stride;
      SmoothSplats::Sums* const sums = leaf.sums + r * leaf.stride;
      for (std::size_t i = from; i < leaf.columns; ++i) {
        const std::uint32_t word = words[i];
        // Within the tolerance of the pixel's nearest depth, either side (unsigned: one compare).
        if (word == FrameView::kEmpty ||
            leaf.key - FrameView::depthKeyOf(word) + leaf.tolerance > 2 * leaf.tolerance) {
          continue;
        }
        const std::uint32_t weight = (row_weight * leaf.column_weight[i]) >> kProductShift;  // Q12
        SmoothSplats::Sums& sum = sums[i];
        sum.r += weight * leaf.colour.r;
        sum.g += weight * leaf.colour.g;
        sum.b += weight * leaf.colour.b;
        sum.weight += weight;
      }
    }
  }

  // addScalar for a frame that carries normals (PixelPayload::kColourNormal), whose words keep the
  // depth key's top 16 bits: the tolerance in those units, rounded up; the leaf's normal (view
  // axes, Q1.10) added with the same weight as its colour, turned to the side of the pixel's own
  // (its word's) normal: where a surface behind lies within the tolerance (a sphere's far side
  // near its outline), its normals, turned toward the viewer, would otherwise cancel the near
  // side's across the screen and light the outline as if it faced the viewer. One pixel at a
  // time: styled close-ups are the viewer's and octopoint-render's, not the bare colour frames
  // the vector steps serve.
  static void addWithNormal(const LeafReach& leaf, const BlendNormal& normal,
                            const std::array<BlendNormal, 256>& turned, DirectionQ14* normal_sums) {
    const std::uint32_t key = leaf.key >> 8, tolerance = (leaf.tolerance + 255) >> 8;
    for (std::size_t r = 0; r < leaf.rows; ++r) {
      const std::uint32_t row_weight = leaf.row_weight[r];
      const std::size_t at = r * leaf.stride;
      for (std::size_t i = 0; i < leaf.columns; ++i) {
        const std::uint32_t word = leaf.words[at + i];
        if (word == FrameView::kEmpty || key - (word >> 16) + tolerance > 2 * tolerance) continue;
        const std::uint32_t weight = (row_weight * leaf.column_weight[i]) >> kProductShift;  // Q12
        SmoothSplats::Sums& sum = leaf.sums[at + i];
        sum.r += weight * leaf.colour.r;
        sum.g += weight * leaf.colour.g;
        sum.b += weight * leaf.colour.b;
        sum.weight += weight;
        DirectionQ14& n = normal_sums[at + i];
        const BlendNormal& own = turned[FrameView::normalIndexOf(word)];
        const std::int32_t agree = own.x * normal.x + own.y * normal.y + own.z * normal.z;
        const auto w =
            agree < 0 ? -static_cast<std::int32_t>(weight) : static_cast<std::int32_t>(weight);
        n.x += w * normal.x;
        n.y += w * normal.y;
        n.z += w * normal.z;
      }
    }
  }

#ifdef OCTOPOINT_SMOOTH_SSE2
  // addScalar four pixels at a time, the same sums (wrapping 32-bit adds of the same products). A
  // pixel's four sums are one 16-byte vector: one multiply-add (pmaddwd of [w, 0] x [r, 0, g, 0,
  // b, 0, 1, 0], every factor below 2^15) gives [w r, w g, w b, w]. The depth test is addScalar's
  // as a signed compare of the values with their top bit flipped.
  struct Sse2Leaf {
    explicit Sse2Leaf(const LeafReach& leaf)
        : colour(_mm_setr_epi32(leaf.colour.r, leaf.colour.g, leaf.colour.b, 1)),
          key(_mm_set1_epi32(static_cast<int>(leaf.key + leaf.tolerance))),
          limit(_mm_set1_epi32(static_cast<int>((2 * leaf.tolerance) ^ 0x8000'0000U))) {}
    __m128i colour;  // 16-bit [c, 0] pairs
    __m128i key;     // key + tolerance: minus a pixel's key, the distance to test
    __m128i limit;   // 2 tolerance, top bit flipped
  };
  __attribute__((always_inline)) static inline void addFour(const Sse2Leaf& leaf,
                                                            __m128i row_weight,
                                                            const std::uint16_t* column_weight,
                                                            const std::uint32_t* words,
                                                            SmoothSplats::Sums* sums) {
    static_assert(sizeof(SmoothSplats::Sums) == 16);
    const __m128i word = _mm_loadu_si128(reinterpret_cast<const __m128i*>(words));
    const __m128i distance = _mm_sub_epi32(leaf.key, _mm_srli_epi32(word, 8));
    const __m128i outside = _mm_or_si128(
        _mm_cmpgt_epi32(_mm_xor_si128(distance, _mm_set1_epi32(static_cast<int>(0x8000'0000U))),
                        leaf.limit),
        _mm_cmpeq_epi32(word, _mm_set1_epi32(-1)));
    if (_mm_movemask_epi8(outside) == 0xFFFF) return;
    const __m128i columns = _mm_unpacklo_epi16(
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(column_weight)), _mm_setzero_si128());
    const __m128i weight = _mm_andnot_si128(
        outside, _mm_srli_epi32(_mm_madd_epi16(columns, row_weight), kProductShift));
    auto* sum = reinterpret_cast<__m128i*>(sums);
    _mm_storeu_si128(sum,
                     _mm_add_epi32(_mm_loadu_si128(sum),
                                   _mm_madd_epi16(_mm_shuffle_epi32(weight, 0x00), leaf.colour)));
    _mm_storeu_si128(sum + 1,
                     _mm_add_epi32(_mm_loadu_si128(sum + 1),
                                   _mm_madd_epi16(_mm_shuffle_epi32(weight, 0x55), leaf.colour)));
    _mm_storeu_si128(sum + 2,
                     _mm_add_epi32(_mm_loadu_si128(sum + 2),
                                   _mm_madd_epi16(_mm_shuffle_epi32(weight, 0xAA), leaf.colour)));
    _mm_storeu_si128(sum + 3,
                     _mm_add_epi32(_mm_loadu_si128(sum + 3),
                                   _mm_madd_epi16(_mm_shuffle_epi32(weight, 0xFF), leaf.colour)));
  }

  // The columns [0, n) of every row with n the most a multiple of 4 allows; returns n.
  static std::size_t addVectorsSse2(const LeafReach& leaf) {
    const Sse2Leaf vectors(leaf);
    const std::size_t n = leaf.columns & ~std::size_t{3};
    for (std::size_t r = 0; r < leaf.rows; ++r) {
      const __m128i row_weight = _mm_set1_epi32(leaf.row_weight[r]);  // Q8, [w, 0] pairs
      const std::size_t at = r * leaf.stride;
      for (std::size_t i = 0; i < n; i += 4) {
        addFour(vectors, row_weight, leaf.column_weight + i, leaf.words + at + i,
                leaf.sums + at + i);
      }
    }
    return n;
  }

  // addVectorsSse2 eight pixels at a time (two pixels' sums to a 32-byte vector), the last four
  // as it does them.
  __attribute__((target("avx2"))) static std::size_t addVectorsAvx2(const LeafReach& leaf) {
    const Sse2Leaf vectors(leaf);
    const __m256i colour = _mm256_broadcastsi128_si256(vectors.colour);
    // The depth test on the words themselves: a word is within the tolerance where it lies in
    // [lowest << 8, highest << 8 | 255], the depth keys [key - tolerance, key + tolerance] clipped
    // to [0, kMaxDepthKey] (so kEmpty, depth 2^24 - 1, is outside): one unsigned compare of the
    // word minus the first against the range's length, addScalar's test and its kEmpty test.
    const std::uint32_t lowest = leaf.key > leaf.tolerance ? leaf.key - leaf.tolerance : 0;
    const std::uint32_t highest = std::min(leaf.key + leaf.tolerance, FrameView::kMaxDepthKey);
    const __m256i first = _mm256_set1_epi32(static_cast<int>(lowest << 8));
    const __m256i length = _mm256_set1_epi32(static_cast<int>((highest - lowest) << 8 | 255));
    // Pixels 2k and 2k + 1's weights, each in the four lanes of its half.
    const __m256i pair[4] = {
        _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1), _mm256_setr_epi32(2, 2, 2, 2, 3, 3, 3, 3),
        _mm256_setr_epi32(4, 4, 4, 4, 5, 5, 5, 5), _mm256_setr_epi32(6, 6, 6, 6, 7, 7, 7, 7)};
    const std::size_t eights = leaf.columns & ~std::size_t{7};
    const std::size_t n = leaf.columns & ~std::size_t{3};
    for (std::size_t r = 0; r < leaf.rows; ++r) {
      const __m256i rows = _mm256_set1_epi32(leaf.row_weight[r]);
      const std::uint32_t* const words = leaf.words + r * leaf.stride;
      SmoothSplats::Sums* const sums = leaf.sums + r * leaf.stride;
      for (std::size_t i = 0; i < eights; i += 8) {
        const __m256i from = _mm256_sub_epi32(
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(words + i)), first);
        const __m256i inside = _mm256_cmpeq_epi32(_mm256_min_epu32(from, length), from);
        if (_mm256_testz_si256(inside, inside)) continue;
        const __m256i columns = _mm256_cvtepu16_epi32(
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(leaf.column_weight + i)));
        const __m256i weight = _mm256_and_si256(
            inside, _mm256_srli_epi32(_mm256_madd_epi16(columns, rows), kProductShift));
        auto* sum = reinterpret_cast<__m256i*>(sums + i);
        for (int k = 0; k < 4; ++k) {
          const __m256i weights = _mm256_permutevar8x32_epi32(weight, pair[k]);
          _mm256_storeu_si256(sum + k, _mm256_add_epi32(_mm256_loadu_si256(sum + k),
                                                        _mm256_madd_epi16(weights, colour)));
        }
      }
      if (n > eights) {
        addFour(vectors, _mm256_castsi256_si128(rows), leaf.column_weight + eights, words + eights,
                sums + eights);
      }
    }
    return n;
  }
#endif

  const std::uint8_t* node_;
  const std::uint8_t* leaf_;
  const std::uint8_t* const first_leaf_;  // the level's first leaf: a leaf's index, for its normal
  const NormalBlend& normals_;
  const FrameSetup& setup_;
  const std::uint32_t* words_;
  SmoothSplats::Sums* sums_;
  const PaletteRgb& palette_;
  std::uint16_t* column_weight_;
  std::uint16_t* row_weight_;
  const std::atomic<bool>* abort_;
  std::int64_t radius_x_, radius_y_;     // the kernel's radius, Q(32-F).F
  std::uint64_t inverse_x_, inverse_y_;  // kKernelSteps 2^32 / radius: distance to table step
  std::uint32_t tolerance_;              // depth-key units
  SubtreeClip clip_;
  const bool avx2_ = simdDecoderAvailable();  // addRow's eight-pixel steps (same sums)
  bool aborted_ = false;
};

bool validSize(std::int32_t width, std::int32_t height) {
  return width >= 1 && width <= kMaxViewportSide && height >= 1 && height <= kMaxViewportSide;
}

std::size_t pixelCount(std::int32_t width, std::int32_t height) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

SmoothReach smoothReachOf(const FrameSetup& setup) {
  SmoothReach reach;
  const std::uint64_t edge = voxelEdgeOnScreen(setup);  // Q(32-F).F pixels
  const std::uint64_t pixel = std::uint64_t{1} << setup.fraction_bits;
  reach.blends = setup.splat.active() &&
                 ((edge * static_cast<std::uint64_t>(setup.sample_reach)) >> 4) > pixel;
  // At least one pixel, so that a leaf always reaches the pixel it lies in; widened by the
  // level's sample reach (Q4; 16 leaves it as it was): neighbouring samples are that much farther
  // apart than the voxels (docs/splats.md, "Samples coarser than the voxel").
  const auto edge_or_pixel = static_cast<std::int64_t>(std::max(edge, pixel));
  reach.radius =
      std::max<std::int64_t>(edge_or_pixel * kRadiusSixteenths * setup.sample_reach / 256, 1);
  reach.tolerance = static_cast<std::uint32_t>(std::min<std::uint64_t>(
      (edge * kDepthToleranceVoxelEdges) >> setup.depth_shift, FrameView::kMaxDepthKey));
  return reach;
}

SmoothSplats::SmoothSplats(std::int32_t width, std::int32_t height)
    : width_(validSize(width, height) ? width : 0),
      height_(validSize(width, height) ? height : 0),
      owned_sums_(pixelCount(width_, height_)),
      owned_column_weight_(static_cast<std::size_t>(width_)),
      owned_row_weight_(static_cast<std::size_t>(height_)) {
  sums_ = owned_sums_;
  column_weight_ = owned_column_weight_;
  row_weight_ = owned_row_weight_;
}

SmoothSplats::SmoothSplats(std::int32_t width, std::int32_t height, const Memory& memory)
    : width_(0), height_(0) {
  if (!validSize(width, height) || memory.sums.size() < pixelCount(width, height) ||
      memory.column_weights.size() < static_cast<std::size_t>(width) ||
      memory.row_weights.size() < static_cast<std::size_t>(height)) {
    return;
  }
  width_ = width;
  height_ = height;
  sums_ = memory.sums.first(pixelCount(width, height));
  column_weight_ = memory.column_weights.first(static_cast<std::size_t>(width));
  row_weight_ = memory.row_weights.first(static_cast<std::size_t>(height));
}

SmoothSplats::SmoothSplats(std::int32_t width, std::int32_t height, const ModelView& model)
    : SmoothSplats(width, height) {
  if (width_ == 0 || !model.hasNormals()) return;
  normal_count_ = model.normalCount();
  for (int i = 0; i < normal_count_; ++i)
    normal_palette_[static_cast<std::size_t>(i)] = model.normal(i);
  normal_sums_.resize(sums_.size());
}

bool SmoothSplats::fits(const FrameSetup& setup, const FrameView& frame) const {
  return width_ != 0 && frame.width() == width_ && frame.height() <= height_ &&
         (frame.payload() == PixelPayload::kColour || !normal_sums_.empty()) &&
         checkFrameSetup(setup) == RenderError::kNone && setup.width == width_ &&
         setup.height == frame.height();
}

bool SmoothSplats::begin(const FrameSetup& setup, const FrameView& frame) {
  if (!fits(setup, frame)) return false;
  // Magnified: a voxel's edge longer than a pixel. A turned voxel of depth auto (edge at most a
  // pixel, footprint up to 2 x 2) is drawn as the box frame draws it: its kernel would be under
  // a pixel wide, and blending it cost 4 to 8 times the box frame (docs/splats.md).
  // A level whose samples lie farther apart than its voxels (setup.sample_reach, Q4) is blended
  // where the samples' spacing is over a pixel.
  blended_ = smoothReachOf(setup).blends;
  blends_normals_ = blended_ && frame.payload() == PixelPayload::kColourNormal;
  blended_rect_ = blended_ ? frame.drawnRect() : PixelRect{};
  if (blended_rect_.empty()) return true;
  const auto width = static_cast<std::size_t>(width_);
  for (std::int32_t y = blended_rect_.y_begin; y < blended_rect_.y_end; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    const auto begin = static_cast<std::ptrdiff_t>(row) + blended_rect_.x_begin;
    const auto end = static_cast<std::ptrdiff_t>(row) + blended_rect_.x_end;
    std::fill(sums_.begin() + begin, sums_.begin() + end, Sums{0, 0, 0, 0});
    if (blends_normals_) {
      std::fill(normal_sums_.begin() + begin, normal_sums_.begin() + end, DirectionQ14{});
    }
  }
  return true;
}

bool SmoothSplats::accumulate(const LevelView& level, const FrameSetup& setup,
                              const FrameView& frame, const PaletteRgb& palette,
                              const std::atomic<bool>* abort) {
  if (!fits(setup, frame) || checkRender(level, setup, frame) != RenderError::kNone) return false;
  if (!blended_ || blended_rect_.empty()) return true;  // nothing to blend
  NormalBlend normals;
  if (blends_normals_) {
    normals.leaf_normals = level.normals.data();  // one per leaf: checkRender
    turnNormalsToViewer(
        normal_palette_, normal_count_,
        rotationFromYawPitchRoll(setup.camera.yaw, setup.camera.pitch, setup.camera.roll),
        normals.turned);
    normals.sums = normal_sums_.data();
  }
  return BlendWalk(level, setup, frame, sums_.data(), palette, column_weight_.data(),
                   row_weight_.data(), normals, abort)
      .run();
}

bool SmoothSplats::finish(FrameView& frame) {
  if (width_ == 0 || frame.width() != width_ || frame.height() > height_) return false;
  if (!blended_ || blended_rect_.empty()) return true;
  // Covered pixels lie in the rectangle the box frame drew: the rest is kEmpty.
  const PixelRect& rect = blended_rect_;
  const auto width = static_cast<std::size_t>(width_);
  std::uint32_t* const words = frame.pixelsToDraw(rect);
  const bool avx2 = simdDecoderAvailable();
  for (std::int32_t y = rect.y_begin; y < rect.y_end; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    if (!blends_normals_) {
      const std::size_t at = row + static_cast<std::size_t>(rect.x_begin);
      normaliseRun(words + at, sums_.data() + at,
                   static_cast<std::size_t>(rect.x_end - rect.x_begin), kCoverWeight, avx2);
      continue;
    }
    for (std::int32_t x = rect.x_begin; x < rect.x_end; ++x) {
      std::uint32_t& word = words[row + static_cast<std::size_t>(x)];
      if (word == FrameView::kEmpty) continue;
      Sums& sum = sums_[row + static_cast<std::size_t>(x)];
      if (sum.weight < kCoverWeight) {
        word = FrameView::kEmpty;
        continue;
      }
      sum.r = blendedColour(sum);
      DirectionQ14& n = normal_sums_[row + static_cast<std::size_t>(x)];
      n = unitDirection(n.x, n.y, n.z);
    }
  }
  return true;
}

PixelBlend SmoothSplats::pixelBlend() const {
  if (!blended_ || blended_rect_.empty()) return {};
  static_assert(sizeof(Sums) == 4 * sizeof(std::uint32_t));
  return {&sums_.front().r, sizeof(Sums) / sizeof(std::uint32_t),
          blends_normals_ ? normal_sums_.data() : nullptr};
}

bool SmoothSplats::blend(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                         const PaletteRgb& palette, const std::atomic<bool>* abort) {
  if (!fits(setup, frame) || checkRender(level, setup, frame) != RenderError::kNone) return false;
  return begin(setup, frame) && accumulate(level, setup, frame, palette, abort) && finish(frame);
}

}  // namespace octopoint
