# prepare_bench: the whole preparer on a real scan and on synthetic 1M/3M/10M-point scans,
# and the streamed preparer on LAS landscapes (tests/support's landscape and LAS writer).
if(TARGET octopoint_prepare AND TARGET octopoint_scan_tools)
  add_executable(prepare_bench prepare_bench.cpp)
  set(default_bench_scan ${PROJECT_SOURCE_DIR}/data/scans/milk_cartoon_all_small_clorox.pcd)
  target_compile_definitions(prepare_bench PRIVATE
    OCTOPOINT_DEFAULT_BENCH_SCAN="${default_bench_scan}")
  target_link_libraries(prepare_bench PRIVATE octopoint_prepare octopoint_scan_tools
                        benchmark::benchmark octopoint_warnings)
endif()
