#pragma once
// Depth by projected size (`--depth auto`, docs/splats.md): which of a model's stored depths to
// draw for a camera (its framebuffer size, zoom and rotation), so that a frame's cost follows the
// pixels it covers rather than the model.
//
// The rule, exactly: let e(d) = zoom * min(width, height) / 2^d be the edge of a voxel of depth d
// in pixels (at zoom 1 the cube's edge spans the framebuffer's shorter side; orthographic, so the
// edge does not depend on the rotation). Depth auto draws the COARSEST stored depth with
// e(d) <= 1 pixel, tested exactly in integers as zoom_raw * min(width, height) <= 2^(16 + d) (the
// zoom in Q16.16). No coarser depth has voxels as small as a pixel, and one finer would put about
// four leaves of a surface on each pixel. With consecutive stored depths e halves per depth, so
// the drawn edge lies in (1/2, 1] pixel: voxels not much smaller than a pixel. Turned, a voxel's
// projected footprint (FrameSetup::splat.extent_x/extent_y: e times the largest row sum
// |r_0| + |r_1| + |r_2| of the rotation's first two rows, up to sqrt(3) e) may exceed a pixel;
// the decoders then draw it as a footprint splat (at most 2 pixels per axis at the drawn depth),
// hole-free at a quarter of the leaves of the next finer depth. When even the finest stored depth
// has e > 1 pixel, the finest is drawn with footprint splats; when even the coarsest has
// e <= 1/2 pixel, the coarsest is drawn. Depths at which the camera is refused (coordinates over
// 32 bits) are passed over. Integer only.
//
// Only depths the scan samples densely are candidates (denseDepthCount): a model prepared with an
// explicit --depths list may store depths finer than its scan's point spacing, and drawn, such a
// depth shows that spacing as speckle (one-pixel voxels over the background) for more cost than
// the densely sampled depth drawn with splats. autoLevel and the progressive model cut there.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "octopoint/camera.h"
#include "octopoint/model.h"

namespace octopoint {

// A surface sampled densely fills about four times as many voxels at each finer depth (eight for
// a volume); a depth with fewer than kDenseGrowth times its coarser neighbour's voxels is finer
// than the scan's point spacing. The preparer's rule (octopoint-prepare keeps no such depth unless
// told to) and the renderer's are this one.
inline constexpr std::uint64_t kDenseGrowth = 3;

// The rule for one depth: `finer` voxels against its coarser neighbour's `coarser` (each below
// 2^62, so the product does not overflow).
constexpr bool sampledDensely(std::uint64_t finer, std::uint64_t coarser) {
  return finer >= kDenseGrowth * coarser;
}

// For the voxel counts of ascending stored depths, how many leading depths are densely sampled: up
// to (excluding) the first whose count is below kDenseGrowth times the previous one's; at least one
// when there is any. With `sample_reaches` (Q4 footprints, one per depth, as format version 6 and
// chunked version 7 store them): a depth whose samples lie farther apart than its voxels but whose
// stored reach (more than one footprint) draws it whole counts as well.
std::size_t denseDepthCount(std::span<const std::uint64_t> voxels_per_depth,
                            std::span<const std::int32_t> sample_reaches = {});

// The depth to draw among `stored_depths` (strictly ascending, each 1..format::kMaxDepth) for
// `camera`, by the rule above; nullopt when the camera is refused at every one of them.
std::optional<int> autoDepth(std::span<const int> stored_depths, const Camera& camera);

// The depth a model would need for this camera if it stored every depth 1..format::kMaxDepth:
// the coarsest whose voxel edge is at most one pixel (what a preparer should store as the
// finest depth). nullopt when the camera is refused at every depth.
std::optional<int> neededDepth(const Camera& camera);

// The level of `model` that autoDepth picks among its densely sampled depths, and the sparser
// ones whose stored sample reach (more than one footprint, format version 6) draws them whole:
// the leading depths each either kDenseGrowth times its coarser neighbour's voxels or so reached.
// nullptr when the camera is refused at every depth.
const LevelView* autoLevel(const ModelView& model, const Camera& camera);

}  // namespace octopoint
