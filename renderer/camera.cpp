#include "octopoint/camera.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <optional>

#include "octopoint/fixed.h"
#include "octopoint/framebuffer.h"
#include "renderer/integer_square_root.h"

namespace octopoint {

const char* describe(CameraError error) {
  switch (error) {
    case CameraError::kNone:
      return "no error";
    case CameraError::kBadViewport:
      return "framebuffer size outside 1..8192";
    case CameraError::kBadZoom:
      return "zoom must be greater than 0";
    case CameraError::kBadFractionBits:
      return "fraction bits outside the supported range";
    case CameraError::kBadDepth:
      return "depth outside the supported range";
    case CameraError::kOverflow:
      return "zoom or pan too large: coordinates would overflow 32 bits";
    case CameraError::kBadSampleReach:
      return "sample reach outside 16..128 sixteenths of a voxel";
  }
  return "unknown error";
}

namespace {

// Pixels per cube edge: zoom (Q16.16) * min(width, height), exact in Q16 (< 2^31 * 2^13).
std::int64_t edgePixelsQ16(const Camera& camera) {
  return static_cast<std::int64_t>(camera.zoom.raw()) * std::min(camera.width, camera.height);
}

// Component `axis` of the offset from a level-`level` node to its child k, Q(32-F).F, or nullopt
// when it does not fit 64 bits.
std::optional<std::int64_t> childOffset(const Rotation& rotation, std::int64_t edge_px_q16,
                                        int level, int k, int axis, int fraction_bits) {
  const int sign[3] = {(k & 4) ? 1 : -1, (k & 2) ? 1 : -1, (k & 1) ? 1 : -1};
  // Row of R (Q1.30) dotted with the child's sign vector: Q2.30, |.| < 2^32.
  std::int64_t row_dot_sign = 0;
  for (int j = 0; j < 3; ++j) row_dot_sign += std::int64_t{sign[j]} * rotation.m_q30[axis][j];
  // pixels = row_dot_sign / 2^30 * edge_px_q16 / 2^16 / 2^(level + 2), wanted in Q.F.
  return mulShiftRound(row_dot_sign, edge_px_q16, 30 + 16 + level + 2 - fraction_bits);
}

CameraError checkCamera(const Camera& camera, int depth, int fraction_bits) {
  if (camera.width < 1 || camera.width > kMaxViewportSide || camera.height < 1 ||
      camera.height > kMaxViewportSide) {
    return CameraError::kBadViewport;
  }
  if (camera.zoom.raw() <= 0) return CameraError::kBadZoom;
  if (fraction_bits < kMinFractionBits || fraction_bits > kMaxFractionBits) {
    return CameraError::kBadFractionBits;
  }
  if (depth < 1 || depth > kMaxRenderDepth) return CameraError::kBadDepth;
  return CameraError::kNone;
}

}  // namespace

std::uint64_t voxelEdgeOnScreen(const FrameSetup& setup) {
  if (setup.depth < 1) return 0;
  const auto& offsets = setup.child_offset[static_cast<std::size_t>(setup.depth - 1)];
  std::uint64_t squared = 0;
  for (const std::int64_t component :
       {std::int64_t{offsets[4].x} - offsets[0].x, std::int64_t{offsets[4].y} - offsets[0].y,
        std::int64_t{offsets[4].z} - offsets[0].z}) {
    squared += static_cast<std::uint64_t>(component * component);  // each < 2^62, sum < 2^64
  }
  return integerSquareRoot(squared);
}

std::optional<SplatFootprint> leafFootprint(const Camera& camera, int depth, int fraction_bits) {
  if (checkCamera(camera, depth, fraction_bits) != CameraError::kNone) return std::nullopt;
  const Rotation rotation = rotationFromYawPitchRoll(camera.yaw, camera.pitch, camera.roll);
  const std::int64_t edge_px_q16 = edgePixelsQ16(camera);
  std::int64_t largest[2] = {0, 0};
  for (int k = 0; k < 8; ++k) {
    for (int axis = 0; axis < 2; ++axis) {
      const std::optional<std::int64_t> value =
          childOffset(rotation, edge_px_q16, depth - 1, k, axis, fraction_bits);
      if (!value || std::llabs(*value) > std::numeric_limits<std::int32_t>::max())
        return std::nullopt;
      largest[axis] = std::max<std::int64_t>(largest[axis], std::llabs(*value));
    }
  }
  return splatFootprint(largest[0], largest[1], depth, fraction_bits);
}

CameraError buildFrameSetup(const Camera& camera, int depth, int fraction_bits, FrameSetup* setup,
                            std::int32_t sample_reach) {
  if (const CameraError error = checkCamera(camera, depth, fraction_bits);
      error != CameraError::kNone) {
    return error;
  }
  if (sample_reach < kOneSampleReach || sample_reach > kMaxSampleReach) {
    return CameraError::kBadSampleReach;
  }
  const Rotation rotation = rotationFromYawPitchRoll(camera.yaw, camera.pitch, camera.roll);
  const std::int64_t edge_px_q16 = edgePixelsQ16(camera);

  constexpr std::int64_t kLimit = std::numeric_limits<std::int32_t>::max();
  const std::int64_t root[3] = {
      (static_cast<std::int64_t>(camera.width) << fraction_bits >> 1) +  // half the width, Q.F
          (static_cast<std::int64_t>(camera.pan_x_px) << fraction_bits),
      (static_cast<std::int64_t>(camera.height) << fraction_bits >> 1) +
          (static_cast<std::int64_t>(camera.pan_y_px) << fraction_bits),
      0};
  std::int64_t worst[3] = {std::llabs(root[0]), std::llabs(root[1]), 0};

  FrameSetup result;
  result.camera = camera;
  result.depth = depth;
  result.fraction_bits = fraction_bits;
  result.width = camera.width;
  result.height = camera.height;
  std::int64_t largest[3] = {0, 0, 0};  // of the last level done: the leaves' half extents
  for (int level = 0; level < depth; ++level) {
    largest[0] = largest[1] = largest[2] = 0;
    for (int k = 0; k < 8; ++k) {
      std::int32_t offset[3];
      for (int axis = 0; axis < 3; ++axis) {
        const std::optional<std::int64_t> value =
            childOffset(rotation, edge_px_q16, level, k, axis, fraction_bits);
        if (!value || std::llabs(*value) > kLimit) return CameraError::kOverflow;
        offset[axis] = static_cast<std::int32_t>(*value);
        largest[axis] = std::max<std::int64_t>(largest[axis], std::llabs(*value));
      }
      result.child_offset[static_cast<std::size_t>(level)][static_cast<std::size_t>(k)] =
          Vec3{offset[0], offset[1], offset[2]};
    }
    for (int axis = 0; axis < 3; ++axis) worst[axis] += largest[axis];
  }
  // Widened by the sample reach (Q4; half extents below 2^31, so the product fits 64 bits), rounded
  // up so that the widened splat covers at least what the reach asks for.
  if (sample_reach != kOneSampleReach) {
    for (int axis = 0; axis < 2; ++axis) largest[axis] = (largest[axis] * sample_reach + 15) >> 4;
  }
  // A splat reaches at most its padded half extent (largest + depth + 1) and one pixel further
  // from a leaf (octopoint/camera.h); a leaf without one, only its own position.
  const SplatFootprint splat = splatFootprint(largest[0], largest[1], depth, fraction_bits);
  const std::int64_t splat_margin =
      splat.active() ? depth + 1 + (std::int64_t{1} << fraction_bits) : 0;
  const std::int64_t splat_reach[3] = {splat.active() ? largest[0] + splat_margin : 0,
                                       splat.active() ? largest[1] + splat_margin : 0, 0};
  // The z-buffer reserves INT32_MAX for "empty", hence the strict bound.
  for (int axis = 0; axis < 3; ++axis) {
    if (worst[axis] + splat_reach[axis] >= kLimit) return CameraError::kOverflow;
  }
  result.root = Vec3{static_cast<std::int32_t>(root[0]), static_cast<std::int32_t>(root[1]), 0};
  result.splat = splat;
  result.sample_reach = sample_reach;
  result.depth_bias = static_cast<std::uint32_t>(worst[2]);
  const std::uint64_t depth_range = 2 * static_cast<std::uint64_t>(worst[2]);
  while ((depth_range >> result.depth_shift) > Framebuffer::kMaxDepthKey) ++result.depth_shift;
  *setup = result;
  return CameraError::kNone;
}

}  // namespace octopoint
