# scripts/measure-city on a small generated city (docs/city.md, "Visibility cells"): frames drawn
# with the cells differ from frames drawing everything in at most 0.1% of the pixels along the
# random walks; with each position's set cut of the instance nearest the eye (--cut) they differ
# by more, so the comparison sees a cut set.
# usage: cmake -DSCRIPT=scripts/measure-city -DOUT=DIR -P this
function(measure output)
  execute_process(COMMAND ${SCRIPT} --blocks 2 --positions 3 --walk 60 --keep ${OUT} ${ARGN}
                  RESULT_VARIABLE code OUTPUT_VARIABLE text ERROR_VARIABLE errors)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "measure-city ${ARGN} failed (${code}):\n${text}${errors}")
  endif()
  string(REGEX MATCH "conservative: worst ([0-9]+)\\.([0-9][0-9])%" found "${text}")
  if(NOT found)
    message(FATAL_ERROR "no 'conservative: worst' line:\n${text}")
  endif()
  math(EXPR hundredths "${CMAKE_MATCH_1} * 100 + ${CMAKE_MATCH_2}")
  set(${output} ${hundredths} PARENT_SCOPE)
  message(STATUS "${text}")
endfunction()

file(REMOVE_RECURSE ${OUT})
measure(whole)
if(whole GREATER 10)
  message(FATAL_ERROR "frames with cells differ by ${whole} hundredths of a percent (at most 10)")
endif()
file(REMOVE_RECURSE ${OUT})
measure(cut --cut)
if(NOT cut GREATER 10)
  message(FATAL_ERROR "sets cut of their nearest instance still within 0.1% (${cut}): the "
                      "comparison does not see what the cells leave out")
endif()
