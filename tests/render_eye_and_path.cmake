# octopoint-render --info, --eye/--look and --path end to end (docs/perspective.md, "Using it"):
# - --info prints the cube's placement (`cube X0,Y0,Z0 EDGE`) and each depth's sample reach of a
#   version 6 model, and says that a version 2 file (the same model with its placement and reaches
#   cut out) has none; --eye refuses that file; a reach byte of 0 is refused in one line;
# - an eye at the orbit camera's position and look, as --perspective prints them, draws the very
#   frame --perspective draws; --near is taken with them and refused alone or beyond the camera;
# - a path's first and last frames are the --eye frames of its first and last keys; its video is
#   written; a path whose third frame cannot be written leaves no frame behind;
# - --fill and --style draw in perspective, and a style a model cannot draw is refused.
# usage: cmake -DRENDER=... -DOUT=DIR -DMODEL_FILE=M.oct -DPATH_FILE=walk.json -P this
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

include(${CMAKE_CURRENT_LIST_DIR}/render_checks.cmake)  # render_ok, render_refused, same_files

set(number "-?[0-9.e+-]+")
# --info: the embedded default model and a model file, version 6.
foreach(source "--model;tabletop" "--file;${MODEL_FILE}")
  render_ok(info ${source} --info)
  if(NOT info MATCHES "format version 6" OR
     NOT info MATCHES "\ncube ${number},${number},${number} ${number}\n" OR
     NOT info MATCHES "depth [0-9]+: [0-9]+ leaves, [0-9]+ node bytes, sample reach 1.00 footprints")
    message(FATAL_ERROR "--info ${source} lacks the version, the cube or the depths:\n${info}")
  endif()
endforeach()

# The same file as version 2: the 40-byte placement after the (empty) normal palette cut out, and
# each level table row's sample reach (its byte 1) set to 0, the reserved byte it is there.
file(READ ${MODEL_FILE} normal_count OFFSET 18 LIMIT 2 HEX)
if(NOT normal_count STREQUAL "0000")
  message(FATAL_ERROR "${MODEL_FILE} has normals: the placement is not at byte 788")
endif()
file(READ ${MODEL_FILE} level_count OFFSET 6 LIMIT 1 HEX)
math(EXPR level_count "0x${level_count}")
math(EXPR levels_end "829 + 12 * ${level_count}")
execute_process(COMMAND sh -c "{ head -c 4 \"$0\"; printf '\\002\\000'; \
                                 tail -c +7 \"$0\" | head -c 782; i=0; \
                                 while [ $i -lt $2 ]; do row=$((829 + 12 * i)); \
                                   tail -c +$row \"$0\" | head -c 1; printf '\\000'; \
                                   tail -c +$((row + 2)) \"$0\" | head -c 10; i=$((i + 1)); done; \
                                 tail -c +$3 \"$0\"; } >\"$1\""
                        ${MODEL_FILE} ${OUT}/version2.oct ${level_count} ${levels_end}
                RESULT_VARIABLE status)
# A version 6 file whose first level's sample reach (byte 829: its row's byte 1) is 0: refused
# in one line naming the reach, nothing drawn.
execute_process(COMMAND sh -c "{ head -c 829 \"$0\"; printf '\\000'; tail -c +831 \"$0\"; } >\"$1\""
                        ${MODEL_FILE} ${OUT}/reach0.oct)
render_refused("sample reach outside 16..128.*byte 829" --file ${OUT}/reach0.oct -o ${OUT}/reach0.png)
if(EXISTS ${OUT}/reach0.png)
  message(FATAL_ERROR "a refused model left ${OUT}/reach0.png")
endif()
render_ok(info --file ${OUT}/version2.oct --info)
if(NOT info MATCHES "format version 2" OR NOT info MATCHES "cube placement not recorded")
  message(FATAL_ERROR "--info of a version 2 file:\n${info}")
endif()
render_refused("does not record" --file ${OUT}/version2.oct --eye 0,0,0 -o ${OUT}/v2.png)
if(EXISTS ${OUT}/v2.png)
  message(FATAL_ERROR "a refused --eye left ${OUT}/v2.png")
endif()

# The orbit camera's eye, printed by --perspective, drawn again by --eye: the same frame.
set(view --size 160x120 --depth 7)
render_ok(orbit ${view} --perspective --yaw 20 --pitch 10 --fov 50 -o ${OUT}/orbit.png)
if(NOT orbit MATCHES "eye (${number},${number},${number}) looking (${number},${number},${number})")
  message(FATAL_ERROR "--perspective did not print its eye: ${orbit}")
endif()
set(eye ${CMAKE_MATCH_1})
set(look ${CMAKE_MATCH_2})
render_ok(placed ${view} --eye ${eye} --look ${look} --fov 50 -o ${OUT}/eye.png)
same_files(${OUT}/orbit.png ${OUT}/eye.png)

# --near: in scan units, with a perspective option only, within the camera's 128 cube edges.
render_ok(near ${view} --eye ${eye} --look ${look} --fov 50 --near 0.01 -o ${OUT}/near.png)
render_refused("--near needs --perspective, --eye or --path" --near 0.01 -o ${OUT}/near_alone.png)
render_refused("--near: 1000 scan units is 1.43e\\+03 cube edges" ${view} --eye ${eye} --near 1000
               -o ${OUT}/near_far.png)
if(EXISTS ${OUT}/near_alone.png OR EXISTS ${OUT}/near_far.png)
  message(FATAL_ERROR "a refused --near left a file")
endif()

# A path: 5 frames, the video, and its ends are its end keys' --eye frames.
render_ok(walk --size 160x120 --path ${PATH_FILE} --frames 5 -o ${OUT}/walk.png)
foreach(frame 0000 0001 0002 0003 0004)
  if(NOT EXISTS ${OUT}/walk_${frame}.png)
    message(FATAL_ERROR "--path wrote no ${OUT}/walk_${frame}.png: ${walk}")
  endif()
endforeach()
if(EXISTS ${OUT}/walk_0005.png OR NOT EXISTS ${OUT}/walk.avi)
  message(FATAL_ERROR "--path --frames 5: a sixth frame, or no video: ${walk}")
endif()
file(SIZE ${OUT}/walk.avi video_bytes)
if(video_bytes LESS 10000)
  message(FATAL_ERROR "${OUT}/walk.avi is only ${video_bytes} bytes")
endif()
render_ok(first --size 160x120 --fov 70 --eye 0.05,0.1,-0.45 --look -5,-20 -o ${OUT}/first.png)
render_ok(last --size 160x120 --fov 70 --eye -0.12,0.06,-0.62 --look 15,-20 -o ${OUT}/last.png)
same_files(${OUT}/walk_0000.png ${OUT}/first.png)
same_files(${OUT}/walk_0004.png ${OUT}/last.png)

# The third frame cannot be written (a directory is in its place): no frame and no video is left.
file(MAKE_DIRECTORY ${OUT}/stuck/w_0002.png)
render_refused("w_0002.png" --size 160x120 --path ${PATH_FILE} --frames 5 -o ${OUT}/stuck/w)
file(GLOB left ${OUT}/stuck/w_000[0134].png ${OUT}/stuck/*.avi)
if(left)
  message(FATAL_ERROR "a path that failed left ${left}")
endif()

# --fill and --style in perspective (docs/perspective.md, "Styles and hole filling"): the fill
# changes the walk's first frame (it closes the specks on the table), a line style draws, and a
# path takes both; a model without normals is refused a style that needs them.
render_ok(filled --size 160x120 --fov 70 --eye 0.05,0.1,-0.45 --look -5,-20 --fill
          -o ${OUT}/first_filled.png)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/first.png ${OUT}/first_filled.png
                RESULT_VARIABLE differ)
if(NOT differ)
  message(FATAL_ERROR "--fill drew the same frame as without it")
endif()
render_ok(lines --size 160x120 --fov 70 --eye 0.05,0.1,-0.45 --look -5,-20 --fill --style lines
          -o ${OUT}/first_lines.png)
render_ok(styled_walk --size 160x120 --path ${PATH_FILE} --frames 2 --fill --style outlined
          -o ${OUT}/styled)
if(NOT EXISTS ${OUT}/styled_0001.png)
  message(FATAL_ERROR "--path with --fill --style outlined wrote no second frame: ${styled_walk}")
endif()
render_refused("the model has no normals" --file ${MODEL_FILE} --eye 0,0,0 --style shaded
               -o ${OUT}/no_normals.png)
if(EXISTS ${OUT}/no_normals.png)
  message(FATAL_ERROR "a refused --style left ${OUT}/no_normals.png")
endif()
