// The set-up of a scene of many models per frame against the frame's time (docs/city.md,
// "Set-up per frame"): 10^4 instances of the default model (100 x 100 on a grid one scene edge
// apart, turned by quarter turns, at scale -1), the eye among them a little above the ground
// looking along a row, 320x240, 60 degrees. `scene/.../frame`: SceneRenderer::draw (the frame
// cleared outside the time); `scene/.../setup`: SceneRenderer::setUp, all that draw does before
// any point is drawn (each instance's box and frustum test, the nearest-first order, each
// instance in view's camera and walk tables). Counters: the instances in view and the points drawn.
#include <benchmark/benchmark.h>

#include <chrono>
#include <vector>

#include "bench/instance_grid.h"
#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "renderer/scene_renderer.h"

namespace octopoint {
namespace {

constexpr std::int64_t kEdge = kPerspectiveUnit;

struct BenchScene {
  ModelView model;
  std::vector<SceneInstance> instances;
  std::optional<SceneRenderer> renderer;
  PerspectiveView view;
};

BenchScene& scene() {
  static BenchScene* built = [] {
    ModelIssue issue;
    auto* s = new BenchScene{*ModelView::fromEmbedded(*models::defaultModel(), &issue), {}, {}, {}};
    s->instances = bench::instanceGrid();
    const ModelView* models[] = {&s->model};
    SceneError error;
    s->renderer.emplace(models, s->instances, &error);
    PerspectiveCamera camera;
    camera.eye = {kEdge / 2, -kEdge / 8, -45 * kEdge};
    camera.pitch = Angle::fromDegrees(-5);
    camera.width = 320;
    camera.height = 240;
    static_cast<void>(buildPerspectiveView(camera, kDefaultFractionBits, &s->view));
    return s;
  }();
  return *built;
}

void frame(benchmark::State& state) {
  BenchScene& s = scene();
  Framebuffer frame(320, 240);
  SceneDrawStats stats;
  for (auto _ : state) {
    frame.clear();
    stats = {};
    const auto start = std::chrono::steady_clock::now();
    if (!s.renderer->draw(s.view, frame, &stats)) state.SkipWithError("the draw was refused");
    benchmark::ClobberMemory();
    state.SetIterationTime(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  state.counters["in_view"] = static_cast<double>(stats.instances_drawn);
  state.counters["points"] = static_cast<double>(stats.points.leaves);
}

void setup(benchmark::State& state) {
  BenchScene& s = scene();
  std::size_t set_up = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    set_up = s.renderer->setUp(s.view);
    benchmark::DoNotOptimize(set_up);
    state.SetIterationTime(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  state.counters["in_view"] = static_cast<double>(set_up);
}

}  // namespace

void registerAll() {
  benchmark::RegisterBenchmark("scene/10000_instances/320x240/frame", frame)->UseManualTime();
  benchmark::RegisterBenchmark("scene/10000_instances/320x240/setup", setup)->UseManualTime();
}

}  // namespace octopoint
