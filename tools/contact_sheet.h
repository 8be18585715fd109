#pragma once
// A contact sheet of many views of one model (`octopoint-render --sheet N`): N yaw angles in
// columns; a first row at depth auto (renderer/level_of_detail.h), then rows for each of the
// model's depths (coarse first), unfilled and hole-filled, all in the chosen style; then, for a
// model with normals, one row at depth auto per other style (octopoint/styles.h).

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "octopoint/render.h"
#include "octopoint/styles.h"

namespace octopoint {

// Pixels above each row of a sheet for its label, and the label written there (its row's top).
inline constexpr int kSheetLabelHeight = 18;
void putSheetLabel(cv::Mat& sheet, const std::string& text, int top);

// The sheet's size in pixels (cells and labels), to check before drawing it.
std::int64_t contactSheetPixels(const ModelView& model, const Camera& camera, int yaw_count);

// Draws the sheet as a BGR image: cells of camera.width x camera.height, the yaw of column i is
// camera.yaw + i * 360 / yaw_count degrees; each row is labelled. `style` must be one the model
// can draw (FrameStyler::setOptions); its background is the sheet's. Throws std::runtime_error
// when the camera is refused.
cv::Mat renderContactSheet(const ModelView& model, const Camera& camera, int yaw_count,
                           Variant variant, const StyleOptions& style);

}  // namespace octopoint
