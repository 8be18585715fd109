# The tradeoff reference (included from tests/CMakeLists.txt): the surface reference against
# synthetic scans with exact answers, and a small octopoint-tradeoff --sweep-views run.
add_executable(reference_tests reference_render_test.cpp)
target_link_libraries(reference_tests PRIVATE octopoint_reference GTest::gtest_main octopoint_warnings)
gtest_discover_tests(reference_tests DISCOVERY_MODE PRE_TEST)
