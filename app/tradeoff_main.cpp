// octopoint-tradeoff: sweeps the speed/accuracy trade for one scan (docs/tradeoff.md): depth,
// decoder variant, fraction bits and hole filling; writes a CSV row per configuration and a plot of
// time against quality.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "app/image_quality.h"
#include "app/reference_render.h"
#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/output_file.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "codegen/cube_fit.h"
#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "codegen/prepare_error.h"
#include "renderer/hole_fill.h"
#include "renderer/render.h"

namespace {

namespace fs = std::filesystem;
using namespace octopoint;

constexpr const char* kUsage = R"(usage: octopoint-tradeoff SCAN [options]

Measures the speed/accuracy trade of octopoint on one scan: for every depth, decoder variant,
fraction bits and hole filling on/off it renders one view and records the time per frame, the
model size and the quality against a dense double precision render of the scan's own points
(docs/tradeoff.md defines it). Writes OUTDIR/tradeoff.csv and OUTDIR/tradeoff.png.

  --axes y-down|y-up     the scan's axes (as octopoint-prepare; default y-down)
  --crop X0,Y0,Z0,X1,Y1,Z1  keep the points inside this box (as octopoint-prepare)
  --yaw DEG, --pitch DEG the view, |DEG| <= 1e6 (default 0, 0)
  --size WxH             framebuffer size, each side 1..8192, at most 16777216 pixels
                         (default 320x240)
  --depths LIST          octree depths, strictly ascending, each 1..16 (default 6,7,8,9,10)
  --fraction-bits LIST   fixed-point fraction bits of the positions, strictly ascending, each
                         1..24 (default 8,12,15,20); a setting the camera refuses for this view
                         (too few integer bits for the frame) is an error
  -o, --output OUTDIR    where to write (default out); the three files appear together at the
                         end or not at all, and existing ones must be regular files
  -h, --help             show this help

SCAN is a regular file of at most 1 GiB. On any error prints one line on stderr and exits with
status 1, writing nothing.
)";

constexpr Rgb kBackground{236, 236, 240};
// What the sweep writes into OUTDIR, all together at the end or nothing.
constexpr const char* kOutputNames[] = {"tradeoff.csv", "tradeoff.png", "tradeoff_reference.png"};
constexpr double kMinSecondsPerConfiguration = 0.05;
constexpr int kMaxFramesPerConfiguration = 200;

struct Options {
  std::string scan;
  prepare::PrepareOptions prepare;
  Camera camera;
  std::vector<int> depths = {6, 7, 8, 9, 10};
  std::vector<int> fraction_bits = {8, 12, 15, 20};
  fs::path output = "out";
};

struct Row {
  int depth;
  std::string variant;
  int fraction_bits;
  bool fill;
  double ms_per_frame;
  std::size_t model_bytes;
  double bits_per_point;
  double psnr;
  double ssim;
  double empty_inside;  // share of the reference's object pixels left empty
};

// The largest frame the sweep draws: the same cap as octopoint-render's images.
constexpr std::int64_t kMaxFramePixels = std::int64_t{4096} * 4096;

Options parseOptions(int argc, char** argv) {
  Options options;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << kUsage;
      std::exit(0);
    } else if (args.is("--axes")) {
      options.prepare.axes = cli::parseChoice(args.name(), args.value(), {"y-down", "y-up"}) == 0
                                 ? prepare::ScanAxes::kYDown
                                 : prepare::ScanAxes::kYUp;
    } else if (args.is("--crop")) {
      options.prepare.crop = prepare::parseCropBox(args.name(), args.value());
    } else if (args.is("--yaw")) {
      options.camera.yaw = cli::parseDegrees(args.name(), args.value());
    } else if (args.is("--pitch")) {
      options.camera.pitch = cli::parseDegrees(args.name(), args.value());
    } else if (args.is("--size")) {
      const cli::FrameSize size =
          cli::parseFrameSize(args.name(), args.value(), 1, kMaxViewportSide, kMaxFramePixels);
      options.camera.width = size.width;
      options.camera.height = size.height;
    } else if (args.is("--depths")) {
      options.depths = cli::parseIntList(args.name(), args.value(), 1, format::kMaxDepth, format::kMaxDepth,
                                         cli::ListOrder::kStrictlyAscending);
    } else if (args.is("--fraction-bits")) {
      options.fraction_bits = cli::parseIntList(args.name(), args.value(), kMinFractionBits, kMaxFractionBits,
                                                kMaxFractionBits, cli::ListOrder::kStrictlyAscending);
    } else if (args.is("-o") || args.is("--output")) {
      options.output = args.value();
    } else if (args.isPlain() && options.scan.empty()) {
      options.scan = args.current();
    } else {
      args.refuseUnknown();
    }
  }
  if (options.scan.empty()) throw cli::Error("no SCAN given (see --help)");
  std::error_code error;
  if (fs::exists(options.output, error) && !fs::is_directory(options.output, error)) {
    throw cli::Error(cli::displayPath(options.output) + ": the output path exists and is not a directory");
  }
  for (const char* name : kOutputNames) cli::checkOutputFile(options.output / name);
  return options;
}

cv::Mat toImage(const Framebuffer& frame, const ModelView& model) {
  cv::Mat rgb(frame.height(), frame.width(), CV_8UC3);
  resolveToRgb(frame, model, kBackground, {rgb.data, rgb.total() * 3});
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

// Median milliseconds per frame over repeated frames (at least kMinSecondsPerConfiguration).
template <typename DrawFrame>
double medianMilliseconds(DrawFrame draw) {
  std::vector<double> times;
  const auto start = std::chrono::steady_clock::now();
  do {
    const auto before = std::chrono::steady_clock::now();
    draw();
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - before).count());
  } while (static_cast<int>(times.size()) < kMaxFramesPerConfiguration &&
           std::chrono::steady_clock::now() - start < std::chrono::duration<double>(kMinSecondsPerConfiguration));
  std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
  return times[times.size() / 2];
}

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
    min_psnr = std::min(min_psnr, r->psnr);
    max_psnr = std::max(max_psnr, r->psnr);
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
    cv::putText(plot, label, {p.x - 20, kHeight - kMargin + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black);
  }
  for (double db = psnr_low; db <= psnr_high; db += 5) {
    const cv::Point p = at(std::pow(10.0, log_low), db);
    cv::line(plot, p, {kWidth - kMargin, p.y}, grey);
    cv::putText(plot, std::to_string(static_cast<int>(db)) + " dB", {10, p.y + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black);
  }
  cv::putText(plot, "time per frame (log scale)", {kWidth / 2 - 110, kHeight - 20}, cv::FONT_HERSHEY_SIMPLEX, 0.6, black);
  cv::putText(plot, "PSNR against the dense reference; dot: hole filling on, ring: off, x: floating point",
              {kMargin, 30}, cv::FONT_HERSHEY_SIMPLEX, 0.5, black);
  const cv::Scalar depth_colour[] = {{180, 119, 31}, {14, 127, 255}, {44, 160, 44}, {40, 39, 214}, {189, 103, 148}, {75, 86, 140}};
  for (const Row* r : shown) {
    const cv::Scalar colour = depth_colour[static_cast<std::size_t>(std::clamp(r->depth - 6, 0, 5))];
    if (r->variant.rfind("float_", 0) == 0) cv::drawMarker(plot, at(r->ms_per_frame, r->psnr), colour, cv::MARKER_TILTED_CROSS, 9);
    else cv::circle(plot, at(r->ms_per_frame, r->psnr), r->fill ? 5 : 4, colour, r->fill ? cv::FILLED : 1);
  }
  for (int d = 0; d < 5; ++d) {
    cv::circle(plot, {kWidth - 150, kHeight - kMargin - 120 + 22 * d}, 5, depth_colour[d], cv::FILLED);
    cv::putText(plot, "depth " + std::to_string(d + 6), {kWidth - 135, kHeight - kMargin - 115 + 22 * d},
                cv::FONT_HERSHEY_SIMPLEX, 0.5, black);
  }
  return plot;
}

std::string encodePng(const cv::Mat& image) {
  std::vector<std::uint8_t> png;
  if (!cv::imencode(".png", image, png)) throw cli::Error("cannot encode a PNG");
  return {png.begin(), png.end()};
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  const prepare::Scan scan = prepare::loadScan(options.scan);
  const prepare::Scan points = prepare::modelPoints(scan, options.scan, options.prepare);
  const prepare::CubeFit fit = prepare::fitCube(points.positions, options.scan);
  cv::Mat object_mask;
  const cv::Mat reference = tradeoff::renderReference(points, fit, options.camera, kBackground, &object_mask);
  const double object_pixels = std::max(1, cv::countNonZero(object_mask));

  std::vector<Row> rows;
  for (int depth : options.depths) {
    prepare::PrepareOptions prepare_options = options.prepare;
    prepare_options.name = "tradeoff";
    prepare_options.depths = {depth};
    const std::vector<std::uint8_t> image =
        prepare::serializeModel(prepare::prepareModel(scan, options.scan, prepare_options));
    ModelIssue issue;
    const std::optional<ModelView> model = ModelView::fromBytes(image, &issue);
    if (!model) throw prepare::PrepareError(std::string("model at depth ") + std::to_string(depth) + ": " + describe(issue.error));
    const LevelView& level = model->finestLevel();
    const std::size_t model_bytes = level.nodes.size() + level.leaves.size();
    Framebuffer frame(options.camera.width, options.camera.height);
    HoleFiller filler(options.camera.width);
    for (const VariantInfo& info : allVariants()) {
      // Fraction bits change nothing in a floating point variant: one run of those.
      const std::vector<int> fractions = isFixedPoint(info.variant) ? options.fraction_bits : std::vector<int>{kDefaultFractionBits};
      for (int bits : fractions) {
        FrameSetup setup;
        const CameraError camera_error = buildFrameSetup(options.camera, depth, bits, &setup);
        if (camera_error != CameraError::kNone) {
          throw cli::Error("--fraction-bits " + std::to_string(bits) + ": the camera refuses this view at depth " +
                           std::to_string(depth) + ": " + describe(camera_error));
        }
        for (bool fill : {false, true}) {
          const double ms = medianMilliseconds([&] {
            frame.clear();
            renderLevel(info.variant, level, setup, frame);
            if (fill) filler.fill(frame, bridgeDepthLimit(setup));
          });
          const cv::Mat drawn = toImage(frame, *model);
          int empty_inside = 0;
          for (int y = 0; y < frame.height(); ++y)
            for (int x = 0; x < frame.width(); ++x)
              empty_inside += object_mask.at<std::uint8_t>(y, x) != 0 && !frame.covered(x, y);
          rows.push_back({depth, std::string(info.name), bits, fill, ms, model_bytes,
                          8.0 * static_cast<double>(model_bytes) / static_cast<double>(level.leaves.size()),
                          tradeoff::psnr(reference, drawn), tradeoff::ssim(reference, drawn),
                          empty_inside / object_pixels});
        }
      }
    }
    std::fprintf(stderr, "octopoint-tradeoff: depth %d done (%zu voxels)\n", depth, level.leaves.size());
  }

  std::string csv =
      "depth,variant,fraction_bits,hole_fill,ms_per_frame,model_bytes,bits_per_point,psnr_db,ssim,empty_inside_share\n";
  for (const Row& r : rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%d,%s,%d,%s,%.4f,%zu,%.3f,%.3f,%.4f,%.4f\n", r.depth, r.variant.c_str(),
                  r.fraction_bits, r.fill ? "on" : "off", r.ms_per_frame, r.model_bytes, r.bits_per_point, r.psnr,
                  r.ssim, r.empty_inside);
    csv += line;
  }
  cli::writeFilesAtomically(options.output, {{kOutputNames[0], csv},
                                             {kOutputNames[1], encodePng(drawPlot(rows))},
                                             {kOutputNames[2], encodePng(reference)}});
  std::printf("wrote %s and %s (%zu configurations)\n", (options.output / "tradeoff.csv").c_str(),
              (options.output / "tradeoff.png").c_str(), rows.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return octopoint::cli::runTool("octopoint-tradeoff", argc, argv, run); }
