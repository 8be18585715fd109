// The manual's first example (octopoint/octopoint.h): the default model compiled into the library,
// drawn to RGB pixels in one call, and written as a PPM image when a path is given.
// usage: draw_rgb [OUT.ppm]
#include <cstdint>
#include <cstdio>
#include <optional>
#include <vector>

#include "octopoint/octopoint.h"

int main(int argc, char** argv) {
  using namespace octopoint;
  // Validate once: the view checks every byte, so drawing may trust it.
  ModelIssue issue;
  const EmbeddedModel& embedded = *models::defaultModel();  // const arrays in the library
  const std::optional<ModelView> model = ModelView::fromEmbedded(embedded, &issue);
  if (!model) {
    std::fprintf(stderr, "draw_rgb: %s\n", describe(issue.error));
    return 1;
  }

  Camera camera;  // 320x240, frontal, the model's cube across the shorter side
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = *zoomRatio(3, 2);  // 1.5x: the ratio is in range, so it has a value
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width) * camera.height * 3);

  RgbRenderer renderer;  // owns the frame: allocates on the first draw, then never at this size
  const DrawError error = renderer.draw(*model, camera, rgb, {.fill_holes = true});
  if (error != DrawError::kNone) {
    std::fprintf(stderr, "draw_rgb: %s\n", describe(error));
    return 1;
  }

  int covered = 0;
  for (const std::uint32_t word : renderer.frame().pixels()) covered += word != FrameView::kEmpty;
  std::printf("draw_rgb: %s at depth %d, %d of %d pixels covered\n", embedded.name,
              renderer.drawnDepth(), covered, camera.width * camera.height);
  if (argc > 1) {
    std::FILE* out = std::fopen(argv[1], "wb");
    if (out == nullptr) return 1;
    std::fprintf(out, "P6\n%d %d\n255\n", camera.width, camera.height);
    const bool written = std::fwrite(rgb.data(), 1, rgb.size(), out) == rgb.size();
    if (std::fclose(out) != 0 || !written) return 1;
  }
  return covered > 0 ? 0 : 1;
}
