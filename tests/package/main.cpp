// Uses one thing from each library of the installed package, so that each must link: fixed-point
// sines (octopoint::fixedpoint), the default model (octopoint::models), the one-call RGB path
// (octopoint::renderer) and a frame of the dual-resolution renderer (octopoint::interactive).
// Prints one line that tests/package_test.cmake checks; exits 1 on any failure.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <vector>

#include "fixedpoint/trig.h"
#include "octopoint/models.h"
#include "octopoint/interactive.h"
#include "octopoint/rgb_renderer.h"

int main() {
  using namespace octopoint;
  const std::int32_t sine = sinQ30(Angle::fromDegrees(90));  // Q2.30: 1.0 is 1 << 30
  if (sine != std::int32_t{1} << 30) {
    std::fprintf(stderr, "package_consumer: sin(90 degrees) is %d in Q2.30\n", sine);
    return 1;
  }

  const EmbeddedModel* embedded = models::defaultModel();
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*embedded, &issue);
  if (!model) {
    std::fprintf(stderr, "package_consumer: model %s: %s\n", embedded->name, describe(issue.error));
    return 1;
  }

  Camera camera;  // 320x240, frontal
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width) * camera.height * 3);
  RgbRenderer renderer;
  if (const DrawError error = renderer.draw(*model, camera, rgb); error != DrawError::kNone) {
    std::fprintf(stderr, "package_consumer: draw: %s\n", describe(error));
    return 1;
  }
  int covered = 0;
  for (const std::uint32_t word : renderer.frame().pixels()) covered += word != Framebuffer::kEmpty;

  const SteadyClock clock;
  const InteractiveConfig config;
  DualResolutionRenderer dual(*model, clock, config);
  const bool drawn = dual.waitUntil(
      [](const RendererStatus& status) { return status.fine_shown > 0; }, std::chrono::seconds(30));
  FrameInfo info;
  if (!drawn || dual.acquireLatest(&info) == nullptr) {
    std::fprintf(stderr, "package_consumer: the dual-resolution renderer drew no frame in 30 s\n");
    return 1;
  }
  std::printf(
      "package_consumer: model %s, %d pixels covered, dual-resolution frame %dx%d at depth %d\n",
      embedded->name, covered, info.width, info.height, info.depth);
  return covered > 0 ? 0 : 1;
}
