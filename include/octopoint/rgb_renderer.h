#pragma once
// octopoint/rgb_renderer.h: One call from a model and a camera to RGB pixels.
// The manual of the whole library is octopoint/octopoint.h.

#include <cstdint>
#include <optional>
#include <span>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/render.h"

// The common case in one call: a model, as a camera sees it, to RGB pixels (docs/embedding.md).
//
//   octopoint::RgbRenderer renderer;                        // owns the frame; allocates on first
//   use octopoint::Camera camera;                                // 320x240, frontal, zoom 1
//   camera.yaw = octopoint::Angle::fromDegrees(30);
//   camera.zoom = *octopoint::zoomRatio(3, 2);               // 1.5x, from a plain ratio
//   std::vector<std::uint8_t> rgb(camera.width * camera.height * 3);
//   if (renderer.draw(model, camera, rgb, {.fill_holes = true}) != octopoint::DrawError::kNone) ...
//
// The size is given once, in the camera: the renderer's framebuffer and hole filler follow it
// (allocated on the first draw and again only when the camera's size changes, so drawing frame
// after frame at one size never allocates), and `rgb` is checked against it. The detailed API
// (buildFrameSetup, Framebuffer, renderLevel, HoleFiller, resolveToRgb) stays for everything else:
// several models in one frame, bands, aborting, a chosen fraction precision.

namespace octopoint {

// A zoom of numerator / denominator (3, 2: 1.5x), rounded to the nearest Q16.16 step; nullopt
// unless the ratio lies in [1/65536, 32767] (what Camera::zoom holds).
[[nodiscard]] std::optional<Q16> zoomRatio(std::int64_t numerator, std::int64_t denominator);

struct DrawOptions {
  int depth = 0;  // a stored depth of the model, or 0: depth auto (renderer/level_of_detail.h)
  Variant variant = defaultVariant();  // the fastest this CPU runs
  bool fill_holes = false;             // scanline hole filling after decoding (docs/holefill.md)
  Rgb background{236, 236, 240};       // for pixels no point covers
};

enum class DrawError : std::uint8_t {
  kNone,
  kBadCamera,    // buildFrameSetup refused the camera (its size, zoom or pan); see cameraError()
  kNoSuchDepth,  // options.depth is not one of the model's depths, or no depth suits the camera
  kRgbTooSmall,  // rgb holds fewer than camera.width * camera.height * 3 bytes
  kRefused,      // renderLevel refused the arguments (renderError() says why); cannot happen
                 // with a ModelView and a camera buildFrameSetup accepted
};

const char* describe(DrawError error);

class RgbRenderer {
 public:
  RgbRenderer() = default;

  // Draws `model` as `camera` sees it into `rgb`: RGB888, row-major, camera.width x camera.height.
  // On an error `rgb` is left as it was.
  [[nodiscard]] DrawError draw(const ModelView& model, const Camera& camera,
                               std::span<std::uint8_t> rgb, const DrawOptions& options = {});

  // After a draw: the frame it drew (depth keys and palette indices), the depth it drew, and why
  // a camera or the render was refused.
  const Framebuffer& frame() const { return frame_; }
  int drawnDepth() const { return drawn_depth_; }
  CameraError cameraError() const { return camera_error_; }
  RenderError renderError() const { return render_error_; }

 private:
  Framebuffer frame_{0, 0};
  HoleFiller filler_{0};
  int drawn_depth_ = 0;
  CameraError camera_error_ = CameraError::kNone;
  RenderError render_error_ = RenderError::kNone;
};

}  // namespace octopoint
