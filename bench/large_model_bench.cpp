// Issue 12: a large model's frame cost follows the screen. At 1280x960, the large chunked model
// (>= 10 million voxels, scripts/measure-large makes it) drawn complete by the progressive model
// at depth auto, against the default model (finest depth 8) drawn at depth auto, as a version-1
// level and as a chunked file, side by side in one binary; frame clear included.
// usage: large_model_bench --large=LARGE.oct [benchmark flags]
#include <benchmark/benchmark.h>

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

void drawProgressive(benchmark::State& state, const std::string& path) {
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
  for (auto _ : state) {
    frame.clear();
    model->draw(camera, defaultVariant(), frame, &stats);
    benchmark::DoNotOptimize(frame.pixelData());
  }
  state.counters["depth"] = stats.drawn_depth;
  state.counters["points"] = static_cast<double>(stats.points);
  state.counters["pieces"] = stats.pieces;
}

void BM_LargeModel(benchmark::State& state) { drawProgressive(state, g_large_path); }
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
