// The cost of each style (docs/styles.md) against the plain frame, in one binary so that the
// ratios are measured side by side: the default model at depth auto, turned 30 degrees, at 320x240
// and 1920x1080 (zoom 1). A frame is what an app pays per picture: clear, decode (fixed_fast, the
// portable decoder, and fixed_simd where the CPU has AVX2: the faster the decoder, the larger a
// style's share), and turn into RGB888. "plain" is today's colour frame (resolveToRgb); each style
// goes through FrameStyler (the colour style too, to show the styler's own overhead). Names:
// style/<style>/<variant>/<width>x<height>. Counter ns_per_px: the whole frame's time per pixel of
// the frame. bench/style-run prints the ratios to plain.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/styles.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

struct Size {
  std::int32_t width, height;
};
constexpr Size kSizes[] = {{320, 240}, {1920, 1080}};
constexpr Rgb kBackground{236, 236, 240};

const ModelView& model() {
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return view;
}

struct Scene {
  const LevelView* level = nullptr;
  FrameSetup setup;
};

Scene sceneFor(Size size) {
  Camera camera;
  camera.width = size.width;
  camera.height = size.height;
  camera.yaw = Angle::fromDegrees(30);
  Scene scene;
  scene.level = autoLevel(model(), camera);
  if (scene.level != nullptr && buildFrameSetup(camera, scene.level->depth, kDefaultFractionBits,
                                                &scene.setup) != CameraError::kNone) {
    scene.level = nullptr;
  }
  return scene;
}

void setCounters(benchmark::State& state, const Scene& scene, Size size) {
  state.counters["depth"] = scene.level->depth;
  state.counters["ns_per_px"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * size.width * size.height,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void plainFrame(benchmark::State& state, Size size, Variant variant) {
  const Scene scene = sceneFor(size);
  if (scene.level == nullptr) {
    state.SkipWithError("camera refused");
    return;
  }
  Framebuffer frame(size.width, size.height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(size.width) *
                                static_cast<std::size_t>(size.height) * 3);
  for (auto _ : state) {
    frame.clear();
    if (!renderLevel(variant, *scene.level, scene.setup, frame))
      state.SkipWithError("renderLevel refused");
    if (!resolveToRgb(frame, model(), kBackground, rgb)) state.SkipWithError("resolve refused");
    benchmark::DoNotOptimize(rgb.data());
    benchmark::ClobberMemory();
  }
  setCounters(state, scene, size);
}

void styledFrame(benchmark::State& state, Size size, Variant variant, Style style) {
  const Scene scene = sceneFor(size);
  FrameStyler styler(model());
  StyleOptions options;
  options.style = style;
  options.background = kBackground;
  if (scene.level == nullptr || styler.setOptions(options) != StyleError::kNone) {
    state.SkipWithError("camera or style refused");
    return;
  }
  Framebuffer frame(size.width, size.height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(size.width) *
                                static_cast<std::size_t>(size.height) * 3);
  for (auto _ : state) {
    frame.clear(styler.payload());
    if (!renderLevel(variant, *scene.level, scene.setup, frame))
      state.SkipWithError("renderLevel refused");
    styler.beginFrame(scene.setup);
    if (styler.resolve(frame, rgb) != StyleError::kNone) state.SkipWithError("resolve refused");
    benchmark::DoNotOptimize(rgb.data());
    benchmark::ClobberMemory();
  }
  setCounters(state, scene, size);
}

}  // namespace

void registerAll() {
  for (const VariantInfo& variant : allVariants()) {
    if (variant.variant != Variant::kFixedFast && variant.variant != Variant::kFixedSimd) continue;
    for (const Size size : kSizes) {
      // Appended, not concatenated: GCC 12 warns falsely (-Wrestrict) about "literal" + string.
      std::string suffix = "/";
      suffix += variant.name;
      suffix += '/';
      suffix += std::to_string(size.width);
      suffix += 'x';
      suffix += std::to_string(size.height);
      std::string plain = "style/plain";
      plain += suffix;
      benchmark::RegisterBenchmark(plain.c_str(), plainFrame, size, variant.variant)
          ->Unit(benchmark::kMicrosecond);
      for (const StyleInfo& info : allStyles()) {
        std::string name = "style/";
        name += info.name;
        name += suffix;
        benchmark::RegisterBenchmark(name.c_str(), styledFrame, size, variant.variant, info.style)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
}

}  // namespace octopoint
