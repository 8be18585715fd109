// Abort latency of the fine render (docs/design.md section 5): the time from the abort request (the
// store to the flag) to renderLevel returning on the rendering thread, with the abort at a random
// point of the frame: the default model's finest level at 320x240 one pixel per leaf
// (fixed_baseline), and the dual-resolution renderer's H frame on a large screen, depth auto with
// footprint splats (fixed_simd, fixed_fast; 1920x1080 at zoom 4 writes 24x17-pixel splats,
// 1280x960 at zoom 2 11x8), where a subtree below the poll's level covers much of the screen.
//
// Each iteration starts a render on a thread of its own, waits a random time in the first half of
// the frame time after the render began, takes the time and stores the flag; the thread takes the
// time when renderLevel returns. Iterations where the frame completed first (on a busy machine the
// aborting thread is often descheduled) are not samples. The reported time is the mean latency
// (manual time); the counters give the median, the 99th percentile and the worst one. On a shared
// machine the wall-clock latency includes the time the render thread waits for a core; the cpu_*
// counters give the render thread's own CPU time from the request to its return (its thread CPU
// clock, read by the aborting thread at the request), which is the decoder's part alone.
#include <benchmark/benchmark.h>
#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

using Clock = std::chrono::steady_clock;

std::int64_t nanosecondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(to - from).count();
}

std::int64_t cpuNanoseconds(clockid_t clock) {
  timespec now{};
  clock_gettime(clock, &now);
  return std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
}

// The median, 99th percentile and worst of `samples` (sorted here), as counters in microseconds,
// and the count of samples over a millisecond.
void setLatencyCounters(benchmark::State& state, const std::string& prefix,
                        std::vector<std::int64_t>& samples) {
  std::sort(samples.begin(), samples.end());
  const auto percentile_us = [&](std::size_t per_mille) {
    return static_cast<double>(samples[(samples.size() - 1) * per_mille / 1000]) * 1e-3;
  };
  state.counters[prefix + "median_us"] = percentile_us(500);
  state.counters[prefix + "p99_us"] = percentile_us(990);
  state.counters[prefix + "worst_us"] = static_cast<double>(samples.back()) * 1e-3;
  // How many aborts missed the millisecond the design promises (docs/design.md section 5).
  const auto first_late = std::upper_bound(samples.begin(), samples.end(), std::int64_t{1'000'000});
  state.counters[prefix + "over_1ms"] = static_cast<double>(samples.end() - first_late);
}

struct Case {
  Variant variant;
  std::int32_t width, height;
  int yaw_degrees, zoom;
  bool depth_auto;  // else the finest level, one pixel per leaf
};

// The median time of 21 frames, to spread the abort points over the frame; none when
// renderLevel refuses the frame.
std::optional<std::int64_t> medianFrameNs(Variant variant, const LevelView& level,
                                          const FrameSetup& setup, Framebuffer& frame) {
  std::vector<std::int64_t> frame_ns;
  for (int i = 0; i < 21; ++i) {
    frame.clear();
    const Clock::time_point start = Clock::now();
    if (!renderLevel(variant, level, setup, frame)) return std::nullopt;
    frame_ns.push_back(nanosecondsBetween(start, Clock::now()));
  }
  std::nth_element(frame_ns.begin(), frame_ns.begin() + 10, frame_ns.end());
  return frame_ns[10];
}

// One render on a thread of its own, aborted `abort_after` after it began.
struct AbortSample {
  bool complete = false;  // the frame completed before the abort: no sample
  std::int64_t latency_ns = 0;
  bool cpu_clock = false;  // whether cpu_latency_ns was measured
  std::int64_t cpu_latency_ns = 0;
};

AbortSample abortOnce(Variant variant, const LevelView& level, const FrameSetup& setup,
                      Framebuffer& frame, std::chrono::nanoseconds abort_after) {
  std::atomic<bool> abort{false};
  std::atomic<bool> started{false};
  bool complete = false;
  Clock::time_point returned;
  std::int64_t returned_cpu_ns = 0;
  std::thread renderer([&] {
    frame.clear();
    started.store(true);
    complete = renderLevel(variant, level, setup, frame, &abort);
    returned = Clock::now();
    returned_cpu_ns = cpuNanoseconds(CLOCK_THREAD_CPUTIME_ID);
  });
  clockid_t renderer_cpu_clock{};
  const bool cpu_clock = pthread_getcpuclockid(renderer.native_handle(), &renderer_cpu_clock) == 0;
  while (!started.load()) {
  }
  const Clock::time_point abort_at = Clock::now() + abort_after;
  while (Clock::now() < abort_at) {
  }
  const std::int64_t requested_cpu_ns = cpu_clock ? cpuNanoseconds(renderer_cpu_clock) : 0;
  const Clock::time_point requested = Clock::now();
  abort.store(true);
  renderer.join();  // after join, `complete` and `returned` are ours to read
  AbortSample sample;
  sample.complete = complete;
  sample.latency_ns = std::max<std::int64_t>(0, nanosecondsBetween(requested, returned));
  sample.cpu_clock = cpu_clock;
  sample.cpu_latency_ns = std::max<std::int64_t>(0, returned_cpu_ns - requested_cpu_ns);
  return sample;
}

void abortLatency(benchmark::State& state, Case c) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  Camera camera;
  camera.width = c.width;
  camera.height = c.height;
  camera.yaw = Angle::fromDegrees(c.yaw_degrees);
  camera.zoom = Q16::fromRaw(c.zoom * Q16::kOneRaw);
  const LevelView* chosen = !model         ? nullptr
                            : c.depth_auto ? autoLevel(*model, camera)
                                           : &model->finestLevel();
  FrameSetup setup;
  if (chosen == nullptr ||
      buildFrameSetup(camera, chosen->depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    state.SkipWithError("no model, or camera refused");
    return;
  }
  if (!c.depth_auto) setup.splat = SplatFootprint{};
  const LevelView& level = *chosen;
  Framebuffer frame(camera.width, camera.height);
  const std::optional<std::int64_t> median = medianFrameNs(c.variant, level, setup, frame);
  if (!median) {
    state.SkipWithError("renderLevel refused");
    return;
  }
  const std::int64_t median_frame_ns = *median;

  std::mt19937_64 random(42);
  std::uniform_int_distribution<std::int64_t> abort_after_ns(0, median_frame_ns / 2 - 1);
  std::vector<std::int64_t> latencies_ns, cpu_latencies_ns;
  std::int64_t completed_first = 0;
  for (auto _ : state) {
    const AbortSample sample =
        abortOnce(c.variant, level, setup, frame, std::chrono::nanoseconds(abort_after_ns(random)));
    if (sample.complete) {
      ++completed_first;
      state.SetIterationTime(0);
      continue;
    }
    latencies_ns.push_back(sample.latency_ns);
    if (sample.cpu_clock) cpu_latencies_ns.push_back(sample.cpu_latency_ns);
    state.SetIterationTime(static_cast<double>(sample.latency_ns) * 1e-9);
  }
  if (latencies_ns.empty()) return;
  setLatencyCounters(state, "", latencies_ns);
  if (!cpu_latencies_ns.empty()) setLatencyCounters(state, "cpu_", cpu_latencies_ns);
  state.counters["samples"] = static_cast<double>(latencies_ns.size());
  state.counters["completed_first"] = static_cast<double>(completed_first);
  state.counters["frame_us"] = static_cast<double>(median_frame_ns) * 1e-3;
  state.counters["depth"] = level.depth;
  state.counters["splat_columns"] = setup.splat.columns;
  state.counters["splat_rows"] = setup.splat.rows;
}

void add(const std::string& name, Case c) {
  benchmark::RegisterBenchmark(name.c_str(), abortLatency, c)
      ->UseManualTime()
      ->Iterations(3000)
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace

void registerAll() {
  for (const int yaw : {0, 30}) {
    const int zoom = yaw == 0 ? 1 : 2;
    add("abort_latency/fixed_baseline/tabletop/depth8/yaw" + std::to_string(yaw) + "_zoom" +
            std::to_string(zoom),
        Case{Variant::kFixedBaseline, 320, 240, yaw, zoom, false});
  }
  std::vector<std::pair<Variant, std::string>> variants = {{Variant::kFixedFast, "fixed_fast"}};
  if (simdDecoderAvailable()) variants.emplace_back(Variant::kFixedSimd, "fixed_simd");
  for (const auto& [variant, name] : variants) {
    add("abort_latency/" + name + "/tabletop/depth_auto/1920x1080_yaw30_zoom4",
        Case{variant, 1920, 1080, 30, 4, true});
    add("abort_latency/" + name + "/tabletop/depth_auto/1280x960_yaw30_zoom2",
        Case{variant, 1280, 960, 30, 2, true});
  }
}

}  // namespace octopoint
