#pragma once
// octopoint-tradeoff's parts (docs/tradeoff.md): the scan and its reference surface, models
// prepared in-process, the measures of one frame, and the two sweeps (depths x variants at one
// view; sizes x zooms, before and after).

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "cli/output_file.h"
#include "codegen/cube_fit.h"
#include "codegen/prepare.h"
#include "lab/error_regions.h"
#include "lab/reference_surface.h"
#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"

namespace octopoint::tradeoff {

inline constexpr Rgb kBackground{236, 236, 240};

// The scan as the model sees it: the points after crop and axes, their cube and their surface.
struct Scene {
  std::string scan_path;
  prepare::Scan scan;  // as loaded: prepareModel crops and turns it itself
  prepare::PrepareOptions prepare;
  prepare::CubeFit fit;
  ReferenceSurface surface;
};
// `rule` makes an unorganized scan's reference discs (lab/reference_surface.h).
Scene loadScene(const std::string& scan_path, const prepare::PrepareOptions& options,
                const SplatRule& rule = kSplatRule);

// A model prepared in memory from the scene at `depths` (only the densely sampled ones when
// `dense_only`, as octopoint-prepare's default range: codegen/depth_range.h); the view points
// into `bytes`.
struct InMemoryModel {
  std::vector<std::uint8_t> bytes;
  std::optional<ModelView> view;
};
std::unique_ptr<InMemoryModel> prepareInMemory(const Scene& scene, const std::vector<int>& depths,
                                               bool dense_only = false);

// The reference render of the scene for `camera`, with its silhouette (CV_8U, 255 = object).
struct Reference {
  cv::Mat image;
  cv::Mat silhouette;
};
Reference referenceFor(const Scene& scene, const Camera& camera);

struct Quality {
  double psnr = 0;         // dB, cv::PSNR against the reference over all pixels
  double ssim = 0;         // mean over B, G, R (lab/image_quality.h)
  double empty_share = 0;  // share of the reference's silhouette pixels the frame leaves empty
  // The same inside the silhouette's interior (Region::kInterior: its pixels at least kBandWidth
  // pixels from its outline), which tells holes from edge effects.
  double interior_empty_share = 0;
  // The frame's squared error by region of the silhouette (lab/error_regions.h).
  RegionError error_by_region;
};
// The frame resolved to BGR (palette colours, kBackground where empty).
cv::Mat toImage(const Framebuffer& frame, const ModelView& model);
Quality measure(const Reference& reference, const Framebuffer& frame, const ModelView& model);
// The same for a frame whose colours are `drawn` (BGR, the frame's size): a smooth frame's.
Quality measure(const Reference& reference, const Framebuffer& frame, const cv::Mat& drawn);

// How long to repeat a frame for its median time: at least `min_frames` frames and
// `min_seconds`, at most `max_frames`.
struct Repeats {
  int min_frames = 1;
  double min_seconds = 0.05;
  int max_frames = 200;
};

// Median milliseconds per call of `draw` (wall clock).
template <typename Draw>
double medianMilliseconds(Draw draw, const Repeats& repeats) {
  std::vector<double> times;
  const auto start = std::chrono::steady_clock::now();
  do {
    const auto before = std::chrono::steady_clock::now();
    draw();
    times.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - before)
            .count());
  } while (static_cast<int>(times.size()) < repeats.max_frames &&
           (static_cast<int>(times.size()) < repeats.min_frames ||
            std::chrono::steady_clock::now() - start <
                std::chrono::duration<double>(repeats.min_seconds)));
  std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2),
                   times.end());
  return times[times.size() / 2];
}

struct DepthSweepOptions {
  Camera camera;
  std::vector<int> depths = {6, 7, 8, 9, 10};
  std::vector<int> fraction_bits = {8, 12, 15, 20};
};
// Every depth x variant x fraction bits x hole filling at one view: returns tradeoff.csv, the plot
// tradeoff.png and the reference tradeoff_reference.png (depthSweepOutputNames), for the caller to
// write together. Throws cli::Error when the camera refuses a fraction bits setting.
std::vector<cli::OutputFile> runDepthSweep(const Scene& scene, const DepthSweepOptions& options);
// Throws cli::Error when the camera refuses the view at one of the depths and fraction bits: the
// same check runDepthSweep makes, before the scan is read (it needs only the options).
void checkDepthSweepViews(const DepthSweepOptions& options);
std::vector<std::string> depthSweepOutputNames();

struct ViewSweepOptions {
  Camera camera;  // its angles; width, height and zoom come from the lists
  std::vector<std::pair<int, int>> sizes = {
      {176, 208}, {320, 240}, {640, 480}, {1280, 960}, {1920, 1080}};
  std::vector<double> zooms = {0.25, 0.5, 1, 2, 4, 8};
  std::string label = "scan";     // names the scan in the outputs
  bool pictures = false;          // also write reference | before | after pictures per cell
  Repeats repeats{9, 0.05, 200};  // per cell, configuration and round
  int rounds = 3;                 // a cell's time is the median of its rounds' medians
};
// Every size x zoom, today's renderer against depth auto with splats: returns sweep.csv and
// sweep.md (viewSweepOutputNames) for the caller to write together. With options.pictures, writes
// each cell's pictures into OUTDIR/pictures as they are made, once every view has been checked.
std::vector<cli::OutputFile> runViewSweep(const Scene& scene, const ViewSweepOptions& options,
                                          const std::filesystem::path& output);
std::vector<std::string> viewSweepOutputNames();
// The PNG encoding of an 8-bit BGR image.
std::string encodePng(const cv::Mat& image);

}  // namespace octopoint::tradeoff
