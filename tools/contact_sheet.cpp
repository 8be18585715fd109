#include "tools/contact_sheet.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

struct SheetRow {
  const LevelView* level;  // nullptr: depth auto, per view
  bool fill;
  Style style;
};

std::vector<SheetRow> sheetRows(const ModelView& model, Style style) {
  std::vector<SheetRow> rows = {{nullptr, false, style}};
  for (int i = 0; i < model.levelCount(); ++i) {
    for (const bool fill : {false, true}) rows.push_back({&model.level(i), fill, style});
  }
  if (model.hasNormals()) {
    for (const StyleInfo& info : allStyles()) {
      if (info.style != style) rows.push_back({nullptr, false, info.style});
    }
  }
  return rows;
}

std::string label(const SheetRow& row) {
  std::string text = row.level == nullptr ? "depth auto (by projected size)"
                                          : "depth " + std::to_string(row.level->depth);
  text += row.fill ? ", hole filling" : ", no filling";
  if (row.style != Style::kColour) text += ", " + std::string(styleName(row.style));
  return text;
}

}  // namespace

void putSheetLabel(cv::Mat& sheet, const std::string& text, int top) {
  cv::putText(sheet, text, {4, top + kSheetLabelHeight - 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              {40, 40, 40}, 1, cv::LINE_AA);
}

std::int64_t contactSheetPixels(const ModelView& model, const Camera& camera, int yaw_count) {
  const auto rows = static_cast<std::int64_t>(sheetRows(model, Style::kColour).size());
  return rows * (camera.height + kSheetLabelHeight) * yaw_count * std::int64_t{camera.width};
}

cv::Mat renderContactSheet(const ModelView& model, const Camera& camera, int yaw_count,
                           Variant variant, const StyleOptions& style) {
  const std::vector<SheetRow> rows = sheetRows(model, style.style);
  const int row_height = camera.height + kSheetLabelHeight;
  const Rgb background = style.background;
  cv::Mat sheet(static_cast<int>(rows.size()) * row_height, yaw_count * camera.width, CV_8UC3,
                cv::Scalar(background.b, background.g, background.r));
  Framebuffer frame(camera.width, camera.height);
  HoleFiller filler(camera.width);
  FrameStyler styler(model);
  cv::Mat rgb(camera.height, camera.width, CV_8UC3), bgr;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const SheetRow& row = rows[r];
    StyleOptions options = style;
    options.style = row.style;
    if (const StyleError error = styler.setOptions(options); error != StyleError::kNone) {
      throw std::runtime_error(describe(error));
    }
    const int top = static_cast<int>(r) * row_height;
    putSheetLabel(sheet, label(row), top);
    for (int column = 0; column < yaw_count; ++column) {
      Camera view = camera;
      view.yaw =
          camera.yaw + Angle::fromTurns16(std::int64_t{column} * Angle::kUnitsPerTurn / yaw_count);
      const LevelView* drawn = row.level != nullptr ? row.level : autoLevel(model, view);
      FrameSetup setup;
      const CameraError error =
          drawn == nullptr ? CameraError::kOverflow
                           : buildFrameSetup(view, drawn->depth, kDefaultFractionBits, &setup);
      if (error != CameraError::kNone)
        throw std::runtime_error(std::string("camera refused: ") + describe(error));
      frame.clear(styler.payload());
      if (!renderLevel(variant, *drawn, setup, frame)) {
        throw std::runtime_error(std::string("draw refused: ") +
                                 describe(checkRender(*drawn, setup, frame)));
      }
      if (row.fill && filler.fill(frame, bridgeDepthLimit(setup)).refused)
        throw std::runtime_error("hole filling refused the frame");
      styler.beginFrame(setup);
      if (const StyleError style_error = styler.resolve(frame, {rgb.data, rgb.total() * 3});
          style_error != StyleError::kNone) {
        throw std::runtime_error(std::string("style refused: ") + describe(style_error));
      }
      cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
      bgr.copyTo(sheet(
          cv::Rect(column * camera.width, top + kSheetLabelHeight, camera.width, camera.height)));
    }
  }
  return sheet;
}

}  // namespace octopoint
