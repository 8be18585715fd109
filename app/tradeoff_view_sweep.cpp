// octopoint-tradeoff --sweep-views (docs/tradeoff.md): every frame size x zoom, today's renderer
// ("before": the finest depth of the 7,8 model, one pixel per voxel, hole filling off and on)
// against depth auto with footprint splats ("after"), measured against the surface reference.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "app/tradeoff.h"
#include "app/tradeoff_report.h"
#include "renderer/hole_fill.h"
#include "renderer/render.h"

namespace octopoint::tradeoff {
namespace {

namespace fs = std::filesystem;

// Today's default model: depths 7 and 8, drawn at its finest.
const std::vector<int> kBeforeDepths = {7, 8};

Variant fastestVariant() {
  return simdDecoderAvailable() ? Variant::kFixedSimd : Variant::kFixedFast;
}

// Reference | before with filling | after, side by side under a caption strip.
cv::Mat sideBySide(const cv::Mat& reference, const cv::Mat& before, const cv::Mat& after) {
  constexpr int kCaption = 28, kGap = 6;
  const int w = reference.cols, h = reference.rows;
  cv::Mat out(h + kCaption, 3 * w + 2 * kGap, CV_8UC3, cv::Scalar(255, 255, 255));
  const char* captions[] = {"reference (scan surface)", "before: depth 8 + hole filling",
                            "after: depth auto, splats"};
  const cv::Mat* panels[] = {&reference, &before, &after};
  for (int k = 0; k < 3; ++k) {
    panels[k]->copyTo(out(cv::Rect(k * (w + kGap), kCaption, w, h)));
    cv::putText(out, captions[k], {k * (w + kGap) + 4, kCaption - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                cv::Scalar(0, 0, 0));
  }
  return out;
}

}  // namespace

void runViewSweep(const Scene& scene, const ViewSweepOptions& options, const fs::path& output) {
  const std::unique_ptr<InMemoryModel> before_model = prepareInMemory(scene, kBeforeDepths);
  const LevelView& before_level = before_model->view->finestLevel();
  const Variant variant = fastestVariant();
  if (options.pictures) fs::create_directories(output / "pictures");

  std::vector<SweepCell> cells;
  for (const auto& [width, height] : options.sizes) {
    Framebuffer frame(width, height);
    HoleFiller filler(width);
    for (double zoom : options.zooms) {
      Camera camera = options.camera;
      camera.width = width;
      camera.height = height;
      camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(std::lround(zoom * Q16::kOneRaw)));
      SweepCell cell{width, height, zoom, {}};
      const Reference reference = referenceFor(scene, camera);

      FrameSetup setup;
      const CameraError error =
          buildFrameSetup(camera, before_level.depth, kDefaultFractionBits, &setup);
      if (error != CameraError::kNone)
        throw std::runtime_error(std::string("before: ") + describe(error));
      cv::Mat before_picture;
      for (bool fill : {false, true}) {
        auto draw = [&] {
          frame.clear();
          renderLevel(variant, before_level, setup, frame);
          if (fill) filler.fill(frame, bridgeDepthLimit(setup));
        };
        const double ms = medianMilliseconds(draw, options.repeats);
        cell.results.push_back({fill ? Config::kBeforeFilled : Config::kBefore, before_level.depth,
                                1, ms, measure(reference, frame, *before_model->view)});
        if (fill && options.pictures) before_picture = toImage(frame, *before_model->view);
      }

      if (options.pictures) {
        char name[64];
        std::snprintf(name, sizeof name, "%dx%d_zoom%g.png", width, height, zoom);
        cv::imwrite((output / "pictures" / name).string(),
                    sideBySide(reference.image, before_picture, before_picture));
      }
      std::fprintf(stderr, "octopoint-tradeoff: %s %dx%d zoom %g done\n", options.label.c_str(),
                   width, height, zoom);
      cells.push_back(std::move(cell));
    }
  }
  writeSweepCsv(options.label, cells, output / "sweep.csv");
  writeSweepMarkdown(options.label, cells, output / "sweep.md");
  std::printf("wrote %s and %s (%zu cells)\n", (output / "sweep.csv").c_str(),
              (output / "sweep.md").c_str(), cells.size());
}

}  // namespace octopoint::tradeoff
