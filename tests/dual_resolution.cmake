# Issue 5's thread tests (included from tests/CMakeLists.txt): headless, scripted, real threads.
# Also built by the tsan preset, which runs them under ThreadSanitizer (scripts/test-tsan).
# progressive_threads_test: the progressive model fed while two threads draw it (issue 12).
add_executable(interactive_tests dual_resolution_content_test.cpp dual_resolution_test.cpp
               dual_resolution_window_test.cpp progressive_threads_test.cpp
               ${PROJECT_SOURCE_DIR}/fuzz/model_images.cpp
               ${PROJECT_SOURCE_DIR}/codegen/chunked_writer.cpp
               ${PROJECT_SOURCE_DIR}/codegen/level_voxels.cpp
               ${PROJECT_SOURCE_DIR}/codegen/oct_serializer.cpp
               ${PROJECT_SOURCE_DIR}/codegen/octree_encoder.cpp)
target_link_libraries(interactive_tests PRIVATE octopoint_interactive octopoint_models GTest::gtest_main
                      octopoint_warnings)
gtest_discover_tests(interactive_tests DISCOVERY_MODE PRE_TEST)
