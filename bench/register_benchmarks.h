// Every benchmark program registers its cases here; bench/bench_main.cpp is the one main() they
// share.
#pragma once

namespace octopoint {

// Defined once per benchmark program: registers that program's cases with Google Benchmark before
// the command line is read, so --benchmark_filter and --benchmark_list_tests see all of them.
void registerAll();

}  // namespace octopoint
