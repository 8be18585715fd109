#include "lab/city_walk_score.h"

#include <limits>
#include <opencv2/imgproc.hpp>

#include "cli/error.h"
#include "lab/image_quality.h"

namespace octopoint {

WalkScorer::WalkScorer(const LoadedScene& scene, const CellTable* cells, int truth_scale)
    : scene_(scene), truth_scale_(truth_scale) {
  SceneError error;
  renderer_.emplace(scene.models, scene.instances, &error);
  if (error != SceneError::kNone) throw cli::Error(scene.label + ": " + describe(error));
  if (cells != nullptr) cells_.emplace(*cells);
}

cv::Mat WalkScorer::draw(const PerspectiveView& view, const std::vector<std::uint32_t>* only,
                         Framebuffer& frame) {
  if (frame.width() != view.camera.width || frame.height() != view.camera.height)
    frame = Framebuffer(view.camera.width, view.camera.height);
  frame.clear();
  if (only != nullptr) {
    renderer_->setVisibleSet(*only);
  } else if (cells_) {
    cells_->apply(*renderer_, view.camera.eye);
  } else {
    renderer_->clearVisibleSet();
  }
  static_cast<void>(renderer_->draw(view, frame));
  cv::Mat rgb(view.camera.height, view.camera.width, CV_8UC3);
  // Every model holds the scene's palette (tools/scene_file.h): the first one's resolves.
  static_cast<void>(
      resolveToRgb(frame, *scene_.models.front(), kWalkBackground, {rgb.data, rgb.total() * 3}));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

cv::Mat WalkScorer::holes(const WalkFrame& walk, std::span<const std::uint8_t> palette) {
  cv::Mat image = streamed(walk, palette);
  const std::span<const std::uint32_t> words = frame_.pixels();
  for (std::size_t i = 0; i < words.size() && i < walk.colours.size(); ++i) {
    if (words[i] != FrameView::kEmpty && walk.colours[i] == 255)
      image.at<cv::Vec3b>(static_cast<int>(i)) = cv::Vec3b{0, 0, 255};
  }
  cv::Mat both;
  cv::hconcat(image, only_frame_, both);
  return both;
}

cv::Mat WalkScorer::complete(const PerspectiveView& view) { return draw(view, nullptr, frame_); }

cv::Mat WalkScorer::streamed(const WalkFrame& walk, std::span<const std::uint8_t> palette) {
  cv::Mat bgr(walk.view.camera.height, walk.view.camera.width, CV_8UC3);
  for (std::size_t i = 0; i < walk.colours.size(); ++i) {
    const std::size_t c = walk.colours[i];
    cv::Vec3b& pixel = bgr.at<cv::Vec3b>(static_cast<int>(i));
    pixel = c == 255 ? cv::Vec3b{kWalkBackground.b, kWalkBackground.g, kWalkBackground.r}
                     : cv::Vec3b{palette[3 * c + 2], palette[3 * c + 1], palette[3 * c]};
  }
  return bgr;
}

WalkScore WalkScorer::score(const WalkFrame& walk, std::span<const std::uint8_t> palette) {
  WalkScore score;
  const cv::Mat whole = complete(walk.view);
  const cv::Mat image = streamed(walk, palette);
  const double differing = cv::norm(whole, image, cv::NORM_INF);
  score.psnr_complete =
      differing == 0 ? std::numeric_limits<double>::infinity() : tradeoff::psnr(whole, image);
  // The truth: the same camera truth_scale_ times wider and higher, averaged down.
  PerspectiveCamera camera = walk.view.camera;
  camera.width *= truth_scale_;
  camera.height *= truth_scale_;
  PerspectiveView wide;
  if (buildPerspectiveView(camera, walk.view.fraction_bits, &wide) != PerspectiveError::kNone)
    throw cli::Error("the truth's camera is refused");
  cv::Mat truth;
  cv::resize(draw(wide, nullptr, truth_), truth, whole.size(), 0, 0, cv::INTER_AREA);
  score.complete_truth = tradeoff::psnr(truth, whole);
  score.psnr_truth = tradeoff::psnr(truth, image);
  score.within_1db = score.psnr_truth >= score.complete_truth - 1;
  // Holes: what the complete city covers from the models that had arrived, left empty.
  only_.clear();
  for (std::size_t i = 0; i < scene_.instances.size(); ++i)
    if (walk.models[scene_.instances[i].model] != 0) only_.push_back(static_cast<std::uint32_t>(i));
  if (only_.size() != scene_.instances.size() || cells_) {
    only_frame_ = draw(walk.view, &only_, frame_);
  } else {
    only_frame_ = complete(walk.view);
  }
  const std::span<const std::uint32_t> words = frame_.pixels();
  const std::int32_t width = frame_.width(), height = frame_.height();
  for (std::size_t i = 0; i < words.size() && i < walk.colours.size(); ++i) {
    if (words[i] == FrameView::kEmpty || walk.colours[i] != 255) continue;
    const auto x = static_cast<std::int32_t>(i % static_cast<std::size_t>(width));
    const auto y = static_cast<std::int32_t>(i / static_cast<std::size_t>(width));
    const bool inside = x > 0 && y > 0 && x + 1 < width && y + 1 < height &&
                        frame_.covered(x - 1, y) && frame_.covered(x + 1, y) &&
                        frame_.covered(x, y - 1) && frame_.covered(x, y + 1);
    ++(inside ? score.holes : score.outline);
    score.hole_top = score.hole_top < 0 ? y : std::min(score.hole_top, y);
    score.hole_bottom = std::max(score.hole_bottom, y);
  }
  return score;
}

}  // namespace octopoint
