# octopoint-render --perspective and --eye on a chunked model file (docs/perspective.md, "Chunked
# models"): the scan prepared with --chunked and as one file of the same depths (the chunked file's
# base included) draws the same PNG, byte for byte, from an orbit camera in perspective and
# from an eye at the cube's corner looking in; and, orthographic, with smooth splats
# (docs/splats.md: the progressive model blends what it holds), which differ from box splats; --info states the same sample reach for each depth of both.
# usage: cmake -DRENDER=... -DPREPARE=... -DSCAN=sphere.pcd -DOUT=DIR -P this
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/one ${OUT}/chunked)

function(run output_variable)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${ARGN} failed (${status}): ${err}")
  endif()
  set(${output_variable} "${out}" PARENT_SCOPE)
endfunction()

run(ignored ${PREPARE} ${SCAN} -o ${OUT}/chunked --name m --depths 4,5,6 --chunked)
run(info ${RENDER} --file ${OUT}/chunked/m.oct --info)
# The depths it holds, the base's included.
string(REGEX MATCHALL "\ndepth [0-9]+" depth_lines "${info}")
string(REGEX REPLACE "\ndepth " "" depths "${depth_lines}")
string(REPLACE ";" "," depths "${depths}")
if(NOT depths MATCHES "^[0-9]+(,[0-9]+)+$")
  message(FATAL_ERROR "--info names no depths: ${info}")
endif()
if(NOT info MATCHES "\ncube ([-0-9.e+]+),([-0-9.e+]+),([-0-9.e+]+) ")
  message(FATAL_ERROR "--info names no cube: ${info}")
endif()
set(corner "${CMAKE_MATCH_1},${CMAKE_MATCH_2},${CMAKE_MATCH_3}")
run(ignored ${PREPARE} ${SCAN} -o ${OUT}/one --name m --depths ${depths})
# Each depth's sample reach, as the chunked file and the one file state it: the same.
function(sample_reaches output_variable text)
  string(REGEX MATCHALL "\ndepth [0-9]+[^\n]*sample reach [0-9.]+" lines "${text}")
  string(REGEX REPLACE "\ndepth ([0-9]+)[^;]*sample reach ([0-9.]+)" "\\1:\\2" reaches "${lines}")
  set(${output_variable} "${reaches}" PARENT_SCOPE)
endfunction()
run(one_info ${RENDER} --file ${OUT}/one/m.oct --info)
sample_reaches(chunked_reaches "${info}")
sample_reaches(one_reaches "${one_info}")
if(NOT chunked_reaches STREQUAL one_reaches OR chunked_reaches STREQUAL "")
  message(FATAL_ERROR "the sample reaches differ: chunked '${chunked_reaches}', one file "
                      "'${one_reaches}'")
endif()

foreach(view "orbit;--perspective;--yaw;30;--pitch;15;--zoom;2"
             "eye;--eye;${corner};--look;45,-35;--fov;90")
  list(POP_FRONT view name)
  foreach(model one chunked)
    run(said ${RENDER} --file ${OUT}/${model}/m.oct ${view} --size 320x240
        -o ${OUT}/${model}_${name}.png)
    if(NOT said MATCHES " ([1-9][0-9]*) points drawn")
      message(FATAL_ERROR "${model} ${name}: no points drawn: ${said}")
    endif()
    set(${model}_points ${CMAKE_MATCH_1})
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/one_${name}.png
                  ${OUT}/chunked_${name}.png RESULT_VARIABLE differ)
  if(differ OR NOT one_points EQUAL chunked_points)
    message(FATAL_ERROR "${name}: the chunked file's frame (${chunked_points} points) is not the "
                        "one file's (${one_points})")
  endif()
  message(STATUS "${name}: ${chunked_points} points, the same PNG from both files")
endforeach()

foreach(splats box smooth)
  foreach(model one chunked)
    run(said ${RENDER} --file ${OUT}/${model}/m.oct --yaw 30 --pitch 15 --zoom 3 --size 320x240
        --splats ${splats} -o ${OUT}/${model}_${splats}.png)
    if(NOT said MATCHES "depth ([0-9]+)[^,]*, ([1-9][0-9]*) points")
      message(FATAL_ERROR "${model} ${splats}: nothing drawn: ${said}")
    endif()
    set(${model}_drawn "depth ${CMAKE_MATCH_1}, ${CMAKE_MATCH_2} points")
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/one_${splats}.png
                  ${OUT}/chunked_${splats}.png RESULT_VARIABLE differ)
  if(differ OR NOT one_drawn STREQUAL chunked_drawn)
    message(FATAL_ERROR "--splats ${splats}: the chunked file's frame (${chunked_drawn}) is not "
                        "the one file's (${one_drawn})")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/chunked_box.png
                ${OUT}/chunked_smooth.png RESULT_VARIABLE differ)
if(NOT differ)
  message(FATAL_ERROR "--splats smooth drew the chunked file's box frame: nothing blended")
endif()
message(STATUS "box and smooth splats: the same PNGs from both files (${chunked_drawn})")
