# What the octopoint-render end-to-end scripts share (render_eye_and_path.cmake,
# render_collide_path.cmake, render_city.cmake): run it with ${RENDER} and expect success (its
# standard output into `output_variable`), or expect exit 1 with one line matching `expected`.
function(render_ok output_variable)
  execute_process(COMMAND ${RENDER} ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "octopoint-render ${ARGN} failed (${status}): ${err}")
  endif()
  set(${output_variable} "${out}" PARENT_SCOPE)
endfunction()

function(render_refused expected)
  execute_process(COMMAND ${RENDER} ${ARGN} RESULT_VARIABLE status ERROR_VARIABLE err)
  string(REGEX MATCHALL "\n" lines "${err}")
  list(LENGTH lines line_count)
  if(NOT status EQUAL 1 OR NOT err MATCHES "${expected}" OR NOT line_count EQUAL 1)
    message(FATAL_ERROR
            "octopoint-render ${ARGN}: wanted exit 1 and one line '${expected}', got ${status}: ${err}")
  endif()
endfunction()

# Fails unless files `a` and `b` hold the same bytes.
function(same_files a b)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${a} ${b} RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "${a} and ${b} differ")
  endif()
endfunction()
