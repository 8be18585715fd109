#include "tools/perspective_sheet.h"

#include <cstdio>
#include <string>
#include <vector>

#include "cli/error.h"
#include "cli/output_file.h"
#include "octopoint/camera.h"
#include "octopoint/styles.h"
#include "tools/contact_sheet.h"
#include "tools/png_file.h"

namespace octopoint {
namespace {

// The sheet's rows: nullptr for detail by distance, then each stored depth the renderer draws.
std::vector<const LevelView*> sheetRows(const ModelView& model) {
  std::vector<const LevelView*> rows = {nullptr};
  for (int i = 0; i < model.levelCount(); ++i) {
    if (model.level(i).depth <= kMaxRenderDepth) rows.push_back(&model.level(i));
  }
  return rows;
}

std::string rowLabel(const PerspectiveJob& job, const LevelView* level) {
  std::string text = level == nullptr ? "depth by distance (auto)"
                                      : "depth " + std::to_string(level->depth) + " everywhere";
  if (job.finish.fill) text += ", hole filling";
  if (job.finish.styler != nullptr)
    text += ", " + std::string(styleName(job.finish.styler->options().style));
  return text;
}

}  // namespace

std::int64_t perspectiveSheetPixels(const PerspectiveJob& job, int columns) {
  const auto rows = static_cast<std::int64_t>(sheetRows(*job.model).size());
  return rows * (job.camera.height + kSheetLabelHeight) * columns * std::int64_t{job.camera.width};
}

cv::Mat renderPerspectiveSheet(const PerspectiveJob& job, std::span<const PerspectiveView> views) {
  const std::vector<const LevelView*> rows = sheetRows(*job.model);
  const int width = job.camera.width, height = job.camera.height;
  const int row_height = height + kSheetLabelHeight;
  const Rgb background = job.background;
  cv::Mat sheet(static_cast<int>(rows.size()) * row_height, static_cast<int>(views.size()) * width,
                CV_8UC3, cv::Scalar(background.b, background.g, background.r));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    // A depth row draws that stored depth over the whole frame, as --depth N does.
    PerspectiveJob row_job = job;
    if (rows[r] != nullptr) {
      row_job.depth = rows[r]->depth;
      row_job.chosen_level = rows[r];
      row_job.point_budget = 0;
    } else {
      row_job.depth.reset();
    }
    const int top = static_cast<int>(r) * row_height;
    putSheetLabel(sheet, rowLabel(job, rows[r]), top);
    for (std::size_t column = 0; column < views.size(); ++column) {
      renderPerspectiveView(row_job, views[column])
          .copyTo(sheet(
              cv::Rect(static_cast<int>(column) * width, top + kSheetLabelHeight, width, height)));
    }
  }
  return sheet;
}

void drawPerspectiveSheet(const PerspectiveJob& job, std::span<const PerspectiveView> views) {
  const auto columns = static_cast<int>(views.size());
  const std::int64_t pixels = perspectiveSheetPixels(job, columns);
  if (pixels > kMaxOutputPixels) {
    throw cli::Error("--sheet " + std::to_string(columns) + " at --size " +
                     std::to_string(job.camera.width) + "x" + std::to_string(job.camera.height) +
                     " makes a " + std::to_string(pixels) + "-pixel image, at most " +
                     std::to_string(kMaxOutputPixels) + ": give fewer views or a smaller --size");
  }
  cli::checkOutputFile(job.output);
  writePng(job.output, renderPerspectiveSheet(job, views));
  std::printf("%s: perspective contact sheet of %d views -> %s\n", job.label.c_str(), columns,
              job.output.c_str());
}

}  // namespace octopoint
