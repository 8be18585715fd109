// The dual-resolution renderer of an installed octopoint::interactive (tests/package/main.cpp).
#include <chrono>

#include "octopoint/interactive.h"

int dualResolutionDepth(const octopoint::ModelView& model) {
  using namespace octopoint;
  const SteadyClock clock;
  DualResolutionRenderer dual(model, clock, InteractiveConfig{});
  const bool drawn = dual.waitUntil(
      [](const RendererStatus& status) { return status.fine_shown > 0; }, std::chrono::seconds(30));
  FrameInfo info;
  if (!drawn || dual.acquireLatest(&info) == nullptr) return 0;
  return info.depth;
}
