// Draws the two models compiled into this app side by side into one PPM image (no OpenCV needed).
// usage: two_models OUT.ppm
#include <cstdio>
#include <vector>

#include "first.h"
#include "second.h"
#include "renderer/framebuffer.h"
#include "renderer/level_of_detail.h"
#include "renderer/render.h"

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// Draws `embedded` at yaw 20 degrees into `rgb` (kWidth x kHeight x 3); returns the covered pixels,
// or -1 when the model does not validate.
int draw(const octopoint::EmbeddedModel& embedded, std::vector<std::uint8_t>& rgb) {
  using namespace octopoint;
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(embedded, &issue);
  if (!model) {
    std::fprintf(stderr, "two_models: model %s: %s\n", embedded.name, describe(issue.error));
    return -1;
  }
  Camera camera;
  camera.yaw = Angle::fromDegrees(20);
  camera.width = kWidth;
  camera.height = kHeight;
  // Depth by projected size, and the fastest variant this CPU runs (footprint splats when a voxel
  // is wider than a pixel).
  const LevelView* level = autoLevel(*model, camera);
  FrameSetup setup;
  if (level == nullptr || buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    return -1;
  }
  Framebuffer frame(kWidth, kHeight);
  frame.clear();
  renderLevel(defaultVariant(), *level, setup, frame);
  resolveToRgb(frame, *model, Rgb{0, 0, 0}, rgb);
  int covered = 0;
  for (const std::uint32_t word : frame.pixels()) covered += word != Framebuffer::kEmpty;
  return covered;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: two_models OUT.ppm\n");
    return 1;
  }
  std::vector<std::uint8_t> left(kWidth * kHeight * 3), right(kWidth * kHeight * 3);
  const int covered_left = draw(octopoint::models::first, left);
  const int covered_right = draw(octopoint::models::second, right);
  if (covered_left <= 0 || covered_right <= 0) {
    std::fprintf(stderr, "two_models: a model drew nothing (%d and %d pixels)\n", covered_left, covered_right);
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
  std::printf("two_models: %s and %s drawn (%d and %d pixels) into %s\n", octopoint::models::first.name,
              octopoint::models::second.name, covered_left, covered_right, argv[1]);
  return written ? 0 : 1;
}
