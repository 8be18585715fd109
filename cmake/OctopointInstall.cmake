# Install rules and the exported CMake package, so that another project can
#   find_package(octopoint REQUIRED)
#   octopoint_add_model(TARGET app NAME face SCAN face.pcd SCENE scene.json)
# (docs/embedding.md). Only the public headers are installed, under include/octopoint/; the manual
# is include/octopoint/octopoint.h.
#
# Every library whose headers are installed is exported, so that whatever an installed header
# declares links: fixedpoint/ (octopoint::fixedpoint), renderer/ (octopoint::renderer, and
# octopoint::interactive for the dual-resolution renderer and its view events), models/
# (octopoint::models: the committed default model and its registry) and, in a build with the
# tools, net/ (octopoint::net: octopoint/http.h on cpp-httplib, which the package's config finds
# with pkg-config). The package test (tests/package_test.cmake) links a program against every
# exported target.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(octopoint_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/octopoint)
set(octopoint_exported octopoint_fixedpoint octopoint_renderer octopoint_models)
if(TARGET octopoint_interactive)  # not in a bare-metal build (no threads)
  list(APPEND octopoint_exported octopoint_interactive)
endif()
set(OCTOPOINT_EXPORTS_NET OFF)  # for octopointConfig.cmake.in: find cpp-httplib only when needed
if(TARGET octopoint_net)  # a build with the tools (OCTOPOINT_BUILD_APPS)
  list(APPEND octopoint_exported octopoint_net)
  set(OCTOPOINT_EXPORTS_NET ON)
endif()
foreach(target IN LISTS octopoint_exported)
  string(REPLACE "octopoint_" "" name ${target})
  target_include_directories(${target} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
endforeach()
# A header is installed only with the library that defines what it declares.
set(octopoint_unbuilt_headers)
if(NOT TARGET octopoint_interactive)
  list(APPEND octopoint_unbuilt_headers PATTERN interactive.h EXCLUDE)
endif()
if(NOT TARGET octopoint_net)
  list(APPEND octopoint_unbuilt_headers PATTERN http.h EXCLUDE)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/octopoint DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        ${octopoint_unbuilt_headers})
# The warnings target travels along only as a link-only dependency of the static libraries.
set_target_properties(octopoint_warnings PROPERTIES EXPORT_NAME warnings)
install(TARGETS ${octopoint_exported} octopoint_warnings EXPORT octopointTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
if(TARGET octopoint-prepare)
  install(TARGETS octopoint-prepare EXPORT octopointTargets RUNTIME DESTINATION
          ${CMAKE_INSTALL_BINDIR})
  # Not exported: octopoint-prepare runs it from its own directory (codegen/whole_scan.h).
  install(TARGETS octopoint-prepare-pcl RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
# The other user tools (tools/); the measuring tools (lab/) are not installed.
foreach(tool octopoint-render octopoint-view octopoint-serve)
  if(TARGET ${tool})
    install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()
install(EXPORT octopointTargets NAMESPACE octopoint:: DESTINATION ${octopoint_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/octopointConfig.cmake.in
  ${PROJECT_BINARY_DIR}/octopointConfig.cmake INSTALL_DESTINATION ${octopoint_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/octopointConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/octopointConfig.cmake
              ${PROJECT_BINARY_DIR}/octopointConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/OctopointAddModel.cmake
        DESTINATION ${octopoint_cmake_dir})
