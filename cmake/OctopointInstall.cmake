# Install rules and the exported CMake package, so that another project can
#   find_package(octopoint REQUIRED)
#   octopoint_add_model(TARGET app NAME face SCAN face.pcd SCENE scene.json)
# (docs/embedding.md). Headers keep their layout: #include "renderer/render.h".
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(octopoint_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/octopoint)
foreach(library fixedpoint renderer)
  target_include_directories(octopoint_${library} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(octopoint_${library} PROPERTIES EXPORT_NAME ${library})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${library}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${library}
          FILES_MATCHING PATTERN "*.h")
endforeach()
# The warnings target travels along only as a link-only dependency of the static libraries.
set_target_properties(octopoint_warnings PROPERTIES EXPORT_NAME warnings)
install(TARGETS octopoint_fixedpoint octopoint_renderer octopoint_warnings EXPORT octopointTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
if(TARGET octopoint-prepare)
  install(TARGETS octopoint-prepare EXPORT octopointTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(EXPORT octopointTargets NAMESPACE octopoint:: DESTINATION ${octopoint_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/octopointConfig.cmake.in
  ${PROJECT_BINARY_DIR}/octopointConfig.cmake INSTALL_DESTINATION ${octopoint_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/octopointConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/octopointConfig.cmake ${PROJECT_BINARY_DIR}/octopointConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/OctopointAddModel.cmake
        DESTINATION ${octopoint_cmake_dir})
