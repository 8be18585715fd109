# ctest city.stream_walk (docs/city.md, "Walking over a slow link"): a small generated city (2 x 2
# blocks, make_city and octopoint-prepare --chunked as scripts/make-city --chunked runs them,
# depths 5..8), then octopoint-city-walk: a street walk while the models stream from a real
# octopoint-serve over a shaped link (--check: no frame has a hole inside a surface the complete
# city's frame of the models that had arrived covers, and the last frame, once everything its view
# needs has arrived, is the complete city's, colour for colour).
# usage: cmake -DMAKE_CITY=... -DPREPARE=... -DWALK=... -DSERVE=... -DOUT=DIR -P this
set(CITY_PREPARE_OPTIONS --chunked)
include(${CMAKE_CURRENT_LIST_DIR}/small_city.cmake)
execute_process(COMMAND ${WALK} ${OUT}/city.json --serve ${SERVE} --rate 100000 --latency 50
                        --seconds 8 --seed 3 --truth-scale 1 --settle 240 --check
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "octopoint-city-walk --check failed")
endif()
foreach(line "holes: 0 frames with a hole" "the complete city's, colour for colour")
  string(FIND "${output}" "${line}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "no '${line}' in octopoint-city-walk's output")
  endif()
endforeach()
