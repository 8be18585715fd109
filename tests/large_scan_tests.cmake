# Issue 15: LAS input and the streamed preparer. Included from tests/CMakeLists.txt after its CLI
# helpers (prepare_error_test) are defined.

# The procedural landscape and the LAS writer, for make_large_scan and the tests.
add_library(octopoint_scan_tools STATIC tools/landscape.cpp tools/las_writer.cpp)
target_include_directories(octopoint_scan_tools PUBLIC ${PROJECT_SOURCE_DIR})
target_compile_features(octopoint_scan_tools PUBLIC cxx_std_20)
target_link_libraries(octopoint_scan_tools PRIVATE octopoint_warnings)
add_executable(make_large_scan tools/make_large_scan.cpp)
target_link_libraries(make_large_scan PRIVATE octopoint_scan_tools octopoint_warnings)

# The streamed preparer against the in-memory reference, across budgets and threads; the LAS
# reader with every format, corner and damaged header. PCL writes the PCD/PLY files to compare with.
add_executable(streamed_tests las_reader_test.cpp streamed_prepare_test.cpp)
target_link_libraries(streamed_tests PRIVATE octopoint_prepare octopoint_scan_tools octopoint_test_scans
                      pcl_common pcl_io GTest::gtest_main octopoint_warnings)
gtest_discover_tests(streamed_tests DISCOVERY_MODE PRE_TEST)
