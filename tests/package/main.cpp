// An outside program that reads octopoint/octopoint.h alone (the manual) and draws: a rotation
// from integer angles (octopoint::fixedpoint), the default model (octopoint::models), a frame to
// RGB in one call (octopoint::renderer). Where the package exports them, interactive_frame.cpp
// draws a frame with the dual-resolution renderer (octopoint::interactive) and net_url.cpp parses
// a URL (octopoint::net). Prints one line that tests/package_test.cmake checks; exits 1 on any
// failure.
#include <cstdint>
#include <cstdio>
#include <optional>
#include <vector>

#include "octopoint/octopoint.h"

#if defined(CONSUMER_HAS_INTERACTIVE)
// interactive_frame.cpp: the depth of a dual-resolution frame of `model`, 0 when none came.
int dualResolutionDepth(const octopoint::ModelView& model);
#endif
#if defined(CONSUMER_HAS_NET)
// net_url.cpp: whether octopoint::net parses a URL.
bool parsesUrl();
#endif

int main() {
  using namespace octopoint;
  // A yaw of 90 degrees maps x to -z, exactly (Q1.30: 1.0 is 1 << 30).
  const Rotation turn = rotationFromYawPitchRoll(Angle::fromDegrees(90), Angle{}, Angle{});
  if (turn.m_q30[2][0] != -(std::int32_t{1} << 30)) {
    std::fprintf(stderr, "package_consumer: a quarter turn is not exact\n");
    return 1;
  }

  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  if (!model) {
    std::fprintf(stderr, "package_consumer: %s\n", describe(issue.error));
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
  for (const std::uint32_t word : renderer.frame().pixels()) covered += word != FrameView::kEmpty;
  std::printf("package_consumer: model %s, %d pixels covered at depth %d",
              models::defaultModel()->name, covered, renderer.drawnDepth());
#if defined(CONSUMER_HAS_INTERACTIVE)
  const int depth = dualResolutionDepth(*model);
  if (depth == 0) {
    std::fprintf(stderr,
                 "\npackage_consumer: the dual-resolution renderer drew no frame in 30 s\n");
    return 1;
  }
  std::printf(", dual-resolution frame at depth %d", depth);
#endif
#if defined(CONSUMER_HAS_NET)
  if (!parsesUrl()) {
    std::fprintf(stderr, "\npackage_consumer: octopoint::net refused a good URL\n");
    return 1;
  }
  std::printf(", URL parsed");
#endif
  std::printf("\n");
  return covered > 0 ? 0 : 1;
}
