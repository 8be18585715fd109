# The tradeoff reference (included from tests/CMakeLists.txt): the surface reference against
# synthetic scans with exact answers (and against the exact silhouette of sampled squares), PSNR and
# SSIM against closed forms, the palette ceiling and the error's regions against known answers, and
# a small octopoint-tradeoff --sweep-views run.
add_executable(reference_tests reference_render_test.cpp reference_truth_test.cpp
               image_quality_test.cpp error_regions_test.cpp palette_ceiling_test.cpp
               voxel_cover_test.cpp)
target_link_libraries(reference_tests PRIVATE octopoint_reference octopoint_models opencv_imgproc
                      GTest::gtest_main octopoint_warnings)
gtest_discover_tests(reference_tests DISCOVERY_MODE PRE_TEST)

# The view sweep through the real CLI, small: the synthetic ball seen by a depth camera (organized:
# meshed) and the synthetic sphere (unorganized: splatted), 2 sizes x 2 zooms, one timing round.
foreach(scan depth_image sphere)
  add_test(NAME cli.tradeoff.sweep_smoke_${scan}
           COMMAND ${CMAKE_COMMAND} -DTRADEOFF=$<TARGET_FILE:octopoint-tradeoff>
                   -DSCAN=${test_scans}/${scan}.pcd -DOUT=${cli_out}/tradeoff_sweep_${scan}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/tradeoff_sweep_smoke.cmake)
  set_tests_properties(cli.tradeoff.sweep_smoke_${scan} PROPERTIES FIXTURES_REQUIRED test_scans)
endforeach()

# Bad options: one line naming the flag, no output.
function(tradeoff_error_test name expected)
  add_test(NAME cli.tradeoff.${name}
           COMMAND ${expect_error} "${expected}" ${cli_out}/tradeoff_${name} --
                   $<TARGET_FILE:octopoint-tradeoff> ${ARGN} -o ${cli_out}/tradeoff_${name})
  set_tests_properties(cli.tradeoff.${name} PROPERTIES FIXTURES_REQUIRED test_scans)
endfunction()
tradeoff_error_test(bad_sizes "--sizes: '0x10' is not WxH" ${test_scans}/sphere.pcd --sweep-views --sizes 64x48,0x10)
tradeoff_error_test(bad_zooms "--zooms: 0 is outside 1/65536..32767" ${test_scans}/sphere.pcd --sweep-views --zooms 1,0)
tradeoff_error_test(bad_zoom "--zoom: 'x' is not a number" ${test_scans}/sphere.pcd --zoom x)
tradeoff_error_test(bad_rounds "--rounds: 0 is outside 1..100" ${test_scans}/sphere.pcd --sweep-views --rounds 0)
tradeoff_error_test(bad_label "--label: 'a,b' is not" ${test_scans}/sphere.pcd --sweep-views --label a,b)
tradeoff_error_test(bad_sparse "--sparse: '0.5' is neither 0 nor in 1..10" ${test_scans}/sphere.pcd --sweep-views --sparse 0.5)
tradeoff_error_test(missing_scan "no such file" ${test_scans}/missing.pcd --sweep-views)

# octopoint-reference-truth refuses a malformed disc rule with one line naming the flag.
add_test(NAME cli.reference_truth.bad_rule
         COMMAND ${expect_error} "--rule: '8,0.7' is not K,SCALE,QUANTILE[,EDGE_OFFSET,EDGE_SCALE]"
                 ${cli_out}/reference_truth_bad_rule -- $<TARGET_FILE:octopoint-reference-truth>
                 --rule 8,0.7)
