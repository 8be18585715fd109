# The package test (ctest runs it with cmake -P; docs/embedding.md):
# 1. a library-only octopoint (OCTOPOINT_LIBRARY_ONLY=ON) configured with every optional
#    dependency made unfindable (PCL, OpenCV, SDL2, GoogleTest, Google Benchmark, nlohmann-json):
#    it must configure, build and install with a compiler and CMake alone, and install no program;
# 2. the full build's install (with the preparer);
# and against each prefix, tests/package: a program that links every exported library target,
# compiles every installed header, runs every exported program's --help, and draws.
# Variables: BUILD_DIR (the octopoint build), SOURCE_DIR, WORK (scratch), and the build's
# CXX_COMPILER, LAUNCHER, BUILD_TYPE, CXX_FLAGS, LINKER_FLAGS (a sanitizer build's libraries need
# the same flags in the program that links them).
file(REMOVE_RECURSE "${WORK}")
include(${CMAKE_CURRENT_LIST_DIR}/run_or_fail.cmake)
set(compiler "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
             "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
if(LAUNCHER)
  list(APPEND compiler "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
endif()

set(unfindable)
foreach(package PCL OpenCV SDL2 GTest benchmark nlohmann_json)
  list(APPEND unfindable "-DCMAKE_DISABLE_FIND_PACKAGE_${package}=ON")
endforeach()
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK}/library_only" ${compiler}
    -DCMAKE_CXX_STANDARD=20 -DOCTOPOINT_LIBRARY_ONLY=ON ${unfindable})
run(${CMAKE_COMMAND} --build "${WORK}/library_only" -j 2)
run(${CMAKE_COMMAND} --install "${WORK}/library_only" --prefix "${WORK}/library_only_prefix")
if(EXISTS "${WORK}/library_only_prefix/bin")
  file(GLOB programs "${WORK}/library_only_prefix/bin/*")
  message(FATAL_ERROR "the library-only install installed programs: ${programs}")
endif()

run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/full_prefix")

foreach(install library_only full)
  set(consumer "${WORK}/consumer_${install}")
  run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/package" -B "${consumer}" ${compiler}
      "-DCMAKE_PREFIX_PATH=${WORK}/${install}_prefix")
  string(REGEX MATCH "exports the libraries [^\n]*" exported "${output}")
  run(${CMAKE_COMMAND} --build "${consumer}" -j 2)
  run("${consumer}/package_consumer")
  if(NOT output MATCHES "dual-resolution frame 320x240 at depth [1-9]")
    message(FATAL_ERROR "package_consumer (${install}) did not draw: ${output}")
  endif()
  string(STRIP "${output}" output)
  message(STATUS "${install} install: ${exported}; ${output}")
endforeach()
