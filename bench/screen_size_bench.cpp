// The cost of a frame at any size and zoom (docs/splats.md): the default model at depth auto
// (renderer/level_of_detail.h) with footprint splats, at 176x208, 320x240, 640x480, 1280x960 and
// 1920x1080, zoom 0.25 to 8, turned 30 degrees, clear included; and at 1920x1080 the PCL/Eigen peer
// drawing the same depth (one pixel per point, as a PCL user would), in the same binary. Counters:
// the depth drawn, the splat's largest columns and rows, the pixels covered. bench/screen-run runs
// it and prints the ratios the targets ask for. At 1280x960 and 1920x1080 the fastest variant also
// runs with the whole frame cleared each time (`..._full_clear`), as before the frame kept its
// drawn rectangle (octopoint/framebuffer.h): what clearing only the drawn rectangle saves.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bench/pcl_peer.h"
#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

struct Size {
  std::int32_t width, height;
};
constexpr Size kSizes[] = {{176, 208}, {320, 240}, {640, 480}, {1280, 960}, {1920, 1080}};
constexpr int kZoomQuarters[] = {1, 2, 4, 8, 16, 32};  // zoom 0.25 .. 8, in quarters

const ModelView& model() {
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return view;
}

Camera cameraFor(Size size, int zoom_quarters) {
  Camera camera;
  camera.width = size.width;
  camera.height = size.height;
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = Q16::fromRaw(zoom_quarters * (Q16::kOneRaw / 4));
  return camera;
}

void setFrameCounters(benchmark::State& state, int depth, const SplatFootprint& splat,
                      std::size_t covered) {
  state.counters["depth"] = depth;
  state.counters["splat_columns"] = splat.columns;
  state.counters["splat_rows"] = splat.rows;
  state.counters["covered_px"] = static_cast<double>(covered);
}

void renderAuto(benchmark::State& state, Variant variant, Size size, int zoom_quarters,
                bool full_clear) {
  const Camera camera = cameraFor(size, zoom_quarters);
  const LevelView* level = autoLevel(model(), camera);
  FrameSetup setup;
  if (level == nullptr ||
      buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  Framebuffer frame(size.width, size.height);
  for (auto _ : state) {
    if (full_clear) frame.pixelData();  // raw access: the whole frame counts as drawn
    frame.clear();
    if (!renderLevel(variant, *level, setup, frame)) state.SkipWithError("renderLevel refused");
    benchmark::DoNotOptimize(frame.pixels().data());
    benchmark::ClobberMemory();
  }
  std::size_t covered = 0;
  for (const std::uint32_t word : frame.pixels()) covered += word != Framebuffer::kEmpty;
  setFrameCounters(state, level->depth, setup.splat, covered);
}

void renderPeer(benchmark::State& state, Size size, int zoom_quarters) {
  const Camera camera = cameraFor(size, zoom_quarters);
  const LevelView* level = autoLevel(model(), camera);
  if (level == nullptr) {
    state.SkipWithError("camera refused");
    return;
  }
  bench::PclPeer peer(model(), *level, size.width, size.height);
  for (auto _ : state) {
    peer.render(camera);  // clears its buffers, transforms, z-buffers
    benchmark::ClobberMemory();
  }
  setFrameCounters(state, level->depth, SplatFootprint{}, peer.coveredPixels());
}

std::string zoomName(int zoom_quarters) {
  switch (zoom_quarters) {
    case 1:
      return "0.25";
    case 2:
      return "0.5";
    default:
      return std::to_string(zoom_quarters / 4);
  }
}

}  // namespace

void registerAll() {
  std::vector<Variant> variants = {Variant::kFixedFast};
  if (simdDecoderAvailable()) variants.push_back(Variant::kFixedSimd);
  for (const Size size : kSizes) {
    const std::string size_name = std::to_string(size.width) + "x" + std::to_string(size.height);
    for (const int zoom : kZoomQuarters) {
      const std::string suffix = "/tabletop/" + size_name + "/zoom" + zoomName(zoom);
      for (const Variant variant : variants) {
        const std::string name = variant == Variant::kFixedSimd ? "fixed_simd" : "fixed_fast";
        benchmark::RegisterBenchmark(("screen/" + name + suffix).c_str(), renderAuto, variant, size,
                                     zoom, false)
            ->Unit(benchmark::kMicrosecond);
      }
      if (size.width >= 1280) {
        const Variant fastest = variants.back();
        const std::string name = fastest == Variant::kFixedSimd ? "fixed_simd" : "fixed_fast";
        benchmark::RegisterBenchmark(("screen/" + name + "_full_clear" + suffix).c_str(),
                                     renderAuto, fastest, size, zoom, true)
            ->Unit(benchmark::kMicrosecond);
      }
      if (size.width == 1920) {
        benchmark::RegisterBenchmark(("screen/pcl_peer" + suffix).c_str(), renderPeer, size, zoom)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
}

}  // namespace octopoint
