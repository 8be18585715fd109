#pragma once
// The dense reference render the speed/accuracy trade is measured against (docs/tradeoff.md):
// every point of the scan (after the same crop and axes as the model), in double precision, with
// its own colour (not the palette's), through the same orthographic camera, nearest point per pixel.

#include <opencv2/core.hpp>

#include "codegen/cube_fit.h"
#include "codegen/scan_loader.h"
#include "renderer/camera.h"
#include "renderer/model.h"

namespace octopoint::tradeoff {

// `fit` is the cube the model was fitted into (so both renders share the same framing); `scan`
// holds the points in the model's axes. Returns an 8-bit BGR image and sets `covered` (CV_8U,
// 255 where some point landed) to the reference's object mask.
cv::Mat renderReference(const prepare::Scan& scan, const prepare::CubeFit& fit, const Camera& camera,
                        Rgb background, cv::Mat* covered);

}  // namespace octopoint::tradeoff
