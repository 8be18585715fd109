#pragma once
// octopoint/camera.h: The orthographic camera, its per-level vectors, and the footprint of a voxel
// on screen. The manual of the whole library is octopoint/octopoint.h.

#include <array>
#include <cstdint>
#include <optional>

#include "octopoint/fixed.h"
#include "octopoint/model.h"

// The footprint splat of one frame: which pixels a leaf covers when a voxel of the drawn depth
// projects to more than one pixel (docs/splats.md).
//
// Orthographic projection maps every leaf cube of a level to the same shape, so its screen extent
// per axis is the same for all leaves of the frame: W_a = e * (|R[a][0]| + |R[a][1]| + |R[a][2]|)
// pixels for a voxel edge of e pixels and the rotation R. FrameSetup holds the child offsets of
// the last level, +-e/2 along each rotated axis, so W_a = 2 * max_k |child_offset[depth-1][k].a|
// (Q(32-F).F, rounded once, within one unit in the last place).
//
// - W_x and W_y both at most one pixel (2^F): no splat. A leaf sets the one pixel p >> F, exactly
//   as the decoders always did, and that is hole-free: a pixel centre c inside the projected cube
//   of a leaf at p has |c - p| < W/2 <= 1/2 per axis, so p lies in c's pixel.
// - Otherwise, per axis with W_a > 1 pixel: the extent is padded by `depth + 1` units on each
//   side (a leaf position is within depth/2 units of exact, W within one), P_a = W_a + 2(depth+1),
//   and the leaf covers the pixels whose centre lies in (p - P_a/2, p + P_a/2]: from
//   floor(p + 1/2 - P_a/2) to floor(p - 1/2 + P_a/2), that is from (p + offset) >> F to
//   (p + offset + span) >> F with offset = 2^(F-1) - P_a/2 and span = P_a - 2^F. That is
//   floor(P_a) or ceil(P_a) pixels, never more than `columns` = ceil(P_x) (`rows` = ceil(P_y)).
//   An axis with W_a <= 1 keeps offset 0, span 0: the one pixel p >> F, as above.
// The splat thus covers every pixel centre inside the projection of the leaf's cube (within the
// leaf's axis-aligned bounding box, padded by the rounding): a surface sampled densely enough to
// leave no empty voxel along it draws with no hole inside its silhouette. The padding is a few
// units of 2^-F pixel, so an exactly 4-pixel voxel still covers 4 pixels, not 5.
// Everything is integer; the set-up computes it once per frame (buildFrameSetup).

namespace octopoint {

struct SplatFootprint {
  std::int32_t columns = 1;  // the most pixels a leaf covers along x
  std::int32_t rows = 1;     // the most pixels a leaf covers along y
  // Q(32-F).F: a leaf at p covers the columns (p.x + offset_x) >> F .. (p.x + offset_x + span_x) >>
  // F and the rows (p.y + offset_y) >> F .. (p.y + offset_y + span_y) >> F.
  std::int32_t offset_x = 0;
  std::int32_t offset_y = 0;
  std::int32_t span_x = 0;
  std::int32_t span_y = 0;
  // The projected voxel extent W per axis, Q(32-F).F, unpadded (what depth by projected size uses).
  std::int32_t extent_x = 0;
  std::int32_t extent_y = 0;

  // Whether leaves cover more than their one pixel (the decoders' splat path).
  bool active() const { return columns > 1 || rows > 1; }
};

// The footprint for a last level whose largest child offsets per axis are `half_x`, `half_y`
// (Q(32-F).F, >= 0), drawn at `depth` with `fraction_bits` F. Offsets and sizes fit 32 bits when
// buildFrameSetup accepted the camera (it checks the splat's reach too).
SplatFootprint splatFootprint(std::int64_t half_x, std::int64_t half_y, int depth,
                              int fraction_bits);

}  // namespace octopoint

// The camera and the per-frame displacement vectors of the recursive decoder (docs/design.md
// section 3).
//
// Frames: the model cube is centred on the origin in the scan's own camera frame (x right, y
// down, z away from the viewer, as PCL and OpenCV use it), so the identity camera shows a range
// scan as its sensor saw it. Projection is orthographic: screen x, y are the rotated, scaled
// coordinates plus the screen centre and the pan; z goes to the z-buffer (smaller is nearer).
// At zoom 1 the cube's edge spans the shorter side of the framebuffer.
//
// A child k = (x << 2) | (y << 1) | z of a node at tree level l (the root is level 0) sits half a
// child edge from its parent's centre on each axis, that is +-2^(depth - l - 2) voxels, or
// +-zoom * min(width, height) / 2^(l + 2) pixels. The camera turns these into rotated screen
// vectors once per frame; the decoder then only adds. Every vector is rounded to nearest once, so
// a leaf (depth additions) is within depth / 2 units in the last place of the exact position.

namespace octopoint {

inline constexpr int kDefaultFractionBits = 15;  // Q17.15 positions (docs/design.md section 3)
inline constexpr int kMinFractionBits = 1;
inline constexpr int kMaxFractionBits = 24;  // leaves 7 integer bits: 64 pixels of room
inline constexpr int kMaxViewportSide = 8192;

// The deepest level a frame set-up can draw: the format's limit, unless a build says less. Each
// level costs a FrameSetup 96 bytes (eight vectors); a microcontroller build sets
// OCTOPOINT_MAX_RENDER_DEPTH=10 (targets/cortex-m/, docs/device.md), which saves 576 bytes of RAM
// per set-up and refuses deeper levels with kBadDepth.
#ifndef OCTOPOINT_MAX_RENDER_DEPTH
#define OCTOPOINT_MAX_RENDER_DEPTH 16
#endif
inline constexpr int kMaxRenderDepth = OCTOPOINT_MAX_RENDER_DEPTH;
static_assert(kMaxRenderDepth >= 1 && kMaxRenderDepth <= format::kMaxDepth);

struct Camera {
  Angle yaw;
  Angle pitch;
  Angle roll;
  Q16 zoom = Q16::fromRaw(Q16::kOneRaw);  // Q16.16, must be > 0
  std::int32_t pan_x_px = 0;              // moves the image right
  std::int32_t pan_y_px = 0;              // moves the image down
  std::int32_t width = 320;
  std::int32_t height = 240;
};

enum class CameraError : std::uint8_t {
  kNone,
  kBadViewport,      // width or height outside 1..kMaxViewportSide
  kBadZoom,          // zoom <= 0
  kBadFractionBits,  // outside kMinFractionBits..kMaxFractionBits
  kBadDepth,         // outside 1..kMaxRenderDepth (format::kMaxDepth unless a build says less)
  kOverflow,         // some leaf coordinate would not fit 32 bits: zoom or pan too large
  kBadSampleReach,   // a sample reach outside kOneSampleReach..kMaxSampleReach
};

// Samples coarser than the voxel (docs/splats.md, "Samples coarser than the voxel"): a level whose
// samples lie farther apart than its voxels draws each leaf's splat this many sixteenths (Q4) of
// its voxel's footprint wide (sampleReach, renderer/sample_reach.h, says how many). One footprint,
// kOneSampleReach, is the frame every level drew before; at most kMaxSampleReach (8 footprints).
inline constexpr std::int32_t kOneSampleReach = format::kOneSampleReachQ4;  // 16
inline constexpr std::int32_t kMaxSampleReach = format::kMaxSampleReachQ4;  // 128

const char* describe(CameraError error);

template <typename T>
struct Point3 {
  T x, y, z;
  friend bool operator==(const Point3&, const Point3&) = default;
};
using Vec3 = Point3<std::int32_t>;

// Everything a decoder needs for one frame at one depth. Positions are in screen pixels with
// `fraction_bits` fraction bits (Q(32-F).F): a leaf at position p lands on pixel p >> F.
struct FrameSetup {
  Camera camera;  // what it was built from (the floating point reference variants rebuild from it)
  int depth = 0;
  int fraction_bits = kDefaultFractionBits;
  std::int32_t width = 0;
  std::int32_t height = 0;
  Vec3 root{};  // screen position of the cube centre
  // child_offset[l][k]: from a node at tree level l to the centre of its child k.
  std::array<std::array<Vec3, 8>, kMaxRenderDepth> child_offset{};
  // The z-buffer keeps 24 bits of depth per pixel (Framebuffer): a leaf's depth key is
  // (z + depth_bias) >> depth_shift, unsigned. Every leaf has |z| <= depth_bias, so the sum lies in
  // [0, 2 * depth_bias]; depth_shift is the least that brings that range under 2^24 - 1. One key
  // step is 2^(depth_shift - F) pixels of depth: at zoom 1 and F = 15, depth_shift is 0 or 1.
  std::uint32_t depth_bias = 0;
  int depth_shift = 0;
  // What a leaf covers (octopoint/camera.h): one pixel while a voxel of this depth projects
  // to at most one pixel per axis, else a columns x rows splat. fixed_fast and fixed_simd draw it;
  // the paper's variants (fixed_baseline .. fixed_clipped, float_*) always set one pixel per leaf.
  // A caller may reset it to SplatFootprint{} to draw one pixel per leaf with any variant.
  SplatFootprint splat;
  // The sample reach the splat was widened by (Q4, kOneSampleReach: not widened); the smooth
  // splats' kernel radius follows it too.
  std::int32_t sample_reach = kOneSampleReach;

  std::uint32_t depthKey(std::int32_t z) const {
    return (static_cast<std::uint32_t>(z) + depth_bias) >> depth_shift;  // mod 2^32: no overflow
  }
};

// The edge of one voxel of the set-up's depth on screen, in Q(32-F).F pixels: the length of the
// rotated displacement between a leaf parent's children 0 and 4 (one voxel along the model's x
// axis; the length does not depend on the rotation), an exact integer square root.
std::uint64_t voxelEdgeOnScreen(const FrameSetup& setup);

// Builds the frame set-up, or refuses the camera (returns the reason) when a coordinate could
// overflow: the worst case |root| + sum over levels of the largest child offset is checked per
// axis, so the decoder's additions can never wrap, nor the splat's pixel range (its reach is
// included in the check).
// `sample_reach` (Q4, kOneSampleReach..kMaxSampleReach) widens the splat: its half extents are
// sample_reach / 16 times the voxel's, rounded up, before the footprint is made of them (so a
// level of voxels under a pixel whose samples lie farther apart than a pixel gets a splat too).
[[nodiscard]] CameraError buildFrameSetup(const Camera& camera, int depth, int fraction_bits,
                                          FrameSetup* setup,
                                          std::int32_t sample_reach = kOneSampleReach);

// The footprint a leaf of `depth` has for `camera` (FrameSetup::splat of buildFrameSetup, computed
// from the last level's offsets alone: cheap enough to ask for every stored depth), or nullopt
// when the camera is refused outright (bad size, zoom, depth or fraction bits, an offset over 32
// bits). buildFrameSetup may still refuse a camera this accepts, for the sum of all levels.
[[nodiscard]] std::optional<SplatFootprint> leafFootprint(const Camera& camera, int depth,
                                                          int fraction_bits);

}  // namespace octopoint
