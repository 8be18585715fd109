// What smooth splats cost against box splats (docs/splats.md, "Smooth splats"): the default model
// turned 30 degrees at depth auto, 320x240 zoom 1 (2x1 footprints) and 1920x1080 zoom 4 (voxels
// about 17 pixels wide), by fixed_fast and fixed_simd, box and smooth side by side in one run.
// A frame is what a user waits for: clear, draw (and blend), palette or blended colours to RGB.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

const ModelView& smoothBenchModel() {
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return view;
}

void drawFrame(benchmark::State& state, Variant variant, SplatMode mode, int width, int height,
               int zoom) {
  const ModelView& model = smoothBenchModel();
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = Q16::fromRaw(zoom * Q16::kOneRaw);
  const LevelView* level = autoLevel(model, camera);
  FrameSetup setup;
  if (level == nullptr ||
      buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  Framebuffer frame(setup);
  SmoothSplats smooth(setup);
  const PaletteRgb palette = paletteOf(model);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                                3);
  for (auto _ : state) {
    frame.clear();
    bool drawn = false;
    if (mode == SplatMode::kSmooth) {
      drawn = renderSmooth(variant, *level, setup, frame, smooth, palette) &&
              smooth.resolveToRgb(frame, palette, Rgb{}, rgb);
    } else {
      drawn = renderLevel(variant, *level, setup, frame) && resolveToRgb(frame, model, Rgb{}, rgb);
    }
    if (!drawn) state.SkipWithError("draw refused");
    benchmark::ClobberMemory();
  }
  state.counters["splat_columns"] = setup.splat.columns;
  state.counters["splat_rows"] = setup.splat.rows;
  state.counters["depth"] = setup.depth;
}

}  // namespace

void registerAll() {
  std::vector<std::pair<Variant, std::string>> variants = {{Variant::kFixedFast, "fixed_fast"}};
  if (simdDecoderAvailable()) variants.emplace_back(Variant::kFixedSimd, "fixed_simd");
  struct View {
    int width, height, zoom;
    std::string name;
  };
  const View views[] = {{320, 240, 1, "320x240/zoom1"}, {1920, 1080, 4, "1920x1080/zoom4"}};
  for (const View& view : views) {
    for (const auto& [variant, name] : variants) {
      for (const SplatMode mode : {SplatMode::kBox, SplatMode::kSmooth}) {
        benchmark::RegisterBenchmark(
            ("smooth/" + name + "/tabletop/" + view.name + "/" + std::string(splatModeName(mode)))
                .c_str(),
            drawFrame, variant, mode, view.width, view.height, view.zoom)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
}

}  // namespace octopoint
