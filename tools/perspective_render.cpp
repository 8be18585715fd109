#include "tools/perspective_render.h"

#include <opencv2/imgproc.hpp>

#include "cli/error.h"
#include "renderer/perspective_renderer.h"

namespace octopoint {

PerspectiveView orbitPerspectiveView(const Camera& camera, Angle fov) {
  PerspectiveView view;
  if (const PerspectiveError error = orbitPerspective(camera, fov, kDefaultFractionBits, &view);
      error == PerspectiveError::kEyeTooFar) {
    throw cli::Error("--perspective: at this zoom and field of view the eye would be more than " +
                     std::to_string(kMaxEyeDistance) +
                     " cube edges from the model: zoom in or widen --fov");
  } else if (error != PerspectiveError::kNone) {
    throw cli::Error(std::string("--perspective: ") + describe(error));
  }
  return view;
}

cv::Mat renderPerspective(const ModelView& model, int depth, const PerspectiveView& view,
                          Rgb background, PerspectiveDrawStats* stats) {
  Framebuffer frame(view.camera.width, view.camera.height);
  frame.clear();
  PerspectiveRenderer renderer(model);
  PerspectiveRenderer::Options options;
  options.depth = depth;
  // No abort flag: it completes; `depth` is a stored one (the caller chose it from the model).
  static_cast<void>(renderer.draw(view, options, frame, stats));
  cv::Mat rgb(view.camera.height, view.camera.width, CV_8UC3);
  // The frame is sized to the camera: resolveToRgb cannot refuse it.
  static_cast<void>(resolveToRgb(frame, model, background, {rgb.data, rgb.total() * 3}));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

}  // namespace octopoint
