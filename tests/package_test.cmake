# The package test (ctest runs it with cmake -P, label `package`; docs/embedding.md). On the host:
# 1. a library-only octopoint (OCTOPOINT_LIBRARY_ONLY=ON) configured with every optional
#    dependency made unfindable (PCL, OpenCV, SDL2, GoogleTest, Google Benchmark, nlohmann-json):
#    it must configure, build and install with a compiler and CMake alone, and install no program;
# 2. the full build's install (with the preparer and the tools).
# For the device (TOOLCHAIN_FILE given: the armel build), that build's install.
# Against each prefix, tests/package: every installed header compiled alone, a program that reads
# octopoint/octopoint.h alone and draws, links every exported library target, and runs every
# exported program's --help; on the device it runs under the emulator (qemu-arm). The headers must
# all lie under include/octopoint/, at most 16 of them (one per part of the product).
# Variables: BUILD_DIR (the octopoint build), SOURCE_DIR, WORK (scratch), and the build's
# CXX_COMPILER, LAUNCHER, BUILD_TYPE, CXX_FLAGS, LINKER_FLAGS (a sanitizer build's libraries need
# the same flags in the program that links them); for a cross build TOOLCHAIN_FILE and EMULATOR.
file(REMOVE_RECURSE "${WORK}")
include(${CMAKE_CURRENT_LIST_DIR}/run_or_fail.cmake)
if(TOOLCHAIN_FILE)
  set(compiler "-DCMAKE_TOOLCHAIN_FILE=${TOOLCHAIN_FILE}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
else()
  set(compiler "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
               "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
endif()
if(LAUNCHER)
  list(APPEND compiler "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
endif()

if(TOOLCHAIN_FILE)
  set(installs device)
  run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/device_prefix")
else()
  set(installs library_only full)
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
endif()

foreach(install IN LISTS installs)
  set(prefix "${WORK}/${install}_prefix")
  file(GLOB_RECURSE headers RELATIVE "${prefix}/include" "${prefix}/include/*")
  list(LENGTH headers header_count)
  foreach(header IN LISTS headers)
    if(NOT header MATCHES "^octopoint/[a-z_0-9]+\\.h$")
      message(FATAL_ERROR "the ${install} install has a header outside include/octopoint/: ${header}")
    endif()
  endforeach()
  if(header_count GREATER 16 OR header_count EQUAL 0)
    message(FATAL_ERROR "the ${install} install has ${header_count} headers (1 to 16): ${headers}")
  endif()
  # find_package by the config's own directory: a cross toolchain searches its sysroot only.
  set(consumer "${WORK}/consumer_${install}")
  run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/package" -B "${consumer}" ${compiler}
      "-Doctopoint_DIR=${prefix}/lib/cmake/octopoint" "-DCMAKE_PREFIX_PATH=${prefix}")
  string(REGEX MATCH "exports the libraries [^\n]*" exported "${output}")
  run(${CMAKE_COMMAND} --build "${consumer}" -j 2)
  run(${EMULATOR} "${consumer}/package_consumer")
  if(NOT output MATCHES "[1-9][0-9]* pixels covered at depth [1-9]")
    message(FATAL_ERROR "package_consumer (${install}) did not draw: ${output}")
  endif()
  if(NOT install STREQUAL "library_only" AND NOT output MATCHES "dual-resolution frame at depth [1-9]")
    message(FATAL_ERROR "package_consumer (${install}) drew no dual-resolution frame: ${output}")
  endif()
  if(install STREQUAL "full" AND NOT output MATCHES "URL parsed")
    message(FATAL_ERROR "package_consumer (full) did not link octopoint::net: ${output}")
  endif()
  string(STRIP "${output}" output)
  message(STATUS "${install} install: ${header_count} headers, each compiled alone; ${exported}; "
                 "${output}")
endforeach()
