# Prepares SCAN with the default budget and threads, then with --memory 1 --threads 3, and fails
# unless the two .oct files are identical and the second run really spilled to disk.
# cmake -DPREPARE=... -DSCAN=... -DOUT=DIR -P same_output_any_budget.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${PREPARE} ${SCAN} -o ${OUT}/default --name m --depths 5,11
                RESULT_VARIABLE first)
execute_process(COMMAND ${PREPARE} ${SCAN} -o ${OUT}/small --name m --depths 5,11 --memory 1
                --threads 3
                RESULT_VARIABLE second OUTPUT_VARIABLE summary)
if(NOT first EQUAL 0 OR NOT second EQUAL 0)
  message(FATAL_ERROR "octopoint-prepare failed")
endif()
if(NOT summary MATCHES "budget 1 MB, [1-9][0-9]* MB spilled to disk")
  message(FATAL_ERROR "the 1 MB run did not spill to disk: ${summary}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/default/m.oct ${OUT}/small/m.oct
                RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "the model differs between --memory 1 --threads 3 and the defaults")
endif()
message(STATUS "identical: ${summary}")
