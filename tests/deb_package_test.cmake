# The Debian package (cmake/OctopointPackage.cmake; ctest runs it with cmake -P, label `package`):
# `cpack -G DEB` on this build, then `dpkg-deb` lists what is inside. The user tools, the manual
# header and the CMake package must be there under /usr, nothing outside include/octopoint/ among
# the headers, and dpkg-shlibdeps must have filled in the dependencies.
# Variables: BUILD_DIR (the octopoint build), WORK (scratch).
file(REMOVE_RECURSE "${WORK}")
include(${CMAKE_CURRENT_LIST_DIR}/run_or_fail.cmake)
run(${CMAKE_COMMAND} -E chdir "${BUILD_DIR}" ${CMAKE_CPACK_COMMAND} -G DEB -B "${WORK}")
file(GLOB debs "${WORK}/octopoint_*.deb")
list(LENGTH debs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "cpack made ${count} packages in ${WORK}, not one: ${output}")
endif()
run(dpkg-deb -c "${debs}")
set(contents "${output}")
foreach(path bin/octopoint-render bin/octopoint-view bin/octopoint-serve bin/octopoint-prepare
             include/octopoint/octopoint.h lib/cmake/octopoint/octopointConfig.cmake)
  if(NOT contents MATCHES " \\./usr/${path}\n")
    message(FATAL_ERROR "the package has no /usr/${path}:\n${contents}")
  endif()
endforeach()
string(REGEX MATCHALL " \\./usr/include/[^\n]*[^/]\n" headers "${contents}")
foreach(header IN LISTS headers)
  if(NOT header MATCHES "^ \\./usr/include/octopoint/[a-z_0-9]+\\.h\n$")
    message(FATAL_ERROR "the package installs a header outside include/octopoint/: ${header}")
  endif()
endforeach()
run(dpkg-deb -f "${debs}" Package Version Depends)
if(NOT output MATCHES "Package: octopoint\n" OR NOT output MATCHES "Depends: [^\n]*libc6")
  message(FATAL_ERROR "the package's control fields are not what dpkg-shlibdeps gives:\n${output}")
endif()
list(LENGTH headers header_count)
get_filename_component(name "${debs}" NAME)
message(STATUS "${name}: ${header_count} headers; ${output}")
