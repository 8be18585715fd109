# The example app built from a clean tree against the installed package (ctest runs it with
# cmake -P): install octopoint into a prefix, configure and build examples/two_models there,
# run it, and check the image it writes.
# Variables: BUILD_DIR (the octopoint build), SOURCE_DIR, WORK (scratch), SCAN_A, SCAN_B, and the
# build's CXX_COMPILER, BUILD_TYPE, CXX_FLAGS, LINKER_FLAGS (a sanitizer build's libraries need
# the same flags in the app that links them).
file(REMOVE_RECURSE "${WORK}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}\n${output}")
  endif()
endfunction()
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/prefix")
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples/two_models" -B "${WORK}/example"
    "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}" "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}" "-DCMAKE_PREFIX_PATH=${WORK}/prefix" "-DSCAN_A=${SCAN_A}"
    "-DSCAN_B=${SCAN_B}")
run(${CMAKE_COMMAND} --build "${WORK}/example")
run("${WORK}/example/two_models" "${WORK}/two_models.ppm")
file(READ "${WORK}/two_models.ppm" header LIMIT 15)
if(NOT header MATCHES "^P6\n320 120\n255\n")
  message(FATAL_ERROR "two_models.ppm has no 320x120 PPM header")
endif()
message(STATUS "example app built against the installed package and drew ${WORK}/two_models.ppm")
