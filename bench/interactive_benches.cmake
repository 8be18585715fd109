# The interactive renderer's benchmarks (included from bench/CMakeLists.txt): hole filling and
# abort latency.
add_executable(hole_fill_bench hole_fill_bench.cpp)
target_link_libraries(hole_fill_bench PRIVATE octopoint_bench_main
                      octopoint_renderer octopoint_models benchmark::benchmark
                      octopoint_warnings)

find_package(Threads REQUIRED)
add_executable(abort_latency_bench abort_latency_bench.cpp)
target_link_libraries(abort_latency_bench PRIVATE octopoint_bench_main
                      octopoint_renderer octopoint_models Threads::Threads
                      benchmark::benchmark octopoint_warnings)
