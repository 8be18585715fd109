// What perspective costs (docs/perspective.md#cost): the default model's finest depth (8), turned
// 20 degrees and tilted 10, drawn orthographically by fixed_fast (with its footprint splats) and in
// perspective by the orbit camera of the same zoom at 60 and at 10 degrees, at 320x240 and
// 1280x960, side by side in one run. The time is the draw alone (manual time; the frame is cleared
// outside it). Counters: the leaves of the level and ns per leaf.
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "renderer/perspective_walk.h"

namespace octopoint {
namespace {

const ModelView& model() {
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return view;
}

Camera cameraOf(int width, int height) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.yaw = Angle::fromDegrees(20);
  camera.pitch = Angle::fromDegrees(10);
  return camera;
}

// Times `draw(frame)` per iteration and reports ns per leaf of the level.
template <typename Draw>
void timeFrames(benchmark::State& state, int width, int height, const Draw& draw) {
  Framebuffer frame(width, height);
  double seconds_in_all = 0;
  for (auto _ : state) {
    frame.clear();
    const auto start = std::chrono::steady_clock::now();
    if (!draw(frame)) state.SkipWithError("the draw was refused");
    benchmark::ClobberMemory();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    seconds_in_all += seconds;
  }
  const auto leaves = static_cast<double>(model().finestLevel().leaves.size());
  state.counters["leaves"] = leaves;
  state.counters["ns_per_leaf"] =
      seconds_in_all * 1e9 / static_cast<double>(state.iterations()) / leaves;
}

void orthographic(benchmark::State& state, int width, int height) {
  const LevelView& level = model().finestLevel();
  FrameSetup setup;
  if (buildFrameSetup(cameraOf(width, height), level.depth, kDefaultFractionBits, &setup) !=
      CameraError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  timeFrames(state, width, height, [&](Framebuffer& frame) {
    return renderLevel(Variant::kFixedFast, level, setup, frame);
  });
}

void perspective(benchmark::State& state, int width, int height, int fov_degrees) {
  const LevelView& level = model().finestLevel();
  PerspectiveView view;
  if (orbitPerspective(cameraOf(width, height), Angle::fromDegrees(fov_degrees),
                       kDefaultFractionBits, &view) != PerspectiveError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  const PerspectiveWalkTables tables =
      perspectiveWalkTables(view, level.depth, std::int64_t{1} << (kDefaultFractionBits - 2));
  timeFrames(state, width, height,
             [&](Framebuffer& frame) { return drawPerspective(level, view, tables, frame); });
}

}  // namespace

void registerAll() {
  for (const auto& [width, height] : {std::pair{320, 240}, std::pair{1280, 960}}) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    benchmark::RegisterBenchmark(("perspective/tabletop/depth8/" + size + "/orthographic").c_str(),
                                 orthographic, width, height)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
    for (int fov : {60, 10}) {
      benchmark::RegisterBenchmark(
          ("perspective/tabletop/depth8/" + size + "/fov" + std::to_string(fov)).c_str(),
          perspective, width, height, fov)
          ->UseManualTime()
          ->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace octopoint
