#include "octopoint/rgb_renderer.h"

#include "renderer/level_of_detail.h"

namespace octopoint {

std::optional<Q16> zoomRatio(std::int64_t numerator, std::int64_t denominator) {
  const std::optional<Q16> zoom = Q16::fromRatio(numerator, denominator);
  if (!zoom || zoom->raw() < 1) return std::nullopt;
  return zoom;
}

const char* describe(DrawError error) {
  switch (error) {
    case DrawError::kNone:
      return "no error";
    case DrawError::kBadCamera:
      return "camera refused";
    case DrawError::kNoSuchDepth:
      return "no such depth in the model";
    case DrawError::kRgbTooSmall:
      return "RGB buffer smaller than width x height x 3 bytes";
    case DrawError::kRefused:
      return "render arguments refused";
  }
  return "unknown error";
}

DrawError RgbRenderer::draw(const ModelView& model, const Camera& camera,
                            std::span<std::uint8_t> rgb, const DrawOptions& options) {
  camera_error_ = CameraError::kNone;
  render_error_ = RenderError::kNone;
  drawn_depth_ = 0;
  const LevelView* level =
      options.depth == 0 ? autoLevel(model, camera) : model.levelOfDepth(options.depth);
  if (level == nullptr) return DrawError::kNoSuchDepth;
  FrameSetup setup;
  camera_error_ = buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup,
                                  model.sampleReachOfDepth(level->depth));
  if (camera_error_ != CameraError::kNone) return DrawError::kBadCamera;
  if (rgb.size() / 3 <
      static_cast<std::size_t>(camera.width) * static_cast<std::size_t>(camera.height)) {
    return DrawError::kRgbTooSmall;
  }
  // The frame follows the camera's size: allocated here only when that size changes.
  if (frame_.width() != setup.width || frame_.height() != setup.height) frame_ = Framebuffer(setup);
  if (filler_.width() != setup.width) filler_ = HoleFiller(frame_);
  frame_.clear();
  render_error_ = checkRender(*level, setup, frame_);
  if (render_error_ != RenderError::kNone || !renderLevel(options.variant, *level, setup, frame_)) {
    return DrawError::kRefused;
  }
  // Neither can fail: the filler follows the frame's width, and rgb's size was checked above.
  if (options.fill_holes && filler_.fill(frame_, bridgeDepthLimit(setup)).refused) {
    return DrawError::kRefused;
  }
  if (!resolveToRgb(frame_, model, options.background, rgb)) return DrawError::kRgbTooSmall;
  drawn_depth_ = level->depth;
  return DrawError::kNone;
}

}  // namespace octopoint
