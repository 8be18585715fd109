#pragma once
// fixed_simd's emit stage (renderer/render_fixed_simd.cpp, x86-64 with AVX2 only): a leaf parent
// whose children all land on screen computes its eight children's pixel indices and packed words
// at once in 32-bit lanes and appends its set children's entries to a batch, with permutations
// and stores of fixed width instead of a loop over the children.
//
// Footprint splats (octopoint/camera.h) take one of two forms here:
// - Small footprints (at most kMostBoxPixels pixels, measured best up to 2 x 2): each pixel of a
//   child's splat becomes a single-pixel entry, plotted like one pixel per leaf. A child covers
//   the footprint's box or one column or row fewer (floor or ceil of its padded extent), so per
//   pixel of the box the children that have it are kept by the same per-mask permutation: the
//   batch holds exactly the splat's pixels, with no branch on which child has which.
// - Larger ones: one entry per child with its splat's first pixel and its columns and rows,
//   written as rectangles (renderer/splat_batch.h).
#include <immintrin.h>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "octopoint/framebuffer.h"
#include "renderer/leaf_cursor.h"

namespace octopoint::simd {

// kKeep[mask]: the lanes of the set bits of `mask`, in order, then zeros: the vpermd control that
// moves a leaf parent's set children to the front.
struct LaneOrder {
  std::uint8_t lane[8];
};
constexpr std::array<LaneOrder, 256> makeKeepTable() {
  std::array<LaneOrder, 256> table{};
  for (unsigned mask = 0; mask < 256; ++mask) {
    unsigned kept = 0;
    for (std::uint8_t child = 0; child < 8; ++child) {
      if (mask >> child & 1u) table[mask].lane[kept++] = child;
    }
  }
  return table;
}
inline constexpr std::array<LaneOrder, 256> kKeep = makeKeepTable();

// kSpread[mask]: for each child lane, its place among the set children of `mask` (0 for the
// others): the vpermd control that moves a leaf parent's colours, read in stream order, back to
// their children's lanes.
constexpr std::array<LaneOrder, 256> makeSpreadTable() {
  std::array<LaneOrder, 256> table{};
  for (unsigned mask = 0; mask < 256; ++mask) {
    std::uint8_t place = 0;
    for (unsigned child = 0; child < 8; ++child) {
      if (mask >> child & 1u) table[mask].lane[child] = place++;
    }
  }
  return table;
}
inline constexpr std::array<LaneOrder, 256> kSpread = makeSpreadTable();

// What the unchecked walk appends per leaf: its one pixel; or, for a footprint of at most
// kMostBoxPixels pixels, each pixel of its splat as an entry of its own, plotted as single pixels;
// or, for larger footprints, its splat's rectangle (first pixel, columns and rows).
enum class Emit { kPixel, kSplatPixels, kSplatRects };
inline constexpr int kMostBoxPixels = 4;
// The walk's template parameter: how leaves are emitted, and for kSplatPixels the box when it is
// one of the common small ones, unrolled at compile time (0 x 0: the frame's SplatBox).
struct EmitMode {
  Emit emit;
  int box_columns = 0;
  int box_rows = 0;
  // A box known at compile time whose last row few children reach (SplatFootprint::span_y small:
  // the footprint's extent just over a whole number of rows): a leaf parent none of whose
  // children reaches it skips that row's entries, a branch taken rarely, instead of keeping no
  // lane of them.
  bool rare_last_row = false;
};

// Emit::kSplatPixels: the frame's box, each pixel as its offset from the first (row * width +
// column) and whether it is in the box's last column (bit 0) or last row (bit 1).
struct SplatBox {
  int pixels = 0;
  std::uint32_t offset[kMostBoxPixels] = {};
  std::uint8_t edge[kMostBoxPixels] = {};
  std::uint8_t column[kMostBoxPixels] = {};  // each pixel's column and row in the box
  std::uint8_t row[kMostBoxPixels] = {};
};

// Emit::kSplatPixels on the frame's edge: per column (row) of the box, one bit per child lane,
// whether that column (row) of the child's splat is on screen.
struct BoxOnScreen {
  unsigned column_drawn[kMostBoxPixels];
  unsigned row_drawn[kMostBoxPixels];
};

// Where the unchecked walk appends: the batch's arrays, how many entries they hold, and the next
// leaf's payload (its colour, and its normal where the frame carries normals:
// renderer/leaf_cursor.h). Locals of the caller, kept in registers: a store to the batch may
// alias any 32-bit field of SimdFrame. One count for all arrays, so that a leaf parent's stores
// share one index register and advance it with one add.
template <typename Leaves>
struct Emitter {
  std::uint32_t* index;
  std::uint32_t* word;
  Leaves leaves;
  std::uint32_t* extent;  // the splat path only
  std::size_t count;

  // Stores eight lanes of each array at the end (the batch has room past its last entry) and
  // keeps the first `kept` of them.
  __attribute__((target("avx2"), always_inline)) void append(__m256i index_lanes,
                                                             __m256i word_lanes, unsigned kept) {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(index + count), index_lanes);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(word + count), word_lanes);
    count += kept;
  }
};

// Eight leaves' payloads, one per lane, from the cursor (which is not advanced): the palette index,
// and for kColourNormal the normal index << 8 (Framebuffer::packLeaf).
__attribute__((target("avx2"), always_inline)) inline __m256i payloadLanes(
    const ColourLeaves& leaves) {
  return _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(leaves.colour)));
}
__attribute__((target("avx2"), always_inline)) inline __m256i payloadLanes(
    const ColourNormalLeaves& leaves) {
  const __m256i colour =
      _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(leaves.colour)));
  const __m256i normal =
      _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(leaves.normal)));
  return _mm256_or_si256(colour, _mm256_slli_epi32(normal, 8));
}

// Depth keys moved above a leaf's payload (Framebuffer::packLeaf): << 8, and for kColourNormal
// only the key's top 16 bits.
template <PixelPayload kPayload>
__attribute__((target("avx2"), always_inline)) inline __m256i keyBits(__m256i key) {
  const __m256i shifted = _mm256_slli_epi32(key, 8);
  if constexpr (kPayload == PixelPayload::kColourNormal) {
    return _mm256_and_si256(
        shifted, _mm256_set1_epi32(static_cast<std::int32_t>(FrameView::kColourNormalKeyMask)));
  }
  return shifted;
}

// The frame's formats as vectors, loaded into registers once per call.
struct LeafLanes {
  __m256i width;
  __m128i fraction_bits, depth_shift;
  __m256i span_x, span_y;  // the splat path only: SplatFootprint::span_x, span_y
  // Emit::kSplatPixels only: the box's columns and rows less one, the frame's width, its box.
  __m256i columns_less_one, rows_less_one;
  std::uint32_t row_pixels;
  const SplatBox* box;
};

// The vpermd control of `table` for `mask`.
__attribute__((target("avx2"), always_inline)) inline __m256i laneControl(
    const std::array<LaneOrder, 256>& table, unsigned mask) {
  return _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&table[mask])));
}

// One bit per lane: whether the lane is all ones (a comparison's result).
__attribute__((target("avx2"), always_inline)) inline unsigned lowBits(__m256i lanes) {
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(lanes)));
}

// Emit::kSplatPixels: a leaf parent's children in child lanes, with their splats' first pixels and
// words, and which of them have one column (row) fewer than the footprint's box.
struct BoxChildren {
  __m256i first;
  __m256i word;
  unsigned mask;
  unsigned short_columns;
  unsigned short_rows;
};

// Appends the pixel `offset` (row * width + column) from each child's first pixel, for the children
// whose rectangle has it: all set children, less those one column short when the pixel is in the
// box's last column, less those one row short when it is in its last row. Kept lanes move to the
// front as in emitChildren: no branch on which children have it.
template <typename Out>
__attribute__((target("avx2"), always_inline)) inline void emitBoxPixel(const BoxChildren& box,
                                                                        std::uint32_t offset,
                                                                        bool last_column,
                                                                        bool last_row, Out& out) {
  const unsigned mask =
      box.mask & ~(last_column ? box.short_columns : 0u) & ~(last_row ? box.short_rows : 0u);
  const __m256i keep = laneControl(kKeep, mask);
  const __m256i at =
      _mm256_add_epi32(box.first, _mm256_set1_epi32(static_cast<std::int32_t>(offset)));
  out.append(_mm256_permutevar8x32_epi32(at, keep), _mm256_permutevar8x32_epi32(box.word, keep),
             static_cast<unsigned>(std::popcount(mask)));
}

// The same for a box known at compile time, unrolled (kRareLastRow: EmitMode::rare_last_row).
template <int kColumns, int kRows, bool kRareLastRow, typename Out>
__attribute__((target("avx2"), always_inline)) inline void emitBox(const LeafLanes& lanes,
                                                                   const BoxChildren& box,
                                                                   Out& out) {
  for (int r = 0; r < kRows; ++r) {
    if (kRareLastRow && r + 1 == kRows && (box.mask & ~box.short_rows) == 0) return;
    for (int c = 0; c < kColumns; ++c) {
      emitBoxPixel(box,
                   static_cast<std::uint32_t>(r) * lanes.row_pixels + static_cast<std::uint32_t>(c),
                   kColumns > 1 && c + 1 == kColumns, kRows > 1 && r + 1 == kRows, out);
    }
  }
}

// emitChildrenOf's footprint pixels (kSplatPixels): each pixel of the box of each child drawn, as
// an entry; `column`, `row` and `key` are the children's first pixel and depth key, `colour` their
// payloads in stream order.
template <EmitMode kEmit, bool kSubset, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline void emitSplatPixels(
    const LeafLanes& lanes, __m256i x, __m256i y, __m256i column, __m256i row, __m256i index,
    __m256i key, __m256i colour, unsigned mask, unsigned drawn, Emitter<Leaves>& out,
    const BoxOnScreen* edge) {
  // A child has one column fewer than the box when first + columns - 1 > its last column,
  // (x + span) >> F (SplatFootprint); the same for rows. As bits, one per child lane.
  const __m256i last_column =
      _mm256_sra_epi32(_mm256_add_epi32(x, lanes.span_x), lanes.fraction_bits);
  const __m256i last_row = _mm256_sra_epi32(_mm256_add_epi32(y, lanes.span_y), lanes.fraction_bits);
  const BoxChildren box{
      index,
      _mm256_or_si256(keyBits<Leaves::kPayload>(key),
                      _mm256_permutevar8x32_epi32(colour, laneControl(kSpread, mask))),
      drawn,
      lowBits(_mm256_cmpgt_epi32(_mm256_add_epi32(column, lanes.columns_less_one), last_column)),
      lowBits(_mm256_cmpgt_epi32(_mm256_add_epi32(row, lanes.rows_less_one), last_row))};
  if constexpr (kSubset && kEmit.box_columns != 0) {
    for (int r = 0; r < kEmit.box_rows; ++r) {
      for (int c = 0; c < kEmit.box_columns; ++c) {
        BoxChildren on_screen = box;
        on_screen.mask &= edge->column_drawn[c] & edge->row_drawn[r];
        emitBoxPixel(
            on_screen,
            static_cast<std::uint32_t>(r) * lanes.row_pixels + static_cast<std::uint32_t>(c),
            kEmit.box_columns > 1 && c + 1 == kEmit.box_columns,
            kEmit.box_rows > 1 && r + 1 == kEmit.box_rows, out);
      }
    }
  } else if constexpr (kSubset) {
    const SplatBox& frame_box = *lanes.box;
    for (int p = 0; p < frame_box.pixels; ++p) {
      BoxChildren on_screen = box;
      on_screen.mask &= edge->column_drawn[frame_box.column[p]] & edge->row_drawn[frame_box.row[p]];
      emitBoxPixel(on_screen, frame_box.offset[p], (frame_box.edge[p] & 1) != 0,
                   (frame_box.edge[p] & 2) != 0, out);
    }
  } else if constexpr (kEmit.box_columns != 0) {
    emitBox<kEmit.box_columns, kEmit.box_rows, kEmit.rare_last_row>(lanes, box, out);
  } else {
    const SplatBox& frame_box = *lanes.box;
    for (int p = 0; p < frame_box.pixels; ++p) {
      emitBoxPixel(box, frame_box.offset[p], (frame_box.edge[p] & 1) != 0,
                   (frame_box.edge[p] & 2) != 0, out);
    }
  }
}

// A leaf parent whose children all land on screen, given its eight children's positions per axis
// (x, y in Q(32-F).F, plus the splat's offsets when kSplat; z in Q(32-F).F plus the depth bias),
// appends its set children (`mask`) to the batch, their payloads being the next popcount(mask) of
// out.leaves. Splats (kEmit, octopoint/camera.h): x and y include the footprint's
// offsets, so the index is the splat's first pixel; each point's columns and rows go to
// out.extent (kSplatRects), or each pixel of the footprint's box becomes an entry (kSplatPixels).
// kSubset (a leaf parent on the frame's edge): only the children `drawn` (a subset of `mask`) are
// appended, and for kSplatPixels each pixel of the box in column c and row r only for the children
// that have it on screen (edge->column_drawn[c] & edge->row_drawn[r]); the leaf cursor still passes
// all of `mask`'s. Otherwise `drawn` is `mask`.
template <EmitMode kEmit, bool kSubset, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline void emitChildrenOf(
    const LeafLanes& lanes, __m256i x, __m256i y, __m256i biased_z, unsigned mask, unsigned drawn,
    Emitter<Leaves>& out, const BoxOnScreen* edge = nullptr) {
  // Pixel column and row: floor(x / 2^F); index = row * width + column (< 2^26).
  const __m256i column = _mm256_sra_epi32(x, lanes.fraction_bits);
  const __m256i row = _mm256_sra_epi32(y, lanes.fraction_bits);
  const __m256i index = _mm256_add_epi32(_mm256_mullo_epi32(row, lanes.width), column);
  // Depth key (FrameSetup::depthKey): (z + bias) >> shift, unsigned, mod 2^32.
  const __m256i key = _mm256_srl_epi32(biased_z, lanes.depth_shift);
  const __m256i keep = laneControl(kKeep, drawn);
  const __m256i colour = payloadLanes(out.leaves);
  // The payloads are in stream order: all of them kept, they match the kept keys; a subset moves
  // them to their children's lanes first (kSpread), then keeps those drawn.
  const __m256i word =
      kSubset
          ? _mm256_permutevar8x32_epi32(
                _mm256_or_si256(keyBits<Leaves::kPayload>(key),
                                _mm256_permutevar8x32_epi32(colour, laneControl(kSpread, mask))),
                keep)
          : _mm256_or_si256(keyBits<Leaves::kPayload>(_mm256_permutevar8x32_epi32(key, keep)),
                            colour);
  const int children = std::popcount(mask);
  out.leaves.skip(static_cast<std::size_t>(children));
  if constexpr (kEmit.emit == Emit::kSplatPixels) {
    emitSplatPixels<kEmit, kSubset>(lanes, x, y, column, row, index, key, colour, mask, drawn, out,
                                    edge);
    return;
  }
  if constexpr (kEmit.emit == Emit::kSplatRects) {
    // Last column and row (SplatFootprint): (x + span) >> F; count = last - first + 1 (< 2^16).
    const __m256i columns = _mm256_sub_epi32(
        _mm256_sra_epi32(_mm256_add_epi32(x, lanes.span_x), lanes.fraction_bits), column);
    const __m256i rows = _mm256_sub_epi32(
        _mm256_sra_epi32(_mm256_add_epi32(y, lanes.span_y), lanes.fraction_bits), row);
    const __m256i one = _mm256_set1_epi32(1);
    const __m256i extent = _mm256_or_si256(_mm256_add_epi32(columns, one),
                                           _mm256_slli_epi32(_mm256_add_epi32(rows, one), 16));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.extent + out.count),
                        _mm256_permutevar8x32_epi32(extent, keep));
  }
  out.append(_mm256_permutevar8x32_epi32(index, keep), word,
             static_cast<unsigned>(std::popcount(drawn)));
}

// All the set children of `mask`: emitChildrenOf with `drawn` = `mask`.
template <EmitMode kEmit, typename Leaves>
__attribute__((target("avx2"), always_inline)) inline void emitChildren(const LeafLanes& lanes,
                                                                        __m256i x, __m256i y,
                                                                        __m256i biased_z,
                                                                        unsigned mask,
                                                                        Emitter<Leaves>& out) {
  emitChildrenOf<kEmit, false>(lanes, x, y, biased_z, mask, mask, out);
}

}  // namespace octopoint::simd
