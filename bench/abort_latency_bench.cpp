// Abort latency of the fine render (docs/design.md section 5): the time from the abort request (the
// store to the flag) to renderLevel returning on the rendering thread, for the default model's fine
// level at 320x240, with the abort at a random point of the frame.
//
// Each iteration starts a render on a thread of its own, waits a random time in the first half of
// the frame time after the render began, takes the time and stores the flag; the thread takes the
// time when renderLevel returns. Iterations where the frame completed first (on a busy machine the
// aborting thread is often descheduled) are not samples. The reported time is the mean latency
// (manual time); the counters give the median, the 99th percentile and the worst one.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "models/registry.h"
#include "renderer/render.h"

namespace octopoint {
namespace {

using Clock = std::chrono::steady_clock;

std::int64_t nanosecondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(to - from).count();
}

void abortLatency(benchmark::State& state, int yaw_degrees, int zoom) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  Camera camera;
  camera.yaw = Angle::fromDegrees(yaw_degrees);
  camera.zoom = Q16::fromRaw(zoom * Q16::kOneRaw);
  FrameSetup setup;
  if (!model || buildFrameSetup(camera, model->finestLevel().depth, kDefaultFractionBits, &setup) !=
                    CameraError::kNone) {
    state.SkipWithError("no model, or camera refused");
    return;
  }
  const LevelView& level = model->finestLevel();
  Framebuffer frame(camera.width, camera.height);

  // The frame time, to spread the abort points over the frame.
  std::vector<std::int64_t> frame_ns;
  for (int i = 0; i < 21; ++i) {
    frame.clear();
    const Clock::time_point start = Clock::now();
    renderLevel(Variant::kFixedBaseline, level, setup, frame);
    frame_ns.push_back(nanosecondsBetween(start, Clock::now()));
  }
  std::nth_element(frame_ns.begin(), frame_ns.begin() + 10, frame_ns.end());
  const std::int64_t median_frame_ns = frame_ns[10];

  std::mt19937_64 random(42);
  std::uniform_int_distribution<std::int64_t> abort_after_ns(0, median_frame_ns / 2 - 1);
  std::vector<std::int64_t> latencies_ns;
  std::int64_t completed_first = 0;
  for (auto _ : state) {
    std::atomic<bool> abort{false};
    std::atomic<bool> started{false};
    bool complete = false;
    Clock::time_point returned;
    std::thread renderer([&] {
      frame.clear();
      started.store(true);
      complete = renderLevel(Variant::kFixedBaseline, level, setup, frame, &abort);
      returned = Clock::now();
    });
    while (!started.load()) {
    }
    const Clock::time_point abort_at =
        Clock::now() + std::chrono::nanoseconds(abort_after_ns(random));
    while (Clock::now() < abort_at) {
    }
    const Clock::time_point requested = Clock::now();
    abort.store(true);
    renderer.join();  // after join, `complete` and `returned` are ours to read
    if (complete) {
      ++completed_first;
      state.SetIterationTime(0);
      continue;
    }
    const std::int64_t latency_ns =
        std::max<std::int64_t>(0, nanosecondsBetween(requested, returned));
    latencies_ns.push_back(latency_ns);
    state.SetIterationTime(static_cast<double>(latency_ns) * 1e-9);
  }
  if (latencies_ns.empty()) return;
  std::sort(latencies_ns.begin(), latencies_ns.end());
  const auto percentile_us = [&](std::size_t per_mille) {
    return static_cast<double>(latencies_ns[(latencies_ns.size() - 1) * per_mille / 1000]) * 1e-3;
  };
  state.counters["median_us"] = percentile_us(500);
  state.counters["p99_us"] = percentile_us(990);
  state.counters["worst_us"] = static_cast<double>(latencies_ns.back()) * 1e-3;
  state.counters["samples"] = static_cast<double>(latencies_ns.size());
  state.counters["completed_first"] = static_cast<double>(completed_first);
  state.counters["frame_us"] = static_cast<double>(median_frame_ns) * 1e-3;
}

void registerAll() {
  struct View {
    int yaw_degrees, zoom;
  };
  for (const View view : {View{0, 1}, View{30, 2}}) {
    const std::string name = "abort_latency/fixed_baseline/tabletop/depth8/yaw" +
                             std::to_string(view.yaw_degrees) + "_zoom" + std::to_string(view.zoom);
    benchmark::RegisterBenchmark(name.c_str(), abortLatency, view.yaw_degrees, view.zoom)
        ->UseManualTime()
        ->Iterations(3000)
        ->Unit(benchmark::kMicrosecond);
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
