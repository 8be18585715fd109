// Draws the two models compiled into this app side by side into one PPM image (no OpenCV needed),
// each with the one-call path: model + camera -> RGB pixels (octopoint/rgb_renderer.h).
// usage: two_models OUT.ppm
#include <cstdio>
#include <optional>
#include <vector>

#include "bottle.h"
#include "carton.h"
#include "octopoint/rgb_renderer.h"

namespace {

constexpr int kWidth = 240;
constexpr int kHeight = 180;

// Draws `embedded` turned by `yaw_degrees` into `rgb` (kWidth x kHeight x 3); returns the covered
// pixels, or -1 when the model does not validate or cannot be drawn.
int draw(const octopoint::EmbeddedModel& embedded, int yaw_degrees,
         std::vector<std::uint8_t>& rgb) {
  using namespace octopoint;
  ModelIssue issue;
  const std::optional<ModelView> model =
      ModelView::fromEmbedded(embedded, &issue);  // validated once
  if (!model) {
    std::fprintf(stderr, "two_models: model %s: %s\n", embedded.name, describe(issue.error));
    return -1;
  }
  Camera camera;
  camera.width = kWidth;
  camera.height = kHeight;
  camera.yaw = Angle::fromDegrees(yaw_degrees);
  camera.zoom = *zoomRatio(9, 10);  // a little room around the object
  DrawOptions options;
  options.fill_holes = true;  // depth auto and the fastest variant are the defaults
  RgbRenderer renderer;
  const DrawError error = renderer.draw(*model, camera, rgb, options);
  if (error != DrawError::kNone) {
    std::fprintf(stderr, "two_models: model %s: %s\n", embedded.name, describe(error));
    return -1;
  }
  int covered = 0;
  for (const std::uint32_t word : renderer.frame().pixels()) covered += word != Framebuffer::kEmpty;
  return covered;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: two_models OUT.ppm\n");
    return 1;
  }
  std::vector<std::uint8_t> left(kWidth * kHeight * 3), right(kWidth * kHeight * 3);
  const int covered_left = draw(octopoint::models::carton, 0, left);
  const int covered_right = draw(octopoint::models::bottle, 20, right);
  if (covered_left <= 0 || covered_right <= 0) {
    std::fprintf(stderr, "two_models: a model drew nothing (%d and %d pixels)\n", covered_left,
                 covered_right);
    return 1;
  }
  std::FILE* out = std::fopen(argv[1], "wb");
  if (out == nullptr) {
    std::fprintf(stderr, "two_models: cannot write %s\n", argv[1]);
    return 1;
  }
  std::fprintf(out, "P6\n%d %d\n255\n", 2 * kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y) {
    std::fwrite(&left[static_cast<std::size_t>(y) * kWidth * 3], 1, kWidth * 3, out);
    std::fwrite(&right[static_cast<std::size_t>(y) * kWidth * 3], 1, kWidth * 3, out);
  }
  const bool written = std::fclose(out) == 0;
  std::printf("two_models: %s and %s drawn (%d and %d pixels) into %s\n",
              octopoint::models::carton.name, octopoint::models::bottle.name, covered_left,
              covered_right, argv[1]);
  return written ? 0 : 1;
}
