# The Debian package: `cpack -G DEB` in a build directory packs what `cmake --install` installs
# (cmake/OctopointInstall.cmake): the user tools octopoint-prepare(-pcl), -render, -view and -serve,
# the static libraries, the headers under include/octopoint/ and the CMake package, under /usr.
# The dependencies are what dpkg-shlibdeps reads off the tools (PCL, OpenCV, SDL2, ...), so the
# package names the library packages this build linked against. The package test
# (tests/deb_package_test.cmake, label `package`) builds it and lists what is inside.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME octopoint)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR octopoint)
set(OCTOPOINT_PACKAGE_MAINTAINER "octopoint maintainers"
    CACHE STRING "The Debian package's Maintainer field: Name <email> of whoever publishes it")
set(CPACK_PACKAGE_CONTACT "${OCTOPOINT_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "integer-only point-based renderer for range scans: tools, libraries and headers")
set(CPACK_PACKAGE_DESCRIPTION
    "octopoint turns a 3D range scan into a compact octree and draws it with integer arithmetic "
    "only (no FPU, no GPU). The package holds the user tools (octopoint-prepare, octopoint-render, "
    "octopoint-view, octopoint-serve), the static libraries, the headers under "
    "include/octopoint/ (the manual is octopoint/octopoint.h) and the CMake package "
    "(find_package(octopoint)). Licence: BSD-3-Clause.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # octopoint_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The headers' and the CMake package's own dependencies, which no binary shows dpkg-shlibdeps.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "pkg-config, libcpp-httplib-dev")
# Debian keeps a package's licence in /usr/share/doc/PACKAGE/copyright.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} RENAME copyright)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
include(CPack)
