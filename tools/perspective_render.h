#pragma once
// octopoint-render --perspective: the orbit camera of the orthographic view, seen in perspective
// (docs/perspective.md).

#include <opencv2/core.hpp>
#include <string>

#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/perspective.h"

namespace octopoint {

// orbitPerspective (renderer/perspective.h) for octopoint-render: throws cli::Error, one line,
// when the camera is refused.
PerspectiveView orbitPerspectiveView(const Camera& camera, Angle fov);

// Draws `level` of `model` with `view` on `background`, as BGR for OpenCV.
cv::Mat renderPerspective(const ModelView& model, const LevelView& level,
                          const PerspectiveView& view, Rgb background);

}  // namespace octopoint
