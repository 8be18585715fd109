// What perspective costs (docs/perspective.md#cost): the default model's finest depth (8), turned
// 20 degrees and tilted 10, drawn orthographically by fixed_fast (with its footprint splats) and in
// perspective by the orbit camera of the same zoom at 60 and at 10 degrees, at 320x240 and
// 1280x960, side by side in one run. And the eye at the table's edge (docs/perspective.md's
// walk-through view) drawn as octopoint-render draws it (PerspectiveRenderer: detail by distance),
// without occlusion culling and with it on tiles of 4 x 4, 8 x 8 and 16 x 16 pixels (the same
// frame). The time is the draw alone (manual time; the frame is cleared outside it). Counters: the
// points handed to the plot (the level's leaves for the orthographic and single-depth frames), ns
// per point, and for the table's edge the subtrees culled and the points per covered pixel.
// Against the perspective PCL/Eigen peer (bench/pcl_perspective_peer.h), at the table's edge: the
// finest depth's leaves (62,502) drawn by ours at that depth and by distance, and by the peer in
// float and in double; ns_per_leaf divides every frame by those same leaves. And the walk's tables
// of one depth for that view (walk_tables), which every frame makes per stored depth.
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "bench/pcl_perspective_peer.h"
#include "bench/register_benchmarks.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "renderer/perspective_renderer.h"
#include "renderer/perspective_walk.h"
#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace {

const ModelView& model() {
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return view;
}

Camera cameraOf(int width, int height) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.yaw = Angle::fromDegrees(20);
  camera.pitch = Angle::fromDegrees(10);
  return camera;
}

// Times `draw(frame)` per iteration and reports ns per leaf of the level.
template <typename Draw>
void timeFrames(benchmark::State& state, int width, int height, const Draw& draw,
                double leaves = static_cast<double>(model().finestLevel().leaves.size())) {
  Framebuffer frame(width, height);
  double seconds_in_all = 0;
  for (auto _ : state) {
    frame.clear();
    const auto start = std::chrono::steady_clock::now();
    if (!draw(frame)) state.SkipWithError("the draw was refused");
    benchmark::ClobberMemory();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    seconds_in_all += seconds;
  }
  state.counters["leaves"] = leaves;
  state.counters["ns_per_leaf"] =
      seconds_in_all * 1e9 / static_cast<double>(state.iterations()) / leaves;
}

void orthographic(benchmark::State& state, int width, int height) {
  const LevelView& level = model().finestLevel();
  FrameSetup setup;
  if (buildFrameSetup(cameraOf(width, height), level.depth, kDefaultFractionBits, &setup) !=
      CameraError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  timeFrames(state, width, height, [&](Framebuffer& frame) {
    return renderLevel(Variant::kFixedFast, level, setup, frame);
  });
}

void perspective(benchmark::State& state, int width, int height, int fov_degrees) {
  const LevelView& level = model().finestLevel();
  PerspectiveView view;
  if (orbitPerspective(cameraOf(width, height), Angle::fromDegrees(fov_degrees),
                       kDefaultFractionBits, &view) != PerspectiveError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  const PerspectiveWalkTables tables =
      perspectiveWalkTables(view, level.depth, std::int64_t{1} << (kDefaultFractionBits - 2));
  timeFrames(state, width, height,
             [&](Framebuffer& frame) { return drawPerspective(level, view, tables, frame); });
}

// The table's edge drawn by PerspectiveRenderer with `options`; `per_leaf_of` the number of leaves
// ns_per_leaf divides by (0: the points the frame hands to the plot).
void tableEdgeDrawn(benchmark::State& state, int width, int height,
                    const PerspectiveRenderer::Options& options, double per_leaf_of = 0) {
  PerspectiveView view;
  if (buildPerspectiveView(tableEdgeCamera(width, height), kDefaultFractionBits, &view) !=
      PerspectiveError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  PerspectiveRenderer renderer(model());
  // One frame outside the timing: the points it hands over, its coverage, and the tiles made.
  Framebuffer frame(width, height);
  frame.clear();
  PerspectiveDrawStats stats;
  if (!renderer.draw(view, options, frame, &stats)) {
    state.SkipWithError("the draw was refused");
    return;
  }
  std::uint64_t covered = 0;
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) covered += frame.covered(x, y);
  }
  const auto points = static_cast<double>(stats.leaves);
  timeFrames(
      state, width, height, [&](Framebuffer& f) { return renderer.draw(view, options, f); },
      per_leaf_of > 0 ? per_leaf_of : points);
  state.counters["points"] = points;
  state.counters["hidden_subtrees"] = static_cast<double>(stats.hidden_subtrees);
  state.counters["points_per_covered_pixel"] = points / static_cast<double>(covered);
}

// tile_shift 0 draws without culling.
void tableEdge(benchmark::State& state, int width, int height, int tile_shift) {
  PerspectiveRenderer::Options options;
  options.cull = tile_shift != 0;
  if (tile_shift != 0) options.tile_shift = tile_shift;
  tableEdgeDrawn(state, width, height, options);
}

// Ours against the peer on the finest depth's leaves: `depth` 0 by distance, else that depth alone
// (culled, as octopoint-render draws).
void tableEdgeOurs(benchmark::State& state, int width, int height, int depth) {
  PerspectiveRenderer::Options options;
  options.depth = depth;
  tableEdgeDrawn(state, width, height, options,
                 static_cast<double>(model().finestLevel().leaves.size()));
}

template <typename Scalar>
void tableEdgePeer(benchmark::State& state, int width, int height) {
  const PerspectiveCamera camera = tableEdgeCamera(width, height);
  bench::PclPerspectivePeer<Scalar> peer(model(), model().finestLevel(), width, height);
  peer.render(camera);  // the first frame allocates nothing either; its coverage for the counter
  const auto covered = static_cast<double>(peer.coveredPixels());
  double seconds_in_all = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    peer.render(camera);
    benchmark::ClobberMemory();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    seconds_in_all += seconds;
  }
  const auto leaves = static_cast<double>(peer.points());
  state.counters["leaves"] = leaves;
  state.counters["ns_per_leaf"] =
      seconds_in_all * 1e9 / static_cast<double>(state.iterations()) / leaves;
  state.counters["covered_pixels"] = covered;
}

// The walk's tables of one depth (perspectiveWalkTables: its thresholds' bisections), made once
// per frame and stored depth, and by a scene per instance in view and depth.
void walkTables(benchmark::State& state, int width, int height) {
  PerspectiveView view;
  if (buildPerspectiveView(tableEdgeCamera(width, height), kDefaultFractionBits, &view) !=
      PerspectiveError::kNone) {
    state.SkipWithError("camera refused");
    return;
  }
  const int depth = model().finestLevel().depth;
  for (auto _ : state) {
    PerspectiveWalkTables tables =
        perspectiveWalkTables(view, depth, std::int64_t{1} << (kDefaultFractionBits - 2));
    benchmark::DoNotOptimize(tables);
  }
}

}  // namespace

void registerAll() {
  for (const auto& [width, height] : {std::pair{320, 240}, std::pair{1280, 960}}) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    benchmark::RegisterBenchmark(("perspective/tabletop/depth8/" + size + "/orthographic").c_str(),
                                 orthographic, width, height)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
    for (int fov : {60, 10}) {
      benchmark::RegisterBenchmark(
          ("perspective/tabletop/depth8/" + size + "/fov" + std::to_string(fov)).c_str(),
          perspective, width, height, fov)
          ->UseManualTime()
          ->Unit(benchmark::kMicrosecond);
    }
    const std::string edge = "perspective/table_edge/" + size + "/by_distance/";
    for (const auto& [name, shift] :
         {std::pair{"unculled", 0}, std::pair{"culled_tiles4", 2}, std::pair{"culled_tiles8", 3},
          std::pair{"culled_tiles16", 4}}) {
      benchmark::RegisterBenchmark((edge + name).c_str(), tableEdge, width, height, shift)
          ->UseManualTime()
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark(("perspective/table_edge/" + size + "/walk_tables").c_str(),
                                 walkTables, width, height);
    const std::string peer = "perspective/table_edge/" + size + "/peer/";
    const int finest = model().finestLevel().depth;
    for (const auto& [name, depth] :
         {std::pair{"ours_finest", finest}, std::pair{"ours_by_distance", 0}}) {
      benchmark::RegisterBenchmark((peer + name).c_str(), tableEdgeOurs, width, height, depth)
          ->UseManualTime()
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark((peer + "pcl_eigen_float").c_str(), tableEdgePeer<float>, width,
                                 height)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((peer + "pcl_eigen_double").c_str(), tableEdgePeer<double>, width,
                                 height)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace octopoint
