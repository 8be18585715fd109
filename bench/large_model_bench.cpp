// A large model's frame cost follows the screen. At 1280x960, the large chunked model
// (>= 10 million voxels, lab/scripts/measure-large makes it) drawn complete by the progressive
// model at depth auto, side by side in one binary, against
//  - the same scene prepared with depths up to 8 (--large-depth8, chunked, and --large-depth8-flat,
//    a single-file model): the fair comparison, the same pixels covered by a depth-8 model;
//  - the default model (finest depth 8), compiled in and as a chunked file (--default-chunked):
//    a smaller scene, so also compared per covered pixel.
// Frame clear included. Each case counts the frame's covered pixels and the CPU time per covered
// pixel (per_covered_px, seconds).
// usage: large_model_bench --large=LARGE.oct [--large-depth8=L8.oct] [--large-depth8-flat=L8.oct]
//          [--default-chunked=DEFAULT.oct] [benchmark flags]
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"

namespace {

using namespace octopoint;

std::string g_large_path;
std::string g_large_depth8_path;       // the large model's scene, depths up to 8, chunked
std::string g_large_depth8_flat_path;  // the same as a single-file (not chunked) model
std::string g_default_chunked_path;

Camera screen(int zoom) {
  Camera camera;
  camera.width = 1280;
  camera.height = 960;
  camera.zoom = Q16::fromRaw(zoom * Q16::kOneRaw);
  return camera;
}

bool readFile(const std::string& path, std::vector<std::uint8_t>& bytes) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return false;
  bytes.resize(static_cast<std::size_t>(in.tellg()));
  in.seekg(0);
  return static_cast<bool>(
      in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())));
}

std::optional<ProgressiveModel> loadChunked(const std::string& path,
                                            std::vector<std::uint8_t>& bytes) {
  if (!readFile(path, bytes)) return std::nullopt;
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
  // Both sized for their frames here: neither can be refused.
  static_cast<void>(resolveToRgb(frame, palette, Rgb{0, 0, 0}, a));
  static_cast<void>(resolveToRgb(reference, palette, Rgb{0, 0, 0}, b));
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = static_cast<double>(a[i]) - static_cast<double>(b[i]);
    sum += d * d;
  }
  if (sum == 0) return 99.0;  // identical
  return 10.0 * std::log10(255.0 * 255.0 * static_cast<double>(a.size()) / sum);
}

// The pixels a frame covers, and the frame's CPU time per covered pixel (seconds; a cost that
// follows the screen is a constant here, whatever the model).
void countCoveredPixels(benchmark::State& state, const FrameView& frame) {
  std::uint64_t covered = 0;
  for (const std::uint32_t word : frame.pixels()) covered += word != FrameView::kEmpty;
  state.counters["covered_px"] = static_cast<double>(covered);
  state.counters["per_covered_px"] = benchmark::Counter(
      static_cast<double>(covered),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
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
    if (!model->draw(camera, defaultVariant(), frame, &stats))
      state.SkipWithError("camera refused");
    benchmark::DoNotOptimize(frame.pixelData());
  }
  state.counters["depth"] = stats.drawn_depth;
  state.counters["points"] = static_cast<double>(stats.points);
  state.counters["pieces"] = stats.pieces;
  countCoveredPixels(state, frame);
  if (budget != 0) {  // against the frame without a budget
    Framebuffer full(camera.width, camera.height);
    full.clear();
    model->setPointBudget(0);
    if (!model->draw(camera, defaultVariant(), full)) state.SkipWithError("camera refused");
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
// The large model's own scene with depths up to 8: what it costs when the same screen is covered.
void BM_LargeSceneDepth8Chunked(benchmark::State& state) {
  drawProgressive(state, g_large_depth8_path);
}

// A single-file model drawn at depth auto by renderLevel, as octopoint-render --file draws it.
void drawLevelModel(benchmark::State& state, const ModelView& model) {
  const Camera camera = screen(static_cast<int>(state.range(0)));
  const LevelView* level = autoLevel(model, camera);
  if (level == nullptr) {
    state.SkipWithError("no depth for this view");
    return;
  }
  FrameSetup setup;
  if (buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  Framebuffer frame(camera.width, camera.height);
  for (auto _ : state) {
    frame.clear();
    if (!renderLevel(defaultVariant(), *level, setup, frame))
      state.SkipWithError("renderLevel refused");
    benchmark::DoNotOptimize(frame.pixelData());
  }
  state.counters["depth"] = level->depth;
  state.counters["points"] = static_cast<double>(level->leaves.size());
  countCoveredPixels(state, frame);
}

void BM_Depth8Model(benchmark::State& state) {
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  drawLevelModel(state, *model);
}

void BM_LargeSceneDepth8Flat(benchmark::State& state) {
  std::vector<std::uint8_t> bytes;
  ModelIssue issue;
  std::optional<ModelView> model;
  if (!g_large_depth8_flat_path.empty() && readFile(g_large_depth8_flat_path, bytes))
    model = ModelView::fromBytes(bytes, &issue);
  if (!model) {
    state.SkipWithError("cannot read the single-file depth-8 model (--large-depth8-flat)");
    return;
  }
  drawLevelModel(state, *model);
}

BENCHMARK(BM_Depth8Model)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Depth8ModelChunked)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LargeSceneDepth8Flat)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LargeSceneDepth8Chunked)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);
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
    } else if (std::strncmp(argv[i], "--large-depth8=", 15) == 0) {
      g_large_depth8_path = argv[i] + 15;
    } else if (std::strncmp(argv[i], "--large-depth8-flat=", 20) == 0) {
      g_large_depth8_flat_path = argv[i] + 20;
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
