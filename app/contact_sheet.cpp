#include "app/contact_sheet.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "renderer/framebuffer.h"
#include "renderer/hole_fill.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

constexpr int kLabelHeight = 18;  // pixels above each row for its label

void putLabel(cv::Mat& image, const std::string& text, cv::Point at) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.45, {40, 40, 40}, 1, cv::LINE_AA);
}

}  // namespace

std::int64_t contactSheetPixels(const ModelView& model, const Camera& camera, int yaw_count) {
  const std::int64_t rows = 1 + std::int64_t{model.levelCount()} * 2;  // depth auto, then each depth twice
  return rows * (camera.height + kLabelHeight) * yaw_count * std::int64_t{camera.width};
}

cv::Mat renderContactSheet(const ModelView& model, const Camera& camera, int yaw_count,
                           Variant variant, Rgb background) {
  const int rows = 1 + model.levelCount() * 2;
  const int row_height = camera.height + kLabelHeight;
  cv::Mat sheet(rows * row_height, yaw_count * camera.width, CV_8UC3,
                cv::Scalar(background.b, background.g, background.r));
  Framebuffer frame(camera.width, camera.height);
  HoleFiller filler(camera.width);
  cv::Mat rgb(camera.height, camera.width, CV_8UC3), bgr;
  // One cell: `level` (nullptr: depth auto, per view) from column `column`'s view.
  auto drawCell = [&](int row, int column, const LevelView* level, bool fill) {
    Camera view = camera;
    view.yaw = camera.yaw + Angle::fromTurns16(std::int64_t{column} * Angle::kUnitsPerTurn / yaw_count);
    const LevelView* drawn = level != nullptr ? level : autoLevel(model, view);
    FrameSetup setup;
    const CameraError error = drawn == nullptr ? CameraError::kOverflow
                                               : buildFrameSetup(view, drawn->depth, kDefaultFractionBits, &setup);
    if (error != CameraError::kNone) throw std::runtime_error(std::string("camera refused: ") + describe(error));
    frame.clear();
    renderLevel(variant, *drawn, setup, frame);
    if (fill) filler.fill(frame, bridgeDepthLimit(setup));
    resolveToRgb(frame, model, background, {rgb.data, rgb.total() * 3});
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    bgr.copyTo(sheet(cv::Rect(column * camera.width, row * row_height + kLabelHeight, camera.width, camera.height)));
  };
  putLabel(sheet, "depth auto (by projected size), no filling", {4, kLabelHeight - 5});
  for (int column = 0; column < yaw_count; ++column) drawCell(0, column, nullptr, false);
  for (int level_index = 0; level_index < model.levelCount(); ++level_index) {
    const LevelView& level = model.level(level_index);
    for (const bool fill : {false, true}) {
      const int row = 1 + level_index * 2 + (fill ? 1 : 0);
      putLabel(sheet, "depth " + std::to_string(level.depth) + (fill ? ", hole filling" : ", no filling"),
               {4, row * row_height + kLabelHeight - 5});
      for (int column = 0; column < yaw_count; ++column) drawCell(row, column, &level, fill);
    }
  }
  return sheet;
}

}  // namespace octopoint
