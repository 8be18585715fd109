#pragma once
// How fixed_simd writes a batch of footprint splats (octopoint/camera.h): each point is its
// splat's first pixel, its packed word, and its column and row counts; every pixel of its
// rectangle keeps the min of its word and the point's (the z-test of a single pixel), so the frame
// does not depend on the order points are written in. The walk proved every rectangle lies on
// the frame (the clip's reach includes the splat).
//
// A frame's footprint is at most `columns` x `rows` pixels (SplatFootprint); a point covers that
// many or one fewer per axis (floor or ceil of the padded extent). One kernel per frame, chosen by
// the footprint, writes the batch:
// - Up to 2 columns and 4 rows: the whole columns x rows box, unrolled, one scalar min per pixel;
//   the pixels of the box outside a point's own rectangle (its last column or row when it has one
//   fewer) get the min with kEmpty, which leaves them as they are. Points are taken from the
//   batch's two halves in turn, two independent chains of stores and loads (neighbours often share
//   pixels). (fixed_simd plots footprints of up to 4 pixels as single-pixel entries instead: a
//   64-bit min per row of a 2 x 2 box was about 1.5x slower than those, bench/splat_bench.)
// - 3 or 4 columns, up to 4 rows: one four-pixel vector min per row of the box, the lanes past the
//   point's rectangle kEmpty, the two halves in turn. The rectangles of neighbouring points
//   overlap, and a wide store followed by a load of an overlapping but different range cannot be
//   forwarded; measured, that still costs less than four scalar mins per row (docs/splats.md,
//   "Small footprints").
// - Up to 8 columns (or taller than 4 rows): one eight-pixel vector min per row, same masking.
// - Wider: eight pixels of a row per vector min, the row's last partial chunk with the columns
//   past the rectangle set to kEmpty (not stored back blended, no masked store).
// A box or chunk that would reach past the frame's last pixel is written pixel by pixel, exactly.

#include <cstddef>
#include <cstdint>

namespace octopoint {

struct SplatBatch {
  std::uint32_t* pixel;         // the frame's words, row-major
  std::size_t width;            // words per row
  std::size_t end;              // width * height: nothing is written at or past it
  const std::uint32_t* index;   // each point's first pixel, row * width + column
  const std::uint32_t* word;    // its packed word (Framebuffer::pack)
  const std::uint32_t* extent;  // its columns (low 16 bits) and rows (high 16 bits), >= 1 each
  int count;
};

using SplatBatchPlot = void (*)(const SplatBatch& batch);

// The kernel for frames whose footprint is at most `columns` x `rows` (both >= 1). x86-64 with
// AVX2 only (fixed_simd calls it).
SplatBatchPlot splatBatchPlot(std::int32_t columns, std::int32_t rows);

}  // namespace octopoint
