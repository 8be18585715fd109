# octopoint-render --sheet in perspective (docs/perspective.md, "Contact sheets"): each cell of the
# sheet is the single view octopoint-render draws with the same options, byte for byte: --eye's
# columns turn the look's yaw by a turn / N, --path's are the frames --frames N draws, the rows
# are depth by distance then each stored depth everywhere (--depth N).
# usage: cmake -DRENDER=... -DPNG_CELL=... -DPATH_FILE=... -DOUT=DIR -P this
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(width 80)
set(height 60)
set(label 18)  # pixels of label above each row (tools/contact_sheet.h, kSheetLabelHeight)

function(render name)
  execute_process(COMMAND ${RENDER} --size ${width}x${height} ${ARGN} -o ${OUT}/${name}.png
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${name}: failed (${status}): ${out}${err}")
  endif()
endfunction()

# Cell (row, column) of sheet `sheet` against the whole of PNG `single`.
function(expect_cell sheet row column single)
  math(EXPR x "${column} * ${width}")
  math(EXPR y "${row} * (${height} + ${label}) + ${label}")
  foreach(job "${sheet};${x};${y};${sheet}_${row}_${column}" "${single};0;0;${single}_whole")
    list(GET job 0 in)
    list(GET job 1 cx)
    list(GET job 2 cy)
    list(GET job 3 cell)
    execute_process(COMMAND ${PNG_CELL} ${OUT}/${in}.png ${cx} ${cy} ${width} ${height}
                            ${OUT}/${cell}.cell.png RESULT_VARIABLE status ERROR_VARIABLE err)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "png_cell ${in}: ${err}")
    endif()
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/${sheet}_${row}_${column}.cell.png
                          ${OUT}/${single}_whole.cell.png RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "${sheet}: the cell in row ${row}, column ${column} is not ${single}.png")
  endif()
endfunction()

set(eye --eye 0.05,0.1,-0.45 --fov 70)
render(eye_sheet ${eye} --look -5,-20 --sheet 3 --fill)
render(eye_0 ${eye} --look -5,-20 --fill)
render(eye_1 ${eye} --look 115,-20 --fill)
render(eye_2_depth8 ${eye} --look 235,-20 --fill --depth 8)
render(eye_0_depth6 ${eye} --look -5,-20 --fill --depth 6)
expect_cell(eye_sheet 0 0 eye_0)
expect_cell(eye_sheet 0 1 eye_1)
expect_cell(eye_sheet 3 2 eye_2_depth8)  # rows: by distance, depths 6, 7, 8
expect_cell(eye_sheet 1 0 eye_0_depth6)

render(path_sheet --path ${PATH_FILE} --sheet 3)
render(path --path ${PATH_FILE} --frames 3)
expect_cell(path_sheet 0 2 path_0002)

render(orbit_sheet --perspective --yaw 20 --sheet 2 --style shaded)
render(orbit_1 --perspective --yaw 200 --style shaded)
expect_cell(orbit_sheet 0 1 orbit_1)
message(STATUS "every checked cell is its single view")
