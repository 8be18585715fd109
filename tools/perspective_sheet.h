#pragma once
// A contact sheet of perspective views (`octopoint-render --perspective/--eye/--path --sheet N`):
// the N views in columns (tools/perspective_render.h, sheetViews); a first row with each part of a
// frame at the depth its distance asks for (detail by distance, as the single views draw), then a
// row per stored depth the renderer draws, coarse first; each row filled and styled as the job
// asks (--fill, --style) and labelled.

#include <cstdint>
#include <opencv2/core.hpp>
#include <span>

#include "renderer/perspective.h"
#include "tools/perspective_render.h"

namespace octopoint {

// The sheet's size in pixels (cells and labels) for `columns` views of the job's size.
std::int64_t perspectiveSheetPixels(const PerspectiveJob& job, int columns);

// Draws the sheet as a BGR image (cells of the views' size, on the job's background).
cv::Mat renderPerspectiveSheet(const PerspectiveJob& job, std::span<const PerspectiveView> views);

// Checks the job's output, draws the sheet of `views` and writes it; prints one line saying what.
// cli::Error, one line, leaving no file, when it cannot.
void drawPerspectiveSheet(const PerspectiveJob& job, std::span<const PerspectiveView> views);

}  // namespace octopoint
