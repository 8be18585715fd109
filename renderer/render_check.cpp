#include <algorithm>
#include <cstdlib>
#include <limits>

#include "octopoint/render.h"

namespace octopoint {

const char* describe(RenderError error) {
  switch (error) {
    case RenderError::kNone:
      return "no error";
    case RenderError::kBadSetup:
      return "frame set-up not made by buildFrameSetup (sizes, depth or offsets out of range)";
    case RenderError::kFrameSizeMismatch:
      return "framebuffer size differs from the frame set-up's";
    case RenderError::kDepthMismatch:
      return "level depth differs from the frame set-up's";
    case RenderError::kImplausibleLevel:
      return "level sizes impossible for its depth";
    case RenderError::kLevelWithoutNormals:
      return "frame carries normals and the level has none";
  }
  return "unknown error";
}

RenderError checkFrameSetup(const FrameSetup& setup) {
  if (setup.depth < 1 || setup.depth > kMaxRenderDepth || setup.fraction_bits < kMinFractionBits ||
      setup.fraction_bits > kMaxFractionBits || setup.width < 1 || setup.width > kMaxViewportSide ||
      setup.height < 1 || setup.height > kMaxViewportSide) {
    return RenderError::kBadSetup;
  }
  // The smooth kernel's radius scales with the sample reach: only the range buildFrameSetup takes.
  if (setup.sample_reach < kOneSampleReach || setup.sample_reach > kMaxSampleReach) {
    return RenderError::kBadSetup;
  }
  // The bound buildFrameSetup proves (renderer/camera.cpp), on the offsets as they are now: no sum
  // of the root and one offset per level, nor a splat's reach from it, may wrap 32 bits.
  constexpr std::int64_t kLimit = std::numeric_limits<std::int32_t>::max();
  std::int64_t worst[3] = {std::llabs(setup.root.x), std::llabs(setup.root.y),
                           std::llabs(setup.root.z)};
  std::int64_t largest[3] = {0, 0, 0};
  for (int level = 0; level < setup.depth; ++level) {
    largest[0] = largest[1] = largest[2] = 0;
    for (const Vec3& offset : setup.child_offset[static_cast<std::size_t>(level)]) {
      largest[0] = std::max<std::int64_t>(largest[0], std::llabs(offset.x));
      largest[1] = std::max<std::int64_t>(largest[1], std::llabs(offset.y));
      largest[2] = std::max<std::int64_t>(largest[2], std::llabs(offset.z));
    }
    for (int axis = 0; axis < 3; ++axis) worst[axis] += largest[axis];
  }
  // A leaf at p covers up to (p + offset + span) >> F (octopoint/camera.h): the decoders
  // add these in 32 bits too. The fields are judged as they are, not against a recomputed splat:
  // a band renderer's subtree set-up keeps the whole frame's splat at a smaller depth.
  const SplatFootprint& splat = setup.splat;
  if (splat.span_x < 0 || splat.span_y < 0) return RenderError::kBadSetup;
  const std::int64_t reach[3] = {
      std::max(std::llabs(splat.offset_x), std::llabs(std::int64_t{splat.offset_x} + splat.span_x)),
      std::max(std::llabs(splat.offset_y), std::llabs(std::int64_t{splat.offset_y} + splat.span_y)),
      0};
  for (int axis = 0; axis < 3; ++axis) {
    if (worst[axis] + reach[axis] >= kLimit) return RenderError::kBadSetup;
  }
  return RenderError::kNone;
}

RenderError checkRender(const LevelView& level, const FrameSetup& setup, const FrameView& frame) {
  if (const RenderError error = checkFrameSetup(setup); error != RenderError::kNone) return error;
  if (frame.width() != setup.width || frame.height() != setup.height)
    return RenderError::kFrameSizeMismatch;
  if (level.depth != setup.depth) return RenderError::kDepthMismatch;
  if (!plausibleLevelSize(level.depth, level.nodes.size(), level.leaves.size())) {
    return RenderError::kImplausibleLevel;
  }
  if (frame.payload() == PixelPayload::kColourNormal &&
      level.normals.size() != level.leaves.size()) {
    return RenderError::kLevelWithoutNormals;
  }
  return RenderError::kNone;
}

}  // namespace octopoint
