# laz.laz_perf_decodes_our_files: make_large_scan writes each point format its LAZ encoder knows
# (0 to 3 point-wise, 6 to 8 layered; every field varied, several scanner channels, extra bytes,
# fixed and variable chunks; COPC, whose LAS twin has the records in the same octree order) as LAZ
# and as LAS, and laz-perf
# (tests/laz/laz_perf_decode.cjs) must decode the LAZ to the LAS file's records.
# usage: cmake -DMAKE=make_large_scan -DNODE=node -DMODULES=dir -DSCRIPT=laz_perf_decode.cjs
#              -DOUT=dir -P laz_perf_check.cmake
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
set(cases "0 --extra-bytes 0" "1 --extra-bytes 3" "2 --chunk-points 777" "3 --variable-chunks"
          "6 --extra-bytes 3" "7 --chunk-points 777" "8 --variable-chunks --extra-bytes 2"
          "7 --copc --chunk-points 2000")
foreach(case IN LISTS cases)
  separate_arguments(case)
  list(GET case 0 format)
  list(SUBLIST case 1 -1 options)
  set(name "${OUT}/format${format}")
  foreach(kind las laz)
    execute_process(COMMAND "${MAKE}" --points 60000 --format ${kind} --las-format ${format}
                            --varied-fields ${options} -o "${name}.${kind}"
                    RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "make_large_scan failed for ${name}.${kind}")
    endif()
  endforeach()
  execute_process(COMMAND "${NODE}" "${SCRIPT}" "${MODULES}" "${name}.laz" "${name}.las"
                  RESULT_VARIABLE status)
  if(status EQUAL 77)  # a skip (SKIP_REGULAR_EXPRESSION), which scripts/ctest-no-skips fails
    message(FATAL_ERROR "laz-perf is not installed: run scripts/fetch-laz-perf")
  endif()
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "laz-perf decodes ${name}.laz otherwise than ${name}.las has it")
  endif()
endforeach()
