// octopoint-tradeoff's common parts: the scene, in-memory models, the reference and the measures.
#include <algorithm>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli/error.h"
#include "codegen/model_writer.h"
#include "codegen/prepare_error.h"
#include "lab/image_quality.h"
#include "lab/reference_render.h"
#include "lab/tradeoff.h"

namespace octopoint::tradeoff {

Scene loadScene(const std::string& scan_path, const prepare::PrepareOptions& options,
                const SplatRule& rule) {
  Scene scene;
  scene.scan_path = scan_path;
  scene.scan = prepare::loadScan(scan_path);
  scene.prepare = options;
  scene.prepare.name = "tradeoff";
  const prepare::Scan points = prepare::modelPoints(scene.scan, scan_path, options);
  scene.fit = prepare::fitCube(points.positions, scan_path);
  scene.surface = buildReferenceSurface(points, rule);
  if (scene.surface.splat_radius.empty()) {
    std::printf("reference surface: %zu triangles over %zu points\n",
                scene.surface.triangles.size(), points.positions.size());
  } else {
    std::vector<float> radius = scene.surface.splat_radius;
    std::nth_element(radius.begin(),
                     radius.begin() + static_cast<std::ptrdiff_t>(radius.size() / 2), radius.end());
    std::printf("reference surface: %zu splats, median radius %.3g (cube edge %.3g)\n",
                radius.size(), static_cast<double>(radius[radius.size() / 2]), scene.fit.edge);
  }
  std::fflush(stdout);
  return scene;
}

std::unique_ptr<InMemoryModel> prepareInMemory(const Scene& scene, const std::vector<int>& depths,
                                               bool dense_only) {
  prepare::PrepareOptions options = scene.prepare;
  options.depths = depths;
  options.stop_at_sparse_depth = dense_only;
  auto model = std::make_unique<InMemoryModel>();
  model->bytes =
      prepare::serializeModel(prepare::prepareModel(scene.scan, scene.scan_path, options));
  ModelIssue issue;
  model->view = ModelView::fromBytes(model->bytes, &issue);
  if (!model->view)
    throw prepare::PrepareError(std::string("model prepared in memory: ") + describe(issue.error));
  return model;
}

Reference referenceFor(const Scene& scene, const Camera& camera) {
  Reference reference;
  reference.image =
      renderReference(scene.surface, scene.fit, camera, kBackground, &reference.silhouette);
  return reference;
}

std::string encodePng(const cv::Mat& image) {
  std::vector<std::uint8_t> png;
  if (!cv::imencode(".png", image, png)) throw cli::Error("cannot encode a PNG");
  return {png.begin(), png.end()};
}

cv::Mat toImage(const Framebuffer& frame, const ModelView& model) {
  cv::Mat rgb(frame.height(), frame.width(), CV_8UC3);
  // The image is made for the frame: resolveToRgb cannot refuse it.
  static_cast<void>(resolveToRgb(frame, model, kBackground, {rgb.data, rgb.total() * 3}));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

Quality measure(const Reference& reference, const Framebuffer& frame, const ModelView& model) {
  return measure(reference, frame, toImage(frame, model));
}

Quality measure(const Reference& reference, const Framebuffer& frame, const cv::Mat& drawn) {
  const cv::Mat regions = silhouetteRegions(reference.silhouette);
  std::int64_t object = 0, empty = 0, inner = 0, inner_empty = 0;
  for (int y = 0; y < frame.height(); ++y) {
    const std::uint8_t* inside = reference.silhouette.ptr<std::uint8_t>(y);
    const std::uint8_t* region = regions.ptr<std::uint8_t>(y);
    for (int x = 0; x < frame.width(); ++x) {
      const bool hole = !frame.covered(x, y);
      const bool deep = region[x] == static_cast<std::uint8_t>(Region::kInterior);
      object += inside[x] != 0;
      empty += inside[x] != 0 && hole;
      inner += deep;
      inner_empty += deep && hole;
    }
  }
  auto share = [](std::int64_t part, std::int64_t whole) {
    return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
  };
  return {psnr(reference.image, drawn), ssim(reference.image, drawn), share(empty, object),
          share(inner_empty, inner), splitSquaredError(reference.image, drawn, regions)};
}

}  // namespace octopoint::tradeoff
