// The cost of scanline hole filling on the default model at 320x240, and what it closes.
// Counters: holes_before / holes_after are the empty pixels inside the object (window 4,
// docs/holefill.md) before and after filling, filled_pixels what the pass wrote.
// The frame is restored from the unfilled copy outside the timed region.
#include <benchmark/benchmark.h>

#include <string>

#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint {
namespace {

constexpr std::int32_t kInsideWindow = 4;

void fillDefaultModel(benchmark::State& state, int depth, int yaw_degrees, int zoom) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  const LevelView* level = model ? model->levelOfDepth(depth) : nullptr;
  Camera camera;
  camera.yaw = Angle::fromDegrees(yaw_degrees);
  camera.zoom = Q16::fromRaw(zoom * Q16::kOneRaw);
  FrameSetup setup;
  if (level == nullptr ||
      buildFrameSetup(camera, depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    state.SkipWithError("no such depth, or camera refused");
    return;
  }
  Framebuffer unfilled(camera.width, camera.height);
  unfilled.clear();
  if (!renderLevel(Variant::kFixedBaseline, *level, setup, unfilled)) {
    state.SkipWithError("renderLevel refused");
    return;
  }
  Framebuffer frame = unfilled;
  HoleFiller filler(camera.width);
  const std::int32_t limit = bridgeDepthLimit(setup);
  HoleFillCounts counts;
  for (auto _ : state) {
    state.PauseTiming();
    frame = unfilled;  // same size: copies, no allocation
    state.ResumeTiming();
    counts = filler.fill(frame, limit);
    benchmark::DoNotOptimize(frame.pixels().data());
    benchmark::ClobberMemory();
  }
  state.counters["holes_before"] = countEnclosedEmptyPixels(unfilled, unfilled, kInsideWindow);
  state.counters["holes_after"] = countEnclosedEmptyPixels(unfilled, frame, kInsideWindow);
  state.counters["filled_pixels"] = counts.total();
}

}  // namespace

void registerAll() {
  struct View {
    int depth, yaw_degrees, zoom;
  };
  for (const View view : {View{8, 30, 2}, View{8, 30, 1}, View{7, 30, 1}}) {
    const std::string name = "hole_fill/tabletop/depth" + std::to_string(view.depth) + "/yaw" +
                             std::to_string(view.yaw_degrees) + "_zoom" + std::to_string(view.zoom);
    benchmark::RegisterBenchmark(name.c_str(), fillDefaultModel, view.depth, view.yaw_degrees,
                                 view.zoom)
        ->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace octopoint
