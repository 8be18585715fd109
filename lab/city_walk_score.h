#pragma once
// Scores the frames of a streamed walk (octopoint-city-walk, docs/city.md "Walking over a slow
// link") against the complete city drawn from the same eyes: PSNR against the complete city's
// frame; "within 1 dB": the frame's PSNR against a supersampled truth (the complete city drawn N
// times wider and higher, averaged down) is within 1 dB of the complete frame's (as
// docs/streaming.md scores a model's frames against its scan's surface); holes: pixels the
// complete city's frame covers, drawing only the instances whose model had arrived, that the
// streamed frame leaves empty: inside its surfaces (all four neighbours covered there too), or on
// their outline (a coarser voxel's footprint splat, centred on its centre's projection, may end a
// row short of the finer voxels' at a silhouette).

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <vector>

#include "renderer/cell_table.h"
#include "renderer/scene_cells.h"
#include "renderer/scene_renderer.h"
#include "tools/scene_file.h"

namespace octopoint {

inline constexpr Rgb kWalkBackground{236, 236, 240};

struct WalkFrame {
  double seconds = 0;  // since the walk began
  PerspectiveView view;
  std::vector<std::uint8_t> colours;  // the streamed frame's palette index per pixel (255: empty)
  std::vector<std::uint8_t> models;   // 1 where the model's head had arrived
  std::uint64_t bytes = 0;            // received when it was drawn
};

struct WalkScore {
  double psnr_complete = 0;  // against the complete city's frame (infinity: identical)
  double psnr_truth = 0, complete_truth = 0;
  bool within_1db = false;
  std::uint64_t holes = 0;              // pixels inside the complete frame's surfaces
  std::uint64_t outline = 0;            // pixels on their outline
  int hole_top = -1, hole_bottom = -1;  // the rows of both
};

class WalkScorer {
 public:
  // `cells`: the eye's cell's set drawn alone, as the streamed frames did (may be null).
  WalkScorer(const LoadedScene& scene, const CellTable* cells, int truth_scale);
  // `palette`: the streamed scene's (renderer/held_scene.h), RGB888 per index.
  WalkScore score(const WalkFrame& frame, std::span<const std::uint8_t> palette);
  // The streamed frame's colours (BGR).
  static cv::Mat streamed(const WalkFrame& frame, std::span<const std::uint8_t> palette);
  // The streamed frame with its holes in red beside the complete city's frame of the models that
  // had arrived (BGR), after score() of the same frame.
  cv::Mat holes(const WalkFrame& frame, std::span<const std::uint8_t> palette);
  // The complete city's frame of `view` (BGR).
  cv::Mat complete(const PerspectiveView& view);

 private:
  cv::Mat draw(const PerspectiveView& view, const std::vector<std::uint32_t>* only,
               Framebuffer& frame);

  const LoadedScene& scene_;
  std::optional<SceneRenderer> renderer_;
  std::optional<SceneCells> cells_;
  int truth_scale_;
  Framebuffer frame_{1, 1}, truth_{1, 1};
  std::vector<std::uint32_t> only_;
  cv::Mat only_frame_;  // score()'s frame of the models that had arrived
};

}  // namespace octopoint
