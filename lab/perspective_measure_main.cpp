// octopoint-perspective-measure: the walk-through measurements of docs/perspective.md for one view
// (lab/perspective_measure.h), at one or more frame sizes, as CSV on stdout.
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "lab/perspective_measure.h"
#include "tools/model_source.h"
#include "tools/png_file.h"
#include "tools/scan_eye.h"

namespace {

using namespace octopoint;

constexpr const char* kUsage =
    R"(usage: octopoint-perspective-measure [--model NAME | --file M.oct] --eye X,Y,Z [options]

Draws the perspective view from the eye as octopoint-render --eye draws it (detail by distance,
occlusion culling) and measures, per frame size, one CSV row on stdout (docs/perspective.md,
"Walk-through views"):
  leaves             the voxels the frame's walks hand over
  max_position_px    the largest distance of one whose splat reaches the screen from its
                     centre's double-precision projection
  silhouette_pixels  the pixels the same voxels cover drawn in double precision (each the convex
                     hull of its 8 projected corners, a pixel where its centre lies inside)
  empty_share        the share of those the frame leaves empty (docs/tradeoff.md's metric)
  near_voxels        voxels left out of the silhouette: they reach behind the near plane
  covered_pixels     the frame's covered pixels
  points_unculled, points_culled   points handed to the plot without and with occlusion culling
  per_pixel_unculled, per_pixel_culled   the same per covered pixel
  perspective_ms, orthographic_ms, time_ratio   median thread CPU time of --rounds frames each,
                     interleaved, clear included: the view, and the orthographic frame of the same
                     screen as octopoint-render draws it (fixed_fast, yaw 0, pitch 0, zoom 1, depth
                     auto)
  orthographic_depth, orthographic_leaves   its depth and leaves
  per_point_ratio    the view's time per point (culled) over the orthographic frame's per leaf
  depths             the stored depths the view chose among
  max_position_all_px  max_position_px over every leaf handed over, those wholly off the screen
                     (which draw nothing) included

  --model NAME        an embedded model (default: the default model)
  --file M.oct        a model file (not chunked)
  --eye X,Y,Z         the eye in the scan's own units and axes (octopoint-render --info: cube)
  --look YAW,PITCH[,ROLL]  degrees (default 0,0)
  --fov DEG           vertical field of view, 10..120 (default 60)
  --near D            the near plane in scan units (default, as octopoint-render's, half the
                      voxel edge of the model's finest depth)
  --size WxH          a frame size (repeatable; default 320x240, 640x480 and 1280x960)
  --rounds N          timed frames of each kind, 0..1000 (default 5; 0: no timing)
  --pictures PREFIX   also write PREFIX_WxH.png (the frame) and PREFIX_WxH_empty.png (the
                      silhouette's pixels the frame leaves empty in red, the rest of it grey)
  -h, --help          show this help
)";

// The largest frame measured: its silhouette and colours are held whole.
constexpr std::int64_t kMaxMeasuredPixels = std::int64_t{4096} * 4096;

struct Options {
  ModelSourceOptions source;
  std::string eye_text;
  Look look{};
  Angle fov = Angle::fromDegrees(60);
  std::optional<double> near;
  std::vector<cli::FrameSize> sizes;
  int rounds = 5;
  std::string pictures;
};

Options parseOptions(int argc, char** argv) {
  Options options;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (parseModelSourceOption(args, options.source)) {
    } else if (args.is("--eye")) {
      options.eye_text = args.value();
      static_cast<void>(parseScanPoint("--eye", options.eye_text));
    } else if (args.is("--look")) {
      options.look = parseLook(args.name(), args.value());
    } else if (args.is("--fov")) {
      options.fov = cli::parseDegrees(args.name(), args.value());
    } else if (args.is("--near")) {
      options.near = cli::parseReal(args.name(), args.value(), 1e-12, kMaxEyeCoordinate);
    } else if (args.is("--size")) {
      options.sizes.push_back(
          cli::parseFrameSize(args.name(), args.value(), 1, kMaxViewportSide, kMaxMeasuredPixels));
    } else if (args.is("--rounds")) {
      options.rounds = cli::parseInt(args.name(), args.value(), 0, 1000);
    } else if (args.is("--pictures")) {
      options.pictures = args.value();
      if (options.pictures.empty()) throw cli::Error("--pictures: empty prefix");
    } else {
      args.refuseUnknown();
    }
  }
  checkOneModelSource(options.source);
  if (!options.source.url.empty()) throw cli::Error("--url: measure a model file (--file)");
  if (options.eye_text.empty()) throw cli::Error("--eye X,Y,Z is required (see --help)");
  if (options.sizes.empty()) options.sizes = {{320, 240}, {640, 480}, {1280, 960}};
  return options;
}

void writePictures(const std::string& prefix, int width, int height,
                   const std::vector<std::uint8_t>& rgb,
                   const std::vector<std::uint8_t>& silhouette,
                   const std::vector<std::uint8_t>& empty) {
  cv::Mat frame(height, width, CV_8UC3), holes(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                            static_cast<std::size_t>(x);
      frame.at<cv::Vec3b>(y, x) = {rgb[3 * i + 2], rgb[3 * i + 1], rgb[3 * i]};  // BGR
      holes.at<cv::Vec3b>(y, x) = empty[i]        ? cv::Vec3b{0, 0, 230}
                                  : silhouette[i] ? cv::Vec3b{170, 170, 170}
                                                  : cv::Vec3b{255, 255, 255};
    }
  }
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  writePng(prefix + "_" + size + ".png", frame);
  writePng(prefix + "_" + size + "_empty.png", holes);
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  const std::unique_ptr<LoadedModel> loaded =
      loadModel(options.source.model_name, options.source.model_file);
  const ModelView& model = *loaded->view;
  const std::optional<ScanCube> cube = scanCube(model.cubePlacement());
  if (!cube) throw cli::Error(loaded->label + ": the model records no cube placement (--eye)");
  const ScanPoint eye = parseScanPoint("--eye", options.eye_text);
  std::printf(
      "width,height,leaves,max_position_px,silhouette_pixels,empty_share,near_voxels,"
      "covered_pixels,points_unculled,points_culled,per_pixel_unculled,per_pixel_culled,"
      "perspective_ms,orthographic_ms,time_ratio,orthographic_depth,orthographic_leaves,"
      "per_point_ratio,depths,max_position_all_px\n");
  for (const cli::FrameSize& size : options.sizes) {
    const PerspectiveView view = scanEyeView(*cube, eye, options.look, options.fov,
                                             modelNearPlane(model, options.near, "--near"),
                                             size.width, size.height, "--eye");
    std::vector<std::uint8_t> rgb, silhouette;
    const lab::PerspectiveMeasurement m =
        lab::measurePerspective(model, view, options.rounds, &rgb, &silhouette);
    if (m.depths.empty()) throw cli::Error(loaded->label + ": no depth this build draws");
    const auto per_pixel = [&](std::uint64_t points) {
      return m.covered_pixels == 0
                 ? 0.0
                 : static_cast<double>(points) / static_cast<double>(m.covered_pixels);
    };
    const double time_ratio = m.orthographic_ms > 0 ? m.perspective_ms / m.orthographic_ms : 0;
    const double per_point_ratio = m.points_culled == 0
                                       ? 0
                                       : time_ratio * static_cast<double>(m.orthographic_leaves) /
                                             static_cast<double>(m.points_culled);
    std::string depths;
    for (const int depth : m.depths) {
      if (!depths.empty()) depths.push_back(' ');
      depths.append(std::to_string(depth));
    }
    std::printf(
        "%d,%d,%llu,%.4f,%llu,%.5f,%llu,%llu,%llu,%llu,%.3f,%.3f,%.3f,%.3f,%.2f,%d,%llu,%.2f,%s,"
        "%.4f\n",
        size.width, size.height, static_cast<unsigned long long>(m.leaves), m.max_position_px,
        static_cast<unsigned long long>(m.silhouette_pixels), m.emptyShare(),
        static_cast<unsigned long long>(m.near_voxels),
        static_cast<unsigned long long>(m.covered_pixels),
        static_cast<unsigned long long>(m.points_unculled),
        static_cast<unsigned long long>(m.points_culled), per_pixel(m.points_unculled),
        per_pixel(m.points_culled), m.perspective_ms, m.orthographic_ms, time_ratio,
        m.orthographic_depth, static_cast<unsigned long long>(m.orthographic_leaves),
        per_point_ratio, depths.c_str(), m.max_position_all_px);
    std::fflush(stdout);
    if (!options.pictures.empty()) {
      std::vector<std::uint8_t> empty(silhouette.size());
      for (std::size_t i = 0; i < rgb.size() / 3; ++i) {
        const bool covered = rgb[3 * i] != 236 || rgb[3 * i + 1] != 236 || rgb[3 * i + 2] != 240;
        empty[i] = silhouette[i] != 0 && !covered;
      }
      writePictures(options.pictures, size.width, size.height, rgb, silhouette, empty);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-perspective-measure", argc, argv, run);
}
