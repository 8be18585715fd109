# The chunked format and the progressive model (issue 12; included from tests/CMakeLists.txt). No
# PCL: the chunked writer and the parts of the preparer it needs are compiled in as sources, so
# these tests also run on the device build.
set(codegen ${PROJECT_SOURCE_DIR}/codegen)
add_executable(chunked_tests
  chunked_format_test.cpp
  chunked_test_support.cpp
  chunked_writer_test.cpp
  point_budget_test.cpp
  progressive_model_test.cpp
  ${PROJECT_SOURCE_DIR}/fuzz/model_images.cpp
  ${codegen}/chunked_writer.cpp
  ${codegen}/level_voxels.cpp
  ${codegen}/oct_serializer.cpp
  ${codegen}/octree_encoder.cpp)
target_link_libraries(chunked_tests PRIVATE octopoint_renderer octopoint_models GTest::gtest_main
                      octopoint_warnings)
gtest_discover_tests(chunked_tests DISCOVERY_MODE PRE_TEST)
