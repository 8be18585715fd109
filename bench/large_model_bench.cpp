// Issue 12: a large model's frame cost follows the screen. At 1280x960, the large chunked model
// (>= 10 million voxels, scripts/measure-large makes it) drawn complete by the progressive model
// at depth auto, against the default model (finest depth 8) drawn at depth auto, as a version-1
// level and as a chunked file, side by side in one binary; frame clear included.
// usage: large_model_bench --large=LARGE.oct [benchmark flags]
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "models/registry.h"
#include "renderer/level_of_detail.h"
#include "renderer/progressive_model.h"
#include "renderer/render.h"

namespace {

using namespace octopoint;

std::string g_large_path;
std::string g_default_chunked_path;

Camera screen(int zoom) {
  Camera camera;
  camera.width = 1280;
  camera.height = 960;
  camera.zoom = Q16::fromRaw(zoom * Q16::kOneRaw);
  return camera;
}

std::optional<ProgressiveModel> loadChunked(const std::string& path,
                                            std::vector<std::uint8_t>& bytes) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return std::nullopt;
  bytes.resize(static_cast<std::size_t>(in.tellg()));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
    return std::nullopt;
  ChunkedIssue issue;
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(bytes, &issue);
  if (model && issue.error != ChunkedError::kNone) model.reset();
  return model;
}

// PSNR (dB) of `frame`'s pixels against `reference`'s, both resolved through the same palette
// (a frame's quality next to its time: what a point budget gives up). Double is fine here: this is
// the bench, not the renderer.
double psnrAgainst(const Framebuffer& frame, const Framebuffer& reference,
                   const ModelView& palette) {
  const std::size_t pixels = static_cast<std::size_t>(frame.width()) * frame.height();
  std::vector<std::uint8_t> a(pixels * 3), b(pixels * 3);
  resolveToRgb(frame, palette, Rgb{0, 0, 0}, a);
  resolveToRgb(reference, palette, Rgb{0, 0, 0}, b);
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = static_cast<double>(a[i]) - static_cast<double>(b[i]);
    sum += d * d;
  }
  if (sum == 0) return 99.0;  // identical
  return 10.0 * std::log10(255.0 * 255.0 * static_cast<double>(a.size()) / sum);
}

void drawProgressive(benchmark::State& state, const std::string& path, std::uint64_t budget = 0) {
  if (path.empty()) {
    state.SkipWithError("no model path given");
    return;
  }
  std::vector<std::uint8_t> bytes;
  std::optional<ProgressiveModel> model = loadChunked(path, bytes);
  if (!model) {
    state.SkipWithError("cannot read the chunked model");
    return;
  }
  const Camera camera = screen(static_cast<int>(state.range(0)));
  Framebuffer frame(camera.width, camera.height);
  ProgressiveDrawStats stats;
  model->setPointBudget(budget);
  for (auto _ : state) {
    frame.clear();
    model->draw(camera, defaultVariant(), frame, &stats);
    benchmark::DoNotOptimize(frame.pixelData());
  }
  state.counters["depth"] = stats.drawn_depth;
  state.counters["points"] = static_cast<double>(stats.points);
  state.counters["pieces"] = stats.pieces;
  if (budget != 0) {  // against the frame without a budget
    Framebuffer full(camera.width, camera.height);
    full.clear();
    model->setPointBudget(0);
    model->draw(camera, defaultVariant(), full);
    state.counters["coarser_chunks"] = stats.over_budget_chunks;
    state.counters["psnr_dB"] = psnrAgainst(frame, full, model->baseModel());
  }
}

void BM_LargeModel(benchmark::State& state) { drawProgressive(state, g_large_path); }
// The same under a point budget: args zoom, budget in thousands of points.
void BM_LargeModelBudget(benchmark::State& state) {
  drawProgressive(state, g_large_path, static_cast<std::uint64_t>(state.range(1)) * 1000);
}
void BM_Depth8ModelChunked(benchmark::State& state) {
  drawProgressive(state, g_default_chunked_path);
}

void BM_Depth8Model(benchmark::State& state) {
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  const Camera camera = screen(static_cast<int>(state.range(0)));
  const LevelView* level = autoLevel(*model, camera);
  FrameSetup setup;
  buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup);
  Framebuffer frame(camera.width, camera.height);
  for (auto _ : state) {
    frame.clear();
    renderLevel(defaultVariant(), *level, setup, frame);
    benchmark::DoNotOptimize(frame.pixelData());
  }
  state.counters["depth"] = level->depth;
  state.counters["points"] = static_cast<double>(level->leaves.size());
}

BENCHMARK(BM_Depth8Model)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Depth8ModelChunked)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LargeModel)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LargeModelBudget)
    ->ArgsProduct({{1, 4}, {100, 150, 200, 400, 800}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--large=", 8) == 0) {
      g_large_path = argv[i] + 8;
    } else if (std::strncmp(argv[i], "--default-chunked=", 18) == 0) {
      g_default_chunked_path = argv[i] + 18;
    } else {
      rest.push_back(argv[i]);
    }
  }
  int rest_count = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_count, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
