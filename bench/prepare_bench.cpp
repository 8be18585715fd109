// The whole preparer, timed: a real 300k-point Kinect scan from its file (load, prepare at depths 7
// and 8, palette, encode, emit the sources and the .oct image), and synthetic scans of 1M, 3M and
// 10M points from memory (the same steps after loading) to show that time grows linearly.
//   prepare_bench --benchmark_repetitions=3
// The real scan defaults to data/scans/milk_cartoon_all_small_clorox.pcd (scripts/fetch-scans);
// OCTOPOINT_BENCH_SCAN names another. BM_PrepareStreamedLas and BM_PrepareStreamedLaz: the
// streamed preparer on LAS and LAZ files of the procedural landscape, one thread against two;
// BM_DecodeLandscape: reading alone, LAS against LAZ, on one thread, of point format 2 (LAZ's
// point-wise items) and 7 (its layered items, LAS 1.4); BM_DecodeLayeredFields: layered LAZ
// decoded whole against only the fields the preparer reads (OCTOPOINT_BENCH_LAZ: a file of yours);
// BM_DecodeLazFile: the file OCTOPOINT_BENCH_LAZ decoded once per iteration, the driver that
// valgrind --tool=callgrind counts a decoded point's instructions with (docs/preparer.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <tuple>

#include "codegen/las_reader.h"
#include "codegen/model_writer.h"
#include "codegen/point_source.h"
#include "codegen/prepare.h"
#include "codegen/scan_loader.h"
#include "codegen/streamed_prepare.h"
#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"

namespace {

using namespace octopoint::prepare;

std::size_t prepareAndEmit(const Scan& scan, const char* path) {
  PrepareOptions options;
  options.name = "bench";
  const PreparedModel model = prepareModel(scan, path, options);
  std::size_t bytes = serializeModel(model).size();
  for (const OutputFile& file : emitSources(model)) bytes += file.contents.size();
  return bytes;
}

void BM_PrepareRealScan(benchmark::State& state) {
  const char* from_env = std::getenv("OCTOPOINT_BENCH_SCAN");
  const std::string path = from_env ? from_env : OCTOPOINT_DEFAULT_BENCH_SCAN;
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("no scan at " + path + ": run scripts/fetch-scans").c_str());
    return;
  }
  std::size_t points = 0;
  for (auto _ : state) {
    const Scan scan = loadScan(path);
    points = scan.points_in_file;
    benchmark::DoNotOptimize(prepareAndEmit(scan, path.c_str()));
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["ns_per_point"] =
      benchmark::Counter(static_cast<double>(points) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PrepareRealScan)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// A scanned head-sized blob: points on a bumpy sphere with range noise, coloured by position, like
// an all-around scan of an object (every voxel of its shell is hit by many points).
const Scan& syntheticScan(std::size_t count) {
  static std::map<std::size_t, Scan> made;
  Scan& scan = made[count];
  if (!scan.positions.empty()) return scan;
  std::mt19937 random(7);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  scan.shading = ScanShading::kColour;
  scan.positions.reserve(count);
  scan.colours.reserve(count);
  while (scan.positions.size() < count) {
    const float x = normal(random), y = normal(random), z = normal(random);
    const float length = std::sqrt(x * x + y * y + z * z);
    if (length < 1e-6f) continue;
    const float radius =
        0.12f * (1.0f + 0.1f * std::sin(9 * x / length) * std::cos(7 * y / length)) +
        0.0005f * normal(random);
    scan.positions.push_back({radius * x / length, radius * y / length, radius * z / length});
    scan.colours.push_back({static_cast<std::uint8_t>(128 + 120 * x / length),
                            static_cast<std::uint8_t>(128 + 120 * y / length),
                            static_cast<std::uint8_t>(128 + 120 * z / length)});
  }
  scan.points_in_file = count;
  return scan;
}

void BM_PrepareSyntheticScan(benchmark::State& state) {
  const Scan& scan = syntheticScan(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(prepareAndEmit(scan, "synthetic.pcd"));
  state.SetComplexityN(state.range(0));
  state.counters["ns_per_point"] = benchmark::Counter(
      static_cast<double>(state.range(0)) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PrepareSyntheticScan)
    ->Arg(1'000'000)
    ->Arg(3'000'000)
    ->Arg(10'000'000)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Iterations(2)
    ->Complexity(benchmark::oN);

// The streamed preparer from a LAS file of the landscape (tests/support/landscape.h) to a depth-12
// model, on one thread and on two side by side: what the second core buys. The file is written
// once into the temporary directory and removed at exit. Reading it is in the time (the page cache
// holds it after the first iteration, as it would after make_large_scan).
// With `varied`, every field of the records changes as in an airborne scan (GPS time, returns,
// scan angle, classes, sources: LasLayout::varied_fields).
const std::string& landscapeLas(std::size_t points, bool laz = false, int format = 2,
                                bool varied = false) {
  static std::map<std::tuple<std::size_t, bool, int, bool>, std::string> written;
  std::string& path = written[{points, laz, format, varied}];
  if (!path.empty()) return path;
  path = (std::filesystem::temp_directory_path() /
          ("octopoint_bench_" + std::to_string(points) + "_format" + std::to_string(format) +
           (varied ? "_varied" : "") + (laz ? ".laz" : ".las")))
             .string();
  octopoint::testing::LasLayout layout;
  layout.laz = laz;
  layout.format = format;
  layout.varied_fields = varied;
  octopoint::testing::LasWriter writer(path, layout);
  const octopoint::testing::Landscape landscape;
  for (std::size_t i = 0; i < points; ++i) writer.add(landscape.point(i));
  writer.finish();
  static struct Cleanup {
    ~Cleanup() {
      for (const auto& [key, file] : written) std::filesystem::remove(file);
    }
  } cleanup;
  return path;
}

// The streamed preparer to a depth-12 model from the landscape as LAS or as LAZ (`laz`; its
// third argument: pass 1's decoded points kept for pass 2, or each chunk decoded in both passes).
void prepareStreamedLandscape(benchmark::State& state, bool laz) {
  const auto points = static_cast<std::size_t>(state.range(0));
  const std::string& path = landscapeLas(points, laz);
  PrepareOptions options;
  options.name = "bench";
  options.depths = {12};
  StreamOptions stream;
  stream.threads = static_cast<unsigned>(state.range(1));
  if (laz) stream.decode_once = state.range(2) != 0;
  for (auto _ : state) {
    const auto source = openPointSource(path);
    benchmark::DoNotOptimize(prepareFromSource(*source, path, options, stream).levels.size());
  }
  state.counters["M_points_per_s"] = benchmark::Counter(
      static_cast<double>(points) * static_cast<double>(state.iterations()) / 1e6,
      benchmark::Counter::kIsRate);
}

void BM_PrepareStreamedLas(benchmark::State& state) { prepareStreamedLandscape(state, false); }
BENCHMARK(BM_PrepareStreamedLas)
    ->ArgsProduct({{1'000'000, 4'000'000}, {1, 2}})
    ->ArgNames({"points", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// The same from the LAZ file of the same points (make_large_scan --format laz: format 2, chunks of
// 50,000): what decoding costs the whole preparer, against BM_PrepareStreamedLas.
void BM_PrepareStreamedLaz(benchmark::State& state) { prepareStreamedLandscape(state, true); }
BENCHMARK(BM_PrepareStreamedLaz)
    ->ArgsProduct({{1'000'000, 4'000'000}, {1, 2}, {0, 1}})
    ->ArgNames({"points", "threads", "decode_once"})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// Reads every piece of `source` in order into one PointChunk per iteration; counts `points` a
// pass as M_points_per_s.
template <typename Source>
void decodeEveryPiece(benchmark::State& state, Source& source, std::uint64_t points) {
  PointChunk chunk;
  for (auto _ : state) {
    for (std::size_t i = 0; i < source.pieceCount(); ++i) {
      const PointRange piece = source.piece(i);
      source.read(piece.first, piece.count, chunk);
      benchmark::DoNotOptimize(chunk.xyz.data());
    }
  }
  state.counters["M_points_per_s"] = benchmark::Counter(
      static_cast<double>(points) * static_cast<double>(state.iterations()) / 1e6,
      benchmark::Counter::kIsRate);
}

// Decoding alone on one thread, every piece in order into PointChunk (doubles, colour,
// intensity), as a pass reads them: LAZ points per second per core, and LAS beside it.
void BM_DecodeLandscape(benchmark::State& state) {
  const auto points = static_cast<std::size_t>(state.range(0));
  const std::string& path =
      landscapeLas(points, state.range(1) != 0, static_cast<int>(state.range(2)));
  const auto source = openPointSource(path);
  decodeEveryPiece(state, *source, points);
}
BENCHMARK(BM_DecodeLandscape)
    ->ArgsProduct({{10'000'000}, {0, 1}, {2, 7}})
    ->ArgNames({"points", "laz", "format"})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// Decoding a layered LAZ file (point format 7, every field varied) on one thread, every field
// (`fields` 0) against the preparer's only (1: position, intensity, colour; the layers of
// classification, flags, scan angle, user data, point source and GPS time stepped over,
// codegen/record_fields.h). OCTOPOINT_BENCH_LAZ names another LAZ file to decode instead (its
// points decoded as often as 4 M points would be, so that a small file times as long).
void BM_DecodeLayeredFields(benchmark::State& state) {
  const char* named = std::getenv("OCTOPOINT_BENCH_LAZ");
  const std::string path =
      named ? std::string(named)
            : landscapeLas(static_cast<std::size_t>(state.range(0)), true, 7, true);
  const auto source =
      openLasSource(path, state.range(1) != 0 ? RecordFields::pointChunk() : RecordFields::all());
  const std::uint64_t points = source->info().points;
  const std::uint64_t rounds = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(state.range(0)) / std::max<std::uint64_t>(points, 1));
  PointChunk chunk;
  for (auto _ : state) {
    for (std::uint64_t round = 0; round < rounds; ++round) {
      for (std::size_t i = 0; i < source->pieceCount(); ++i) {
        const PointRange piece = source->piece(i);
        source->read(piece.first, piece.count, chunk);
        benchmark::DoNotOptimize(chunk.xyz.data());
      }
    }
  }
  state.counters["M_points_per_s"] = benchmark::Counter(
      static_cast<double>(points * rounds) * static_cast<double>(state.iterations()) / 1e6,
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DecodeLayeredFields)
    ->ArgsProduct({{4'000'000}, {0, 1}})
    ->ArgNames({"points", "fields"})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// The LAZ (or LAS) file OCTOPOINT_BENCH_LAZ decoded once per iteration on one thread, every field
// (`fields` 0) or the preparer's (1), without writing anything first: one iteration of it under
// callgrind counts the instructions of a decoded point (its total over the file's points; opening
// the file and the benchmark's own are a few million of them).
//   OCTOPOINT_BENCH_LAZ=F.laz valgrind --tool=callgrind prepare_bench
//     --benchmark_filter=BM_DecodeLazFile/fields:1 --benchmark_min_time=0.01
void BM_DecodeLazFile(benchmark::State& state) {
  const char* named = std::getenv("OCTOPOINT_BENCH_LAZ");
  if (!named) {
    state.SkipWithError("OCTOPOINT_BENCH_LAZ names no file");
    return;
  }
  const auto source =
      openLasSource(named, state.range(0) != 0 ? RecordFields::pointChunk() : RecordFields::all());
  const std::uint64_t points = source->info().points;
  decodeEveryPiece(state, *source, points);
}
BENCHMARK(BM_DecodeLazFile)
    ->ArgsProduct({{0, 1}})
    ->ArgNames({"fields"})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
