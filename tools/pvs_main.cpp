// octopoint-pvs: a scene's visibility cells (docs/city.md, "Visibility cells"): per view cell, the
// instances seen from anywhere in it (tools/cell_build.h), written beside the scene in the cell
// table format (renderer/cell_table.h) that octopoint-render --cells reads.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/output_file.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "tools/cell_build.h"
#include "tools/cell_occlusion.h"
#include "tools/scene_file.h"

namespace {

using namespace octopoint;

constexpr const char* kUsage =
    R"(usage: octopoint-pvs SCENE.json -o CELLS [--cell EDGES] [--layers Y0,Y1,...] [--face PX]
                     [--samples N] [--seed N] [--margin EDGES] [--no-neighbours]
                     [--eps EDGES --near-occluder EDGES [--near-steps N] [--ground Y] [--radii]
                      [--depth-windows]]

Computes a scene's visibility cells (docs/city.md): a grid of view cells over the instances'
extent in x and z and the layers of height the eye may take, and per cell the instances visible
from anywhere in it. From sample points (every cell's corners and centre on its layer's top and
bottom) and N seeded points inside each cell, the scene is drawn to
the six faces of a cube by octopoint's own renderer; an instance is seen when it submitted a point.
Each set is widened by the instances within the margin of its cell and by its eight neighbours'
sets. octopoint-render --city SCENE.json --cells CELLS draws only the eye's cell's set.

  -o CELLS           the cell table written (renderer/cell_table.h: a few percent of the scene)
  --cell EDGES       the cells' edge in x and z, scene edges (default 2; 1/64..4096)
  --layers Y0,...    the layers' bounds in y, scene edges, increasing (y down: the highest
                     first), 2..65 of them (default -1.5,-0.09375,-0.015625: in the generated
                     city 48 m, 3 m and 0.5 m above the ground; an eye outside every layer
                     draws everything)
  --face PX          pixels of a cube face's side, 16..1024 (default 64)
  --samples N        seeded points inside each cell, 0..64 (default 1)
  --seed N           their seed, 0..10^9 (default 1)
  --margin EDGES     instances whose cube comes this near a cell are in its set (default 0.5)
  --no-neighbours    do not widen a set by its neighbours' (for measuring what that buys)
  --winners          an instance is seen when it wins a pixel of a face (the word the frame
                     keeps), not when it submits a point: tighter sets
  --spacing S,...    samples on a lattice over the whole grid on every layer bound, of spacing
                     S scene edges (one per bound, from the top, or one for all), instead of
                     the corners, centres and seeded points, and no neighbours' union: a cell
                     takes what every sample within --reach of it saw
  --reach EDGES      with --spacing: how far from a cell's box its samples may stand (default 0:
                     those in it and on its bounds)

Eroded occlusion maps (conservative by construction, tighter; docs/city.md):
  --eps EDGES        sample each cell's layer box so that every point of it lies within EDGES
                     of a sample, and let each sample stand for every eye within EDGES of it:
                     per cube face an occlusion map in which surfaces nearer than the near
                     occluder distance and depth cracks are empty, eroded by asin(EDGES / NEAR);
                     an instance with a point nearer than the map is in the set. No lattice,
                     seeded points or neighbours then; --face is the face without its border.
  --near-occluder EDGES  surfaces nearer than this do not occlude (needs --eps; above it)
  --near-steps N     maps at the near occluder distance times 1, 2, 4, ... 2^(N-1), each with
                     its own erosion (narrower the farther): an instance is in a sample's set
                     when every one of them lets it in; 1..8 (default 1). Samples shut in
                     (every direction meets a surface, none within EDGES at the layer's
                     heights: inside a building) stand for no eye.
  --ground Y         the scene's ground is the plane y = Y (scene edges, y down; the generated
                     city's: 0), every layer above it and no instance below it: pixels on it
                     are no holes in the maps, near or far (needs --eps)
  --radii            erode each pixel by its own radius: asin(EDGES / NEAR) moves an image
                     by 1 + t^2 of it at x/z offset t, a third of the face corner's at its centre
  --depth-windows    size each pixel's window by the nearest surface in it, at depth D:
                     asin(EDGES / D) rather than asin(EDGES / NEAR), at that pixel's offset
                     (an occluder eroded at its own depth; supersedes --radii). The border
                     is then cut to fit 120 degrees (a window wider: empty), so the near
                     occluder distance may be anything above --eps
)";

// A decimal number of scene edges to Q.24, within +-limit scene edges; cli::Error otherwise.
std::int64_t edgesOption(const std::string& option, const std::string& text, double limit) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(std::fabs(value) <= limit))
    throw cli::Error(option + ": '" + text + "' is no number of scene edges within +-" +
                     std::to_string(static_cast<long long>(limit)));
  return std::llround(std::ldexp(value, kPerspectiveUnitBits));
}

// A comma-separated list of edgesOption's numbers.
std::vector<std::int64_t> edgesList(const std::string& option, const std::string& list,
                                    double limit) {
  std::vector<std::int64_t> values;
  for (std::size_t at = 0; at <= list.size();) {
    const std::size_t comma = std::min(list.find(',', at), list.size());
    values.push_back(edgesOption(option, list.substr(at, comma - at), limit));
    at = comma + 1;
  }
  return values;
}

int run(int argc, char** argv) {
  cli::ArgumentReader args(argc, argv);
  std::string scene_path, output;
  CellBuildOptions options;
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (args.is("-o")) {
      output = args.value();
    } else if (args.is("--cell")) {
      options.edge = edgesOption("--cell", args.value(), 4096);
      if (options.edge < kPerspectiveUnit / 64) throw cli::Error("--cell: below 1/64 scene edge");
    } else if (args.is("--layers")) {
      options.y = edgesList("--layers", args.value(), 128);
      if (options.y.size() < 2 || options.y.size() > kMaxCellLayers + 1)
        throw cli::Error("--layers: give 2 to 65 bounds");
      for (std::size_t k = 1; k < options.y.size(); ++k)
        if (options.y[k] <= options.y[k - 1]) throw cli::Error("--layers: bounds not increasing");
    } else if (args.is("--face")) {
      options.face = cli::parseInt(args.name(), args.value(), 16, 1024);
    } else if (args.is("--samples")) {
      options.random_samples = cli::parseInt(args.name(), args.value(), 0, 64);
    } else if (args.is("--seed")) {
      options.seed =
          static_cast<std::uint32_t>(cli::parseInt(args.name(), args.value(), 0, 1'000'000'000));
    } else if (args.is("--margin")) {
      options.margin = edgesOption("--margin", args.value(), 64);
      if (options.margin < 0) throw cli::Error("--margin: negative");
    } else if (args.is("--eps")) {
      options.eps = edgesOption("--eps", args.value(), 64);
      if (options.eps <= 0) throw cli::Error("--eps: not above 0");
    } else if (args.is("--near-occluder")) {
      options.near_occluder = edgesOption("--near-occluder", args.value(), 1024);
    } else if (args.is("--near-steps")) {
      options.near_steps = cli::parseInt(args.name(), args.value(), 1, 8);
    } else if (args.is("--ground")) {
      options.ground = true;
      options.ground_y = edgesOption("--ground", args.value(), 128);
    } else if (args.is("--radii")) {
      args.noValue();
      options.radii = true;
    } else if (args.is("--depth-windows")) {
      args.noValue();
      options.depth_windows = true;
    } else if (args.is("--winners")) {
      args.noValue();
      options.winners = true;
    } else if (args.is("--spacing")) {
      options.spacing = edgesList("--spacing", args.value(), 64);
      for (const std::int64_t spacing : options.spacing)
        if (spacing < kPerspectiveUnit / 256) throw cli::Error("--spacing: below 1/256 scene edge");
    } else if (args.is("--reach")) {
      options.reach = edgesOption("--reach", args.value(), 64);
      if (options.reach < 0) throw cli::Error("--reach: negative");
    } else if (args.is("--no-neighbours")) {
      args.noValue();
      options.neighbours = false;
    } else if (scene_path.empty() && args.isPlain()) {
      scene_path = args.current();
    } else {
      args.refuseUnknown();
    }
  }
  if (scene_path.empty()) throw cli::Error("no scene given: octopoint-pvs SCENE.json -o CELLS");
  if (output.empty()) throw cli::Error("no output given: use -o CELLS");
  if ((options.eps > 0) != (options.near_occluder != 0))
    throw cli::Error("--eps and --near-occluder go together");
  if (options.reach > 0 && options.spacing.empty()) throw cli::Error("--reach: needs --spacing");
  if (options.spacing.size() > 1 && options.spacing.size() != options.y.size())
    throw cli::Error("--spacing: give one value or one per layer bound");
  if ((!options.spacing.empty() || options.winners) && options.eps > 0)
    throw cli::Error("--spacing and --winners: not with --eps");
  if (options.ground && options.eps == 0) throw cli::Error("--ground: needs --eps");
  if (options.radii && options.eps == 0) throw cli::Error("--radii: needs --eps");
  if (options.depth_windows && options.eps == 0) throw cli::Error("--depth-windows: needs --eps");
  if (options.ground && options.y.back() >= options.ground_y)
    throw cli::Error("--ground: the layers reach down to it (every eye must be above it)");
  if (options.eps > 0 && options.near_occluder <= options.eps)
    throw cli::Error("--near-occluder: not above --eps");
  OcclusionSampling fitting{options.eps, options.near_occluder, options.face};
  fitting.depth_windows = options.depth_windows;
  if (!erosionFits(fitting))
    throw cli::Error(
        "--eps: its erosion would widen a face past 120 degrees: give a larger "
        "--near-occluder (eps / near at most about 0.2)");
  cli::checkOutputFile(output);
  const std::unique_ptr<LoadedScene> scene = loadScene(scene_path);
  const auto start = std::chrono::steady_clock::now();
  const CellBuild build = buildCells(scene->models, scene->instances, options);
  if (build.grid.nx == 0) {
    throw cli::Error(scene->label + ": the cells' grid over its instances would exceed " +
                     std::to_string(kMaxCellsPerAxis) + " cells a side or " +
                     std::to_string(kMaxCells) + " cells: give a larger --cell");
  }
  const std::vector<std::uint8_t> bytes = encodeCellTable(build.grid, build.sets);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  cli::writeFileAtomically(output, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  std::size_t total = 0, largest = 0;
  for (const auto& set : build.sets) {
    total += set.size();
    largest = std::max(largest, set.size());
  }
  std::printf(
      "%s: %u x %u cells x %u layers, %llu samples (%llu frames of %dx%d, erosion %d px) in %.1f "
      "s: "
      "sets of %.0f "
      "of %zu instances on average, largest %zu; %zu bytes -> %s\n",
      scene->label.c_str(), build.grid.nx, build.grid.nz, build.grid.ny,
      static_cast<unsigned long long>(build.samples), static_cast<unsigned long long>(build.frames),
      build.side, build.side, build.rho, seconds,
      static_cast<double>(total) / static_cast<double>(build.sets.size()), scene->instances.size(),
      largest, bytes.size(), output.c_str());
  if (options.eps > 0 && build.maps.pixels > 0) {
    const auto share = [&](std::uint64_t n) {
      return 100.0 * static_cast<double>(n) / static_cast<double>(build.maps.pixels);
    };
    std::printf(
        "maps: %.1f%% of pixels near, %.1f%% cracks, %.1f%% ground, %.1f%% empty after the "
        "erosion; %llu samples enclosed\n",
        share(build.maps.near), share(build.maps.cracks), share(build.maps.ground),
        share(build.maps.open), static_cast<unsigned long long>(build.maps.enclosed));
    std::printf("maps empty after the erosion, per near step:");
    for (int step = 0; step < options.near_steps; ++step) {
      std::printf(
          " %.1f%% (near %.3g edges)", share(build.maps.open_steps[step]),
          std::ldexp(static_cast<double>(options.near_occluder << step), -kPerspectiveUnitBits));
    }
    std::printf("\n");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-pvs", argc, argv, run);
}
