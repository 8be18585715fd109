// The web page's draw (web/octopoint_web.cpp: depth auto, the frame, the colour style, RGBA) of
// the embedded default model, compiled natively, with fixed_fast (what the page's WebAssembly
// draws with) and fixed_simd side by side: the native side of docs/web.md's frame time, whose
// other side is the same function in headless Chromium (lab/scripts/web_point_cost.py runs both).
#include <benchmark/benchmark.h>

#include <string>

#include "bench/register_benchmarks.h"
#include "web/octopoint_web.h"

namespace octopoint {
namespace {

void webDraw(benchmark::State& state, Variant variant, int width, int height) {
  if (octopoint_web_create() != 0) {
    state.SkipWithError(octopoint_web_error());
    return;
  }
  for (auto _ : state) {
    // yaw 30, pitch 10, zoom 1: the view lab/scripts/web_point_cost.py times in the browser
    if (web::drawWith(variant, 30'000, 10'000, 0, 65536, width, height) != 0) {
      state.SkipWithError(octopoint_web_error());
      return;
    }
    benchmark::DoNotOptimize(octopoint_web_pixels());
  }
}

}  // namespace

void registerAll() {
  const struct {
    const char* name;
    Variant variant;
  } variants[] = {{"fixed_fast", Variant::kFixedFast}, {"fixed_simd", Variant::kFixedSimd}};
  // 640x480 too: the size of docs/web.md's cost a point (lab/scripts/web_point_cost.py's fit).
  for (const auto& [width, height] :
       {std::pair{320, 240}, std::pair{640, 480}, std::pair{1280, 960}}) {
    for (const auto& v : variants) {
      const std::string name = std::string("web_draw/") + v.name + "/" + std::to_string(width) +
                               "x" + std::to_string(height);
      benchmark::RegisterBenchmark(name.c_str(), webDraw, v.variant, width, height)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace octopoint
