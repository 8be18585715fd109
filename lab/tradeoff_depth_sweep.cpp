// octopoint-tradeoff's first sweep (docs/tradeoff.md): at one view, every depth, decoder variant,
// fraction bits and hole filling on/off; a CSV row per configuration and a plot of time against
// quality.
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "cli/error.h"
#include "lab/tradeoff.h"
#include "octopoint/render.h"

namespace octopoint::tradeoff {
namespace {

namespace fs = std::filesystem;

struct Row {
  int depth;
  std::string variant;
  int fraction_bits;
  bool fill;
  double ms_per_frame;
  std::size_t model_bytes;
  double bits_per_point;
  Quality quality;
};

// Time (log scale) against PSNR, one point per variant, depth and hole filling, at the default
// fraction bits (the CSV has every fraction bits setting).
cv::Mat drawPlot(const std::vector<Row>& rows) {
  constexpr int kWidth = 900, kHeight = 600, kMargin = 70;
  cv::Mat plot(kHeight, kWidth, CV_8UC3, cv::Scalar(255, 255, 255));
  std::vector<const Row*> shown;
  for (const Row& r : rows) {
    if (r.fraction_bits == kDefaultFractionBits) shown.push_back(&r);
  }
  double min_ms = 1e9, max_ms = 0, min_psnr = 1e9, max_psnr = 0;
  for (const Row* r : shown) {
    min_ms = std::min(min_ms, r->ms_per_frame);
    max_ms = std::max(max_ms, r->ms_per_frame);
    min_psnr = std::min(min_psnr, r->quality.psnr);
    max_psnr = std::max(max_psnr, r->quality.psnr);
  }
  const double log_low = std::floor(std::log10(min_ms)), log_high = std::ceil(std::log10(max_ms));
  const double psnr_low = std::floor(min_psnr) - 1, psnr_high = std::ceil(max_psnr) + 1;
  auto at = [&](double ms, double psnr) {
    const double u = (std::log10(ms) - log_low) / (log_high - log_low);
    const double v = (psnr - psnr_low) / (psnr_high - psnr_low);
    return cv::Point(kMargin + static_cast<int>(u * (kWidth - 2 * kMargin)),
                     kHeight - kMargin - static_cast<int>(v * (kHeight - 2 * kMargin)));
  };
  const cv::Scalar black(0, 0, 0), grey(210, 210, 210);
  for (double decade = log_low; decade <= log_high; ++decade) {
    const cv::Point p = at(std::pow(10.0, decade), psnr_low);
    cv::line(plot, p, {p.x, kMargin}, grey);
    char label[32];
    std::snprintf(label, sizeof label, "%g ms", std::pow(10.0, decade));
    cv::putText(plot, label, {p.x - 20, kHeight - kMargin + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
                black);
  }
  for (double db = psnr_low; db <= psnr_high; db += 5) {
    const cv::Point p = at(std::pow(10.0, log_low), db);
    cv::line(plot, p, {kWidth - kMargin, p.y}, grey);
    cv::putText(plot, std::to_string(static_cast<int>(db)) + " dB", {10, p.y + 5},
                cv::FONT_HERSHEY_SIMPLEX, 0.45, black);
  }
  cv::putText(plot, "time per frame (log scale)", {kWidth / 2 - 110, kHeight - 20},
              cv::FONT_HERSHEY_SIMPLEX, 0.6, black);
  cv::putText(
      plot,
      "PSNR against the surface reference; dot: hole filling on, ring: off, x: floating point",
      {kMargin, 30}, cv::FONT_HERSHEY_SIMPLEX, 0.5, black);
  const cv::Scalar depth_colour[] = {{180, 119, 31}, {14, 127, 255},  {44, 160, 44},
                                     {40, 39, 214},  {189, 103, 148}, {75, 86, 140}};
  for (const Row* r : shown) {
    const cv::Scalar colour =
        depth_colour[static_cast<std::size_t>(std::clamp(r->depth - 6, 0, 5))];
    if (r->variant.rfind("float_", 0) == 0)
      cv::drawMarker(plot, at(r->ms_per_frame, r->quality.psnr), colour, cv::MARKER_TILTED_CROSS,
                     9);
    else
      cv::circle(plot, at(r->ms_per_frame, r->quality.psnr), r->fill ? 5 : 4, colour,
                 r->fill ? cv::FILLED : 1);
  }
  for (int d = 0; d < 5; ++d) {
    cv::circle(plot, {kWidth - 150, kHeight - kMargin - 120 + 22 * d}, 5, depth_colour[d],
               cv::FILLED);
    cv::putText(plot, "depth " + std::to_string(d + 6),
                {kWidth - 135, kHeight - kMargin - 115 + 22 * d}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                black);
  }
  return plot;
}

// The set-up of one depth and fraction bits setting, or cli::Error naming the option.
FrameSetup setupFor(const Camera& camera, int depth, int fraction_bits) {
  FrameSetup setup;
  const CameraError camera_error = buildFrameSetup(camera, depth, fraction_bits, &setup);
  if (camera_error != CameraError::kNone) {
    throw cli::Error("--fraction-bits " + std::to_string(fraction_bits) +
                     ": the camera refuses this view at depth " + std::to_string(depth) + ": " +
                     describe(camera_error));
  }
  return setup;
}

}  // namespace

void checkDepthSweepViews(const DepthSweepOptions& options) {
  for (int depth : options.depths) {
    for (int bits : options.fraction_bits) setupFor(options.camera, depth, bits);
    setupFor(options.camera, depth, kDefaultFractionBits);  // the floating point variants' setting
  }
}

std::vector<std::string> depthSweepOutputNames() {
  return {"tradeoff.csv", "tradeoff.png", "tradeoff_reference.png"};
}

std::vector<cli::OutputFile> runDepthSweep(const Scene& scene, const DepthSweepOptions& options) {
  const Reference reference = referenceFor(scene, options.camera);
  const Repeats repeats;
  std::vector<Row> rows;
  for (int depth : options.depths) {
    const std::unique_ptr<InMemoryModel> model = prepareInMemory(scene, {depth});
    const LevelView& level = model->view->finestLevel();
    const std::size_t model_bytes = level.nodes.size() + level.leaves.size();
    Framebuffer frame(options.camera.width, options.camera.height);
    HoleFiller filler(options.camera.width);
    for (const VariantInfo& info : allVariants()) {
      // Fraction bits change nothing in a floating point variant: one run of those.
      const std::vector<int> fractions = isFixedPoint(info.variant)
                                             ? options.fraction_bits
                                             : std::vector<int>{kDefaultFractionBits};
      for (int bits : fractions) {
        FrameSetup setup = setupFor(options.camera, depth, bits);
        setup.splat =
            SplatFootprint{};  // one pixel per leaf in every variant, as they were measured
        for (bool fill : {false, true}) {
          const double ms = medianMilliseconds(
              [&] {
                frame.clear();
                if (!renderLevel(info.variant, level, setup, frame) ||
                    (fill && filler.fill(frame, bridgeDepthLimit(setup)).refused)) {
                  throw cli::Error("the frame was refused");
                }
              },
              repeats);
          rows.push_back(
              {depth, std::string(info.name), bits, fill, ms, model_bytes,
               8.0 * static_cast<double>(model_bytes) / static_cast<double>(level.leaves.size()),
               measure(reference, frame, *model->view)});
        }
      }
    }
    std::printf("depth %d done (%zu voxels)\n", depth, level.leaves.size());
    std::fflush(stdout);
  }

  std::string csv =
      "depth,variant,fraction_bits,hole_fill,ms_per_frame,model_bytes,bits_per_point,psnr_db,"
      "ssim,empty_inside_share\n";
  for (const Row& r : rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%d,%s,%d,%s,%.4f,%zu,%.3f,%.3f,%.4f,%.4f\n", r.depth,
                  r.variant.c_str(), r.fraction_bits, r.fill ? "on" : "off", r.ms_per_frame,
                  r.model_bytes, r.bits_per_point, r.quality.psnr, r.quality.ssim,
                  r.quality.empty_share);
    csv += line;
  }
  const std::vector<std::string> names = depthSweepOutputNames();
  return {{names[0], csv},
          {names[1], encodePng(drawPlot(rows))},
          {names[2], encodePng(reference.image)}};
}

}  // namespace octopoint::tradeoff
