// What a footprint splat costs (docs/splats.md#cost): the default model's finest depth (8), turned
// 30 degrees, on a 1920x1080 frame at the zooms that give its leaves footprints of 2x1 to 8x6
// pixels (the whole model on screen, so every leaf is drawn), by fixed_fast and fixed_simd, each
// with its splats and at one pixel per leaf (`setup.splat` reset) in the same run. The time is the
// decode alone (manual time around renderLevel; the frame is cleared outside it). Counters: the
// leaves drawn, the pixels their splats write (each leaf's rectangle, as
// tests/support/splat_reference.h defines it), ns per leaf and per pixel written.
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>
#include <vector>

#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "renderer/decode_baseline.h"

namespace octopoint {
namespace {

const ModelView& model() {
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return view;
}

FrameSetup setupAt(int zoom_percent) {
  Camera camera;
  camera.width = 1920;
  camera.height = 1080;
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = Q16::fromRaw(zoom_percent * Q16::kOneRaw / 100);
  FrameSetup setup;
  // A refused camera gives an empty set-up, which renderLevel refuses: the benchmark then skips.
  if (buildFrameSetup(camera, model().finestLevel().depth, kDefaultFractionBits, &setup) !=
      CameraError::kNone) {
    return FrameSetup{};
  }
  return setup;
}

// Pixels the leaves write: per leaf its splat's columns times rows (one for one pixel per leaf),
// clipped to the frame.
std::int64_t pixelsWritten(const FrameSetup& setup) {
  struct Count {
    const FrameSetup& setup;
    std::int64_t pixels = 0;
    void operator()(std::int32_t x, std::int32_t y, std::int32_t, std::uint8_t) {
      const SplatFootprint& s = setup.splat;
      const int f = setup.fraction_bits;
      const std::int64_t x0 = std::max<std::int64_t>((std::int64_t{x} + s.offset_x) >> f, 0);
      const std::int64_t x1 =
          std::min<std::int64_t>((std::int64_t{x} + s.offset_x + s.span_x) >> f, setup.width - 1);
      const std::int64_t y0 = std::max<std::int64_t>((std::int64_t{y} + s.offset_y) >> f, 0);
      const std::int64_t y1 =
          std::min<std::int64_t>((std::int64_t{y} + s.offset_y + s.span_y) >> f, setup.height - 1);
      if (x1 >= x0 && y1 >= y0) pixels += (x1 - x0 + 1) * (y1 - y0 + 1);
    }
  } count{setup};
  BaselineWalk<Count>(model().finestLevel(), setup, count).run();
  return count.pixels;
}

void drawSplats(benchmark::State& state, Variant variant, int zoom_percent, bool splats) {
  FrameSetup setup = setupAt(zoom_percent);
  if (!splats) setup.splat = SplatFootprint{};
  const LevelView& level = model().finestLevel();
  Framebuffer frame(setup.width, setup.height);
  double decode_seconds = 0;
  for (auto _ : state) {
    frame.clear();
    const auto start = std::chrono::steady_clock::now();
    if (!renderLevel(variant, level, setup, frame)) state.SkipWithError("renderLevel refused");
    benchmark::ClobberMemory();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    decode_seconds += seconds;
  }
  const auto leaves = static_cast<double>(level.leaves.size());
  const auto pixels = static_cast<double>(pixelsWritten(setup));
  const double ns_per_frame = decode_seconds * 1e9 / static_cast<double>(state.iterations());
  state.counters["leaves"] = leaves;
  state.counters["pixels_written"] = pixels;
  state.counters["ns_per_leaf"] = ns_per_frame / leaves;
  state.counters["ns_per_pixel"] = ns_per_frame / pixels;
  state.counters["splat_columns"] = setup.splat.columns;
  state.counters["splat_rows"] = setup.splat.rows;
}

}  // namespace

void registerAll() {
  std::vector<std::pair<Variant, std::string>> variants = {{Variant::kFixedFast, "fixed_fast"}};
  if (simdDecoderAvailable()) variants.emplace_back(Variant::kFixedSimd, "fixed_simd");
  // Zoom (percent) -> footprint at 1920x1080, yaw 30, depth 8.
  const std::pair<int, std::string> zooms[] = {{20, "2x1"}, {25, "2x2"},  {40, "3x2"}, {50, "3x3"},
                                               {60, "4x3"}, {100, "6x5"}, {125, "8x6"}};
  for (const auto& [zoom, footprint] : zooms) {
    for (const auto& [variant, name] : variants) {
      for (const bool splats : {true, false}) {
        const std::string what = splats ? footprint : footprint + "_as_one_pixel";
        benchmark::RegisterBenchmark(
            ("splat/" + name + "/tabletop/depth8/1920x1080/" + what).c_str(), drawSplats, variant,
            zoom, splats)
            ->UseManualTime()
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
}

}  // namespace octopoint
