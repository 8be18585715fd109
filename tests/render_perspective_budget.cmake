# octopoint-render --point-budget with --eye (docs/perspective.md, "Point budget"): a budget the
# frame fits changes nothing (the same PNG, byte for byte); a smaller one draws at most that many
# points, fewer for a smaller budget, the same PNG every run; the far parts go coarser first.
# usage: cmake -DRENDER=... -DOUT=DIR -P this
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

# Draws the view at the table's edge of the default model with ARGN; sets `points` and the PNG.
function(draw name)
  execute_process(COMMAND ${RENDER} --eye 0.05,0.1,-0.45 --look -5,-20 --fov 70 ${ARGN}
                          -o ${OUT}/${name}.png
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0 OR NOT out MATCHES " ([0-9]+) points drawn")
    message(FATAL_ERROR "${name}: failed (${status}): ${out}${err}")
  endif()
  set(points ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()

function(expect_same a b)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/${a}.png ${OUT}/${b}.png
                  RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "${a} and ${b} differ")
  endif()
endfunction()

draw(none)
set(all ${points})
math(EXPR large "${all} * 10")
draw(large --point-budget ${large})
if(NOT points EQUAL all)
  message(FATAL_ERROR "a budget of ${large} drew ${points} points, not ${all}")
endif()
expect_same(none large)
math(EXPR half "${all} / 2")
math(EXPR eighth "${all} / 8")
draw(half --point-budget ${half})
set(half_points ${points})
draw(half_again --point-budget ${half})
expect_same(half half_again)
draw(eighth --point-budget ${eighth})
if(half_points GREATER half OR points GREATER eighth OR NOT points LESS half_points)
  message(FATAL_ERROR "budgets ${half} and ${eighth} drew ${half_points} and ${points} points")
endif()
message(STATUS "${all} points; within ${half}: ${half_points}; within ${eighth}: ${points}")
