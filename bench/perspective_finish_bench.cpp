// What hole filling and the styles add to a perspective frame (docs/perspective.md, "Styles and
// hole filling"): the eye at the table's edge of the default model (the view of
// perspective_bench's table_edge), drawn as octopoint-render --eye draws it (detail by distance,
// culled), then turned into RGB: `plain` is the colour frame through resolveToRgb (what a
// perspective frame cost before), `fill` the same after the hole filler, and each style through
// FrameStyler after the fill (a frame cleared for normals where the style needs them). The time is
// the whole frame: clear, draw, fill, resolve.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/styles.h"
#include "renderer/perspective_depth.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace {

const ModelView& finishBenchModel() {
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return view;
}

// `style`: nullopt for the plain colour frame through resolveToRgb.
void finishedFrame(benchmark::State& state, int width, int height, bool fill,
                   std::optional<Style> style) {
  PerspectiveView view;
  if (buildPerspectiveView(tableEdgeCamera(width, height), kDefaultFractionBits, &view) !=
      PerspectiveError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  const ModelView& model = finishBenchModel();
  PerspectiveRenderer renderer(model);
  FrameStyler styler(model);
  if (style) {
    StyleOptions options;
    options.style = *style;
    if (styler.setOptions(options) != StyleError::kNone) {
      state.SkipWithError("style refused");
      return;
    }
  }
  const PixelPayload payload = style ? styler.payload() : PixelPayload::kColour;
  const PerspectiveBridge bridge = perspectiveBridge(view, renderer.detailDepths().back());
  Framebuffer frame(width, height);
  HoleFiller filler(frame);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
  for (auto _ : state) {
    frame.clear(payload);
    bool ok = renderer.draw(view, {}, frame);
    if (fill) ok = ok && !filler.fill(frame, bridge).refused;
    if (style) {
      styler.beginPerspectiveFrame(view.world_to_camera, view.focal_q16);
      ok = ok && styler.resolve(frame, rgb) == StyleError::kNone;
    } else {
      ok = ok && resolveToRgb(frame, model, Rgb{255, 255, 255}, rgb);
    }
    if (!ok) state.SkipWithError("a step was refused");
    benchmark::ClobberMemory();
  }
}

}  // namespace

void registerAll() {
  for (const auto& [width, height] : {std::pair{320, 240}, std::pair{640, 480}}) {
    const std::string prefix =
        "perspective_finish/table_edge/" + std::to_string(width) + "x" + std::to_string(height);
    benchmark::RegisterBenchmark((prefix + "/plain").c_str(), finishedFrame, width, height, false,
                                 std::nullopt)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((prefix + "/fill").c_str(), finishedFrame, width, height, true,
                                 std::nullopt)
        ->Unit(benchmark::kMicrosecond);
    for (const StyleInfo& info : allStyles()) {
      benchmark::RegisterBenchmark((prefix + "/fill/" + std::string(info.name)).c_str(),
                                   finishedFrame, width, height, true, info.style)
          ->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace octopoint
