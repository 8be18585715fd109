#pragma once
// A contact sheet of many views of one model (`octopoint-render --sheet N`): N yaw angles in
// columns; a first row at depth auto (renderer/level_of_detail.h), then rows for each of the
// model's depths (coarse first), unfilled and hole-filled.

#include <cstdint>

#include <opencv2/core.hpp>

#include "renderer/camera.h"
#include "renderer/model.h"
#include "renderer/render.h"

namespace octopoint {

// Draws the sheet as a BGR image: cells of camera.width x camera.height, the yaw of column i is
// camera.yaw + i * 360 / yaw_count degrees; each row is labelled. Throws std::runtime_error when
// the camera is refused.
// The sheet's size in pixels (cells and labels), to check before drawing it.
std::int64_t contactSheetPixels(const ModelView& model, const Camera& camera, int yaw_count);

cv::Mat renderContactSheet(const ModelView& model, const Camera& camera, int yaw_count,
                           Variant variant, Rgb background);

}  // namespace octopoint
