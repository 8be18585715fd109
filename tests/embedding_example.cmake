# The example app built from a clean tree against the installed package (ctest runs it with
# cmake -P): install octopoint into a prefix, configure and build examples/two_models there,
# run it, and check the image it writes.
# Variables: BUILD_DIR (the octopoint build), SOURCE_DIR, WORK (scratch), SCAN (the tabletop scan),
# and the build's CXX_COMPILER, BUILD_TYPE, CXX_FLAGS, LINKER_FLAGS (a sanitizer build's libraries
# need the same flags in the app that links them).
if(NOT EXISTS "${SCAN}")
  message(FATAL_ERROR "${SCAN} is missing: run scripts/fetch-scans")
endif()
file(REMOVE_RECURSE "${WORK}")
include(${CMAKE_CURRENT_LIST_DIR}/run_or_fail.cmake)
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/prefix")
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples/two_models" -B "${WORK}/example"
    "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}" "-DCMAKE_PREFIX_PATH=${WORK}/prefix"
    "-DSCAN=${SCAN}")
run(${CMAKE_COMMAND} --build "${WORK}/example")
execute_process(COMMAND "${WORK}/example/two_models" "${WORK}/two_models.ppm" RESULT_VARIABLE status
                OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "two_models failed: ${output}")
endif()
file(READ "${WORK}/two_models.ppm" header LIMIT 15)
if(NOT header MATCHES "^P6\n480 180\n255\n")
  message(FATAL_ERROR "two_models.ppm has no 480x180 PPM header")
endif()
# Each object fills a good part of its 240x180 half (the carton about a quarter, the bottle a
# fifth).
if(NOT output MATCHES "carton and bottle drawn [(]([0-9]+) and ([0-9]+) pixels[)]")
  message(FATAL_ERROR "two_models did not report its pixels: ${output}")
endif()
foreach(covered ${CMAKE_MATCH_1} ${CMAKE_MATCH_2})
  if(covered LESS 5000)
    message(FATAL_ERROR "an object covers only ${covered} of 43200 pixels: ${output}")
  endif()
endforeach()
message(STATUS "example app built against the installed package and drew ${WORK}/two_models.ppm")
