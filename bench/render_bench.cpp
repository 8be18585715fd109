// Frame rendering speed of the embedded default model, per variant, depth and view, at 320x240.
// Counters: points/s and ns/point over the leaves decoded per frame.
#include <benchmark/benchmark.h>

#include "models/registry.h"
#include "renderer/camera.h"
#include "renderer/framebuffer.h"
#include "renderer/render.h"

namespace octopoint {
namespace {

void renderDefaultModel(benchmark::State& state, Variant variant, int depth, int yaw_degrees) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  const LevelView* level = model ? model->levelOfDepth(depth) : nullptr;
  if (level == nullptr) {
    state.SkipWithError("default model has no such depth");
    return;
  }
  Camera camera;
  camera.yaw = Angle::fromDegrees(yaw_degrees);
  FrameSetup setup;
  if (buildFrameSetup(camera, depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  Framebuffer frame(camera.width, camera.height);
  for (auto _ : state) {
    frame.clear();
    renderLevel(variant, *level, setup, frame);
    benchmark::DoNotOptimize(frame.colourIndices().data());
    benchmark::ClobberMemory();
  }
  const double points = static_cast<double>(level->leaves.size());
  state.counters["points/s"] = benchmark::Counter(points, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ns/point"] = benchmark::Counter(
      points * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void registerAll() {
  for (const VariantInfo& info : allVariants()) {
    for (int depth : {7, 8}) {
      for (int yaw : {0, 30}) {
        const std::string name = "render/" + std::string(info.name) + "/tabletop/depth" +
                                 std::to_string(depth) + (yaw == 0 ? "/frontal" : "/yaw30");
        benchmark::RegisterBenchmark(name.c_str(), renderDefaultModel, info.variant, depth, yaw)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
}

}  // namespace
}  // namespace octopoint

int main(int argc, char** argv) {
  octopoint::registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
