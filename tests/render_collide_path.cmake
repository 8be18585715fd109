# octopoint-render --path --collide end to end (docs/perspective.md, "Collision"): a path that
# sinks from above the default model's table to below it draws, without --collide, a last frame
# from under the table; with --collide the eye stops on the table (the run says in how many frames
# something stopped it, and the last frame differs); with --eye-height it stays at eye height
# above the table (stopped in no frame: it never reaches it). Bad collision options are refused
# with one line and leave no file.
# usage: cmake -DRENDER=... -DOUT=DIR -DPATH_FILE=down_through_table.json -P this
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

include(${CMAKE_CURRENT_LIST_DIR}/render_checks.cmake)  # render_ok, render_refused

function(files_differ a b)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${a} ${b} RESULT_VARIABLE differ)
  if(NOT differ)
    message(FATAL_ERROR "${a} and ${b} are the same: the collision changed nothing")
  endif()
endfunction()

render_ok(free --path ${PATH_FILE} --frames 5 -o ${OUT}/free.png)
render_ok(stopped --path ${PATH_FILE} --frames 5 --collide -o ${OUT}/stopped.png)
if(NOT stopped MATCHES "collision: eye radius [0-9.e-]+, stopped or turned in [1-5] of 5 frames")
  message(FATAL_ERROR "--collide did not stop the eye sinking through the table: ${stopped}")
endif()
files_differ(${OUT}/free_0004.png ${OUT}/stopped_0004.png)
render_ok(walking --path ${PATH_FILE} --frames 5 --collide --eye-height 0.08 -o ${OUT}/walking.png)
if(NOT walking MATCHES "eye height 0.08, stopped or turned in 0 of 5 frames")
  message(FATAL_ERROR "--eye-height did not hold the eye above the table: ${walking}")
endif()
files_differ(${OUT}/stopped_0004.png ${OUT}/walking_0004.png)

render_refused("--collide needs --path" --collide -o ${OUT}/bad.png)
render_refused("--eye-radius and --eye-height need --collide"
               --path ${PATH_FILE} --frames 5 --eye-radius 0.01 -o ${OUT}/bad.png)
render_refused("--eye-height: .* must be above the eye's radius"
               --path ${PATH_FILE} --frames 5 --collide --eye-radius 0.01 --eye-height 0.005
               -o ${OUT}/bad.png)
render_refused("--eye-radius: .*the eye's radius is 2\\^-24 to 1 cube edge"
               --path ${PATH_FILE} --frames 5 --collide --eye-radius 5 -o ${OUT}/bad.png)
file(GLOB left ${OUT}/bad*)
if(left)
  message(FATAL_ERROR "a refused run left files: ${left}")
endif()
