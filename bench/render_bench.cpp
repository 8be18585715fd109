// Frame rendering speed per variant, depth, view and scan, at 320x240, with the PCL/Eigen peer in
// the same binary. Counters: points/s and ns/point over the leaves of the level drawn.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "bench/pcl_peer.h"
#include "bench/register_benchmarks.h"
#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint {
namespace {

constexpr std::int32_t kWidth = 320;
constexpr std::int32_t kHeight = 240;

struct Scan {
  std::string name;
  std::vector<std::uint8_t> file;  // keeps a .oct model's bytes alive for its view
  std::optional<ModelView> model;
};

std::vector<std::unique_ptr<Scan>>& scans() {
  static std::vector<std::unique_ptr<Scan>> loaded;
  return loaded;
}

void loadScans() {
  ModelIssue issue;
  auto tabletop = std::make_unique<Scan>();
  tabletop->name = "tabletop";
  tabletop->model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  scans().push_back(std::move(tabletop));
  auto table = std::make_unique<Scan>();
  table->name = "lms400";
  // Read by size: byte-by-byte iterators make g++ 12 warn of a null streambuf it cannot rule out.
  std::ifstream in(OCTOPOINT_SECOND_SCAN_OCT_PATH, std::ios::binary | std::ios::ate);
  table->file.resize(static_cast<std::size_t>(std::max<std::streamoff>(in.tellg(), 0)));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(table->file.data()),
          static_cast<std::streamsize>(table->file.size()));
  table->model = ModelView::fromBytes(table->file, &issue);
  scans().push_back(std::move(table));
}

Camera cameraFor(int yaw_degrees) {
  Camera camera;
  camera.width = kWidth;
  camera.height = kHeight;
  camera.yaw = Angle::fromDegrees(yaw_degrees);
  return camera;
}

void setPointCounters(benchmark::State& state, std::size_t points) {
  const auto n = static_cast<double>(points);
  state.counters["points/s"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
  // Inverted rate of n * 1e-9: reads as nanoseconds per point.
  state.counters["ns/point"] = benchmark::Counter(
      n * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void renderScan(benchmark::State& state, const Scan* scan, Variant variant, int depth, int yaw) {
  const LevelView* level = scan->model ? scan->model->levelOfDepth(depth) : nullptr;
  FrameSetup setup;
  if (level == nullptr ||
      buildFrameSetup(cameraFor(yaw), depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    state.SkipWithError("model or camera unavailable");
    return;
  }
  setup.splat = SplatFootprint{};  // one pixel per leaf in every variant: the paper's comparison
  Framebuffer frame(kWidth, kHeight);
  for (auto _ : state) {
    frame.clear();
    if (!renderLevel(variant, *level, setup, frame)) state.SkipWithError("renderLevel refused");
    benchmark::DoNotOptimize(frame.pixels().data());
    benchmark::ClobberMemory();
  }
  setPointCounters(state, level->leaves.size());
}

void renderScanWithPeer(benchmark::State& state, const Scan* scan, int depth, int yaw) {
  const LevelView* level = scan->model ? scan->model->levelOfDepth(depth) : nullptr;
  if (level == nullptr) {
    state.SkipWithError("model unavailable");
    return;
  }
  bench::PclPeer peer(*scan->model, *level, kWidth, kHeight);
  const Camera camera = cameraFor(yaw);
  for (auto _ : state) {
    peer.render(camera);
    benchmark::ClobberMemory();
  }
  setPointCounters(state, peer.points());
}

}  // namespace

void registerAll() {
  loadScans();
  for (const auto& scan : scans()) {
    for (int depth : {7, 8}) {
      for (int yaw : {0, 30}) {
        const std::string suffix = "/" + scan->name + "/depth" + std::to_string(depth) +
                                   (yaw == 0 ? "/frontal" : "/yaw30");
        for (const VariantInfo& info : allVariants()) {
          benchmark::RegisterBenchmark(("render/" + std::string(info.name) + suffix).c_str(),
                                       renderScan, scan.get(), info.variant, depth, yaw)
              ->Unit(benchmark::kMicrosecond);
        }
        benchmark::RegisterBenchmark(("render/pcl_peer" + suffix).c_str(), renderScanWithPeer,
                                     scan.get(), depth, yaw)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
}

}  // namespace octopoint
