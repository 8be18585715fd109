#pragma once
// octopoint-render --perspective: the orbit camera of the orthographic view, seen in perspective
// (docs/perspective.md).

#include <opencv2/core.hpp>
#include <string>

#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/perspective.h"
#include "renderer/perspective_walk.h"

namespace octopoint {

// orbitPerspective (renderer/perspective.h) for octopoint-render: throws cli::Error, one line,
// when the camera is refused.
PerspectiveView orbitPerspectiveView(const Camera& camera, Angle fov);

// Draws `model` with `view` on `background`, as BGR for OpenCV: its stored `depth`, or with 0
// each part at the depth its distance asks for (detail by distance); occlusion culling on.
// `stats` (may be null) learns what was drawn.
cv::Mat renderPerspective(const ModelView& model, int depth, const PerspectiveView& view,
                          Rgb background, PerspectiveDrawStats* stats = nullptr);

}  // namespace octopoint
