// The small zoomed-in frames where depth auto was slower than today's renderer with hole
// filling (docs/tradeoff.md), with the skip index (octopoint/model.h) and without it, side by
// side in one binary: the same level drawn with LevelView::skip as ModelView builds it and with it
// cleared (the byte walk of renderer/skip_runs.h, what the decoders did before). Yaw 30, clear
// included, as the view sweep times them:
//  - after: depth auto with footprint splats, no filling;
//  - before_filled: depth 8 one pixel per leaf, then hole filling (octopoint/render.h). The
//    sweep's "before" model stores depths 7 and 8; its depth 8 has the same nodes as the one drawn
//    here (the same scan and cube fit), so the same walk.
// Scans: the default model (tabletop, compiled in) and lms400 at the preparer's default depths
// (6..9, prepared at build time).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"

namespace octopoint {
namespace {

struct Scan {
  std::string name;
  std::vector<std::uint8_t> file;  // what `model` points into (empty for a compiled-in model)
  std::optional<ModelView> model;
};

std::vector<std::unique_ptr<Scan>>& scans() {
  static std::vector<std::unique_ptr<Scan>> loaded = [] {
    std::vector<std::unique_ptr<Scan>> list;
    ModelIssue issue;
    auto tabletop = std::make_unique<Scan>();
    tabletop->name = "tabletop";
    tabletop->model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    list.push_back(std::move(tabletop));
    auto lms400 = std::make_unique<Scan>();
    lms400->name = "lms400";
    std::ifstream in(OCTOPOINT_LMS400_DEFAULT_DEPTHS_OCT_PATH, std::ios::binary | std::ios::ate);
    lms400->file.resize(static_cast<std::size_t>(std::max<std::streamoff>(in.tellg(), 0)));
    in.seekg(0);
    in.read(reinterpret_cast<char*>(lms400->file.data()),
            static_cast<std::streamsize>(lms400->file.size()));
    lms400->model = ModelView::fromBytes(lms400->file, &issue);
    list.push_back(std::move(lms400));
    return list;
  }();
  return loaded;
}

struct Cell {
  std::int32_t width, height, zoom;
};
constexpr Cell kCells[] = {
    {176, 208, 2}, {176, 208, 4}, {320, 240, 2}, {320, 240, 4}, {176, 208, 8}};

void drawFrame(benchmark::State& state, const Scan* scan, Cell cell, bool after, bool indexed) {
  if (!scan->model) {
    state.SkipWithError("model not loaded");
    return;
  }
  Camera camera;
  camera.width = cell.width;
  camera.height = cell.height;
  camera.yaw = Angle::fromDegrees(30);
  camera.zoom = Q16::fromRaw(cell.zoom * Q16::kOneRaw);
  const LevelView* chosen = after ? autoLevel(*scan->model, camera) : scan->model->levelOfDepth(8);
  FrameSetup setup;
  if (chosen == nullptr ||
      buildFrameSetup(camera, chosen->depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  if (!after) setup.splat = SplatFootprint{};
  LevelView level = *chosen;
  if (!indexed) level.skip = SkipIndex{};
  const Variant variant = defaultVariant();
  Framebuffer frame(cell.width, cell.height);
  HoleFiller filler(cell.width);
  for (auto _ : state) {
    frame.clear();
    if (!renderLevel(variant, level, setup, frame)) state.SkipWithError("renderLevel refused");
    if (!after && filler.fill(frame, bridgeDepthLimit(setup)).refused)
      state.SkipWithError("hole filling refused");
    benchmark::DoNotOptimize(frame.pixels().data());
    benchmark::ClobberMemory();
  }
  state.counters["depth"] = level.depth;
  state.counters["indexed"] = level.skip.level > 0 ? 1 : 0;
}

}  // namespace

void registerAll() {
  for (const std::unique_ptr<Scan>& scan : scans()) {
    for (const Cell cell : kCells) {
      const std::string cell_name = "/" + scan->name + "/" + std::to_string(cell.width) + "x" +
                                    std::to_string(cell.height) + "_zoom" +
                                    std::to_string(cell.zoom);
      for (const bool after : {true, false}) {
        for (const bool indexed : {true, false}) {
          const std::string name = std::string("small_screen") + cell_name +
                                   (after ? "/after" : "/before_filled") +
                                   (indexed ? "/indexed" : "/byte_walk");
          benchmark::RegisterBenchmark(name.c_str(), drawFrame, scan.get(), cell, after, indexed)
              ->Unit(benchmark::kMicrosecond);
        }
      }
    }
  }
}

}  // namespace octopoint
