// The main() of every benchmark program that registers its cases in octopoint::registerAll().
#include <benchmark/benchmark.h>

#include "bench/register_benchmarks.h"

int main(int argc, char** argv) {
  octopoint::registerAll();
  benchmark::Initialize(&argc, argv);
  // A mistyped flag must not silently run every case with defaults.
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
