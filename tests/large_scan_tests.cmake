# LAS input and the streamed preparer. Included from tests/CMakeLists.txt after its CLI
# helpers (prepare_error_test) are defined.

# The streamed preparer against the in-memory reference, across budgets and threads; the LAS
# reader with every format, corner and damaged header. PCL writes the PCD/PLY files to compare with.
add_executable(streamed_tests preparer/las_reader_test.cpp preparer/laz_coder_test.cpp
               preparer/laz_reader_test.cpp preparer/laz_selective_test.cpp
               preparer/copc_reader_test.cpp preparer/header_box_test.cpp
               preparer/streamed_prepare_test.cpp)
target_link_libraries(streamed_tests PRIVATE octopoint_prepare octopoint_scan_tools
                      octopoint_test_scans pcl_common pcl_io GTest::gtest_main octopoint_warnings)
gtest_discover_tests(streamed_tests DISCOVERY_MODE PRE_TEST)

# Scans made at test time into the build directory: a LAS file of every point format, the hidden
# corners (1.0 and 1.1, 1.4 with VLRs, EVLRs and extra bytes, 8-bit colour), binary PLY, and the
# broken LAS files of make_bad_las.
set(las_scans ${CMAKE_CURRENT_BINARY_DIR}/las_scans)
add_test(NAME cli.make_las_scans
         COMMAND ${CMAKE_COMMAND} -DMAKE=$<TARGET_FILE:make_large_scan>
                 -DMAKE_BAD=$<TARGET_FILE:make_bad_las>
                 -DOUT=${las_scans} -P ${CMAKE_CURRENT_SOURCE_DIR}/make_las_scans.cmake)
set_tests_properties(cli.make_las_scans PROPERTIES FIXTURES_SETUP las_scans)

foreach(format RANGE 0 10)
  add_test(NAME cli.prepare.las_format_${format}
           COMMAND octopoint-prepare ${las_scans}/format${format}.las
                   -o ${cli_out}/las_format_${format} --name m --depths 6,9)
  set_tests_properties(cli.prepare.las_format_${format} PROPERTIES FIXTURES_REQUIRED las_scans
                       PASS_REGULAR_EXPRESSION "streamed LAS 1\\.[2-4], point format ${format},")
endforeach()
function(las_corner_test name scan expected)
  add_test(NAME cli.prepare.las_${name}
           COMMAND octopoint-prepare ${las_scans}/${scan} -o ${cli_out}/las_${name} --name m
                   --depths 6,9)
  set_tests_properties(cli.prepare.las_${name} PROPERTIES FIXTURES_REQUIRED las_scans
                       PASS_REGULAR_EXPRESSION "${expected}")
endfunction()
las_corner_test(version_1_0 v10.las "streamed LAS 1\\.0, point format 1, 28-byte records")
las_corner_test(version_1_1 v11.las "streamed LAS 1\\.1, point format 0,")
las_corner_test(vlrs_evlrs_extra_bytes rich.las
                "streamed LAS 1\\.4, point format 7, 45-byte records, 16-bit colour")
las_corner_test(eight_bit_colour colour8.las "8-bit colour in 16-bit fields")
las_corner_test(binary_ply land.ply "streamed binary PLY: 20000 points")

# The output does not depend on the memory budget or the thread count: 1 MB and three threads
# (points spilled, bins split again) against the defaults, byte for byte.
add_test(NAME cli.prepare.same_output_any_budget
         COMMAND ${CMAKE_COMMAND} -DPREPARE=$<TARGET_FILE:octopoint-prepare>
                 -DSCAN=${las_scans}/budget.las
                 -DOUT=${cli_out}/same_output -P
                 ${CMAKE_CURRENT_SOURCE_DIR}/same_output_any_budget.cmake)
set_tests_properties(cli.prepare.same_output_any_budget PROPERTIES FIXTURES_REQUIRED las_scans)

add_test(NAME cli.prepare.starts_without_pcl
         COMMAND ${CMAKE_COMMAND} -DPREPARE=$<TARGET_FILE:octopoint-prepare>
                 -DLAS=${las_scans}/budget.las
                 -DPCD=${PROJECT_SOURCE_DIR}/data/scans/milk.pcd -DOUT=${cli_out}/without_pcl
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/prepare_without_pcl.cmake)
set_tests_properties(cli.prepare.starts_without_pcl PROPERTIES FIXTURES_REQUIRED las_scans)

# Bad LAS files: one line, exit 1, no output; under a 1 GiB address-space limit, which a header
# that made the reader allocate what it declares would exceed at once. AddressSanitizer reserves
# terabytes of shadow address space, so its builds cap each allocation at 1 GiB instead.
if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=[a-z,]*address")
  set(memory_limit)
  string(CONCAT memory_limit_environment "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:"
         "allocator_may_return_null=0:max_allocation_size_mb=1024")
else()
  set(memory_limit /bin/bash -c "ulimit -v 1048576 && exec \"$@\"" bash)
  set(memory_limit_environment)
endif()
function(bad_las_test name expected scan)
  add_test(NAME cli.prepare.bad_las_${name}
           COMMAND ${expect_error} "${expected}" ${cli_out}/bad_las_${name} -- ${memory_limit}
                   $<TARGET_FILE:octopoint-prepare> ${las_scans}/bad/${scan}
                   -o ${cli_out}/bad_las_${name} --name m)
  set_tests_properties(cli.prepare.bad_las_${name} PROPERTIES FIXTURES_REQUIRED las_scans
                       ENVIRONMENT "${memory_limit_environment}")
endfunction()
bad_las_test(count_lies "truncated: header declares 2001 points" count_lies.las)
bad_las_test(count_2e64 "header declares 18446744073709551615 points" count_2e64.las)
bad_las_test(truncated "truncated" truncated.las)
bad_las_test(scale_zero "absurd X scale factor 0" scale_zero.las)
bad_las_test(scale_huge "absurd Y scale factor 1e+300" scale_huge.las)
bad_las_test(offset_nan "absurd Z offset nan" offset_nan.las)
bad_las_test(vlr_overrun "runs into the point data" vlr_overrun.las)
bad_las_test(laz_without_vlr "says LAZ (compressed), but no LASzip VLR" compressed.laz)
bad_las_test(sparse_1tb "the point data has a hole" sparse_1tb.las)

# The streamed preparer's own options and limits.
function(stream_error_test name expected)
  prepare_error_test(${name} "${expected}" ${ARGN})
  set_tests_properties(cli.prepare.${name} PROPERTIES FIXTURES_REQUIRED las_scans)
endfunction()
stream_error_test(temp_dir_missing "not a directory, so no temporary files can go there"
                  ${las_scans}/budget.las -o ${cli_out}/temp_dir_missing --name m --memory 1
                  --temp-dir ${cli_out}/no_such_directory)
stream_error_test(memory_zero "--memory" ${las_scans}/format0.las -o ${cli_out}/memory_zero --name m
                  --memory 0)
stream_error_test(threads_fraction "--threads" ${las_scans}/format0.las
                  -o ${cli_out}/threads_fraction --name m --threads 1.5)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/outliers_scene.json
     "{\"yaw\": [-10, 10], \"framebuffer\": [64, 48], \"depths\": [5],\n"
     " \"outliers\": {\"method\": \"statistical\", \"neighbours\": 8, \"stddev\": 2}}\n")
stream_error_test(las_outliers
                  "outlier removal (the scene's \"outliers\") needs the whole scan in memory"
                  ${las_scans}/format0.las -o ${cli_out}/las_outliers --name m
                  --scene ${CMAKE_CURRENT_BINARY_DIR}/outliers_scene.json)
stream_error_test(las_normals "normal estimation (--normals) needs the whole scan in memory"
                  ${las_scans}/format0.las -o ${cli_out}/las_normals --name m --normals)

# An independent decoder for the LAZ that make_large_scan writes: laz-perf (WebAssembly, from npm,
# installed under build/node by scripts/fetch-laz-perf), run by Node.
find_program(OCTOPOINT_NODE NAMES node nodejs)
if(OCTOPOINT_NODE)
  add_test(NAME laz.laz_perf_decodes_our_files
           COMMAND ${CMAKE_COMMAND} -DMAKE=$<TARGET_FILE:make_large_scan> -DNODE=${OCTOPOINT_NODE}
                   -DMODULES=${PROJECT_SOURCE_DIR}/build/node/node_modules
                   -DSCRIPT=${CMAKE_CURRENT_SOURCE_DIR}/laz/laz_perf_decode.cjs
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/laz_perf -P
                   ${CMAKE_CURRENT_SOURCE_DIR}/laz/laz_perf_check.cmake)
  set_tests_properties(laz.laz_perf_decodes_our_files PROPERTIES
                       SKIP_REGULAR_EXPRESSION "laz-perf is not installed" TIMEOUT 300)
endif()
