# A scene's eyes and paths end to end (docs/scene.md, "Eyes and paths"): the default model's scan
# prepared for a walk at the table's edge, pruned and unpruned; from every listed eye and every
# frame of the path (as octopoint-render --eye and --path --frames draw them) the two models draw
# the same PNG, byte for byte, also in the lit styles of a model with normals; the pruned model is
# smaller; an eye not on the list differs.
# usage: cmake -DPREPARE=... -DRENDER=... -DSCAN=milk.pcd -DSCENE=tabletop_walk.json -DOUT=DIR
#        -P this
cmake_policy(VERSION 3.20)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
include(${CMAKE_CURRENT_LIST_DIR}/render_checks.cmake)  # render_ok, same_files

# The same scene without pruning, its path file beside it.
get_filename_component(scene_dir ${SCENE} DIRECTORY)
file(COPY ${scene_dir}/tabletop_walk_path.json DESTINATION ${OUT})
file(READ ${SCENE} scene)
string(REGEX REPLACE "}[ \n]*$" ",\n  \"prune\": false\n}\n" unpruned "${scene}")
file(WRITE ${OUT}/unpruned.json "${unpruned}")

foreach(kind pruned unpruned)
  set(scene_file ${SCENE})
  if(kind STREQUAL "unpruned")
    set(scene_file ${OUT}/unpruned.json)
  endif()
  execute_process(COMMAND ${PREPARE} ${SCAN} --scene ${scene_file} -o ${OUT}/${kind} --name walk
                  RESULT_VARIABLE status OUTPUT_VARIABLE report ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "octopoint-prepare --scene ${scene_file} failed (${status}): ${err}")
  endif()
  message(STATUS "${kind}: ${report}")
  file(SIZE ${OUT}/${kind}/walk.oct ${kind}_bytes)
endforeach()
if(NOT pruned_bytes LESS unpruned_bytes)
  message(FATAL_ERROR "pruning kept everything: ${pruned_bytes} bytes of ${unpruned_bytes}")
endif()

# The listed eyes (as the scene gives them) and the path's 16 frames.
set(index 0)
foreach(pair "0.05,0.1,-0.45|-5,-20" "-0.12,0.06,-0.62|15,-20")
  string(REPLACE "|" ";" parts "${pair}")
  list(GET parts 0 at)
  list(GET parts 1 look)
  foreach(kind pruned unpruned)
    render_ok(out --file ${OUT}/${kind}/walk.oct --eye ${at} --look ${look} --fov 70
              --size 320x240 -o ${OUT}/${kind}_eye${index}.png)
  endforeach()
  same_files(${OUT}/pruned_eye${index}.png ${OUT}/unpruned_eye${index}.png)
  math(EXPR index "${index} + 1")
endforeach()
foreach(kind pruned unpruned)
  render_ok(out --file ${OUT}/${kind}/walk.oct --path ${OUT}/tabletop_walk_path.json --frames 16
            --size 320x240 -o ${OUT}/${kind}_path.png)
endforeach()
foreach(frame RANGE 15)
  string(LENGTH "${frame}" digits)
  set(name "000${frame}")
  if(digits EQUAL 2)
    set(name "00${frame}")
  endif()
  same_files(${OUT}/pruned_path_${name}.png ${OUT}/unpruned_path_${name}.png)
endforeach()

# An eye not on the list (beside the table, looking across it at the Clorox bottle's side, which
# the walk never sees): the pruned model lacks that side, so the frames differ.
foreach(kind pruned unpruned)
  render_ok(out --file ${OUT}/${kind}/walk.oct --eye 0.32,0.25,-0.75 --look -90,-35 --fov 70
            --size 320x240 -o ${OUT}/${kind}_unlisted.png)
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/pruned_unlisted.png
                        ${OUT}/unpruned_unlisted.png RESULT_VARIABLE differ)
if(NOT differ)
  message(FATAL_ERROR "an eye not on the list draws the same frame: nothing it sees was pruned")
endif()
message(STATUS "pruned ${pruned_bytes} bytes, unpruned ${unpruned_bytes}")

# With normals (the whole-scan preparer): the lit styles' frames, whose depth code is coarser, are
# kept too: the first eye shaded and outlined, and the path shaded, the same PNGs.
foreach(kind pruned unpruned)
  set(text "${scene}")
  if(kind STREQUAL "unpruned")
    set(text "${unpruned}")
  endif()
  string(REGEX REPLACE "}[ \n]*$" ",\n  \"normals\": true\n}\n" text "${text}")
  file(WRITE ${OUT}/normals_${kind}.json "${text}")
  execute_process(COMMAND ${PREPARE} ${SCAN} --scene ${OUT}/normals_${kind}.json
                          -o ${OUT}/normals_${kind} --name walk
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "octopoint-prepare with normals failed (${status}): ${err}")
  endif()
  foreach(style shaded outlined)
    render_ok(out --file ${OUT}/normals_${kind}/walk.oct --eye 0.05,0.1,-0.45 --look -5,-20
              --fov 70 --style ${style} -o ${OUT}/normals_${kind}_${style}.png)
  endforeach()
  render_ok(out --file ${OUT}/normals_${kind}/walk.oct --path ${OUT}/tabletop_walk_path.json
            --frames 16 --style shaded -o ${OUT}/normals_${kind}_path.png)
endforeach()
foreach(style shaded outlined)
  same_files(${OUT}/normals_pruned_${style}.png ${OUT}/normals_unpruned_${style}.png)
endforeach()
foreach(frame 0000 0005 0010 0015)
  same_files(${OUT}/normals_pruned_path_${frame}.png ${OUT}/normals_unpruned_path_${frame}.png)
endforeach()
