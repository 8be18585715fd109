# Runs a small octopoint-tradeoff --sweep-views and checks its outputs: a CSV row per cell and
# configuration (before, before_fill, after, after_smooth) with every column and no PSNR above its
# palette ceiling, the markdown tables with the targets (box against smooth against the exact voxel
# cover included), the pictures, and nothing on stderr.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${TRADEOFF} ${SCAN} --sweep-views --sizes 64x48,160x120 --zooms 1,4
                        --rounds 1 --pictures -o ${OUT}
                RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "octopoint-tradeoff failed (${status}): ${errors}")
endif()
# stderr is for the one error line: a run that succeeds leaves it empty (no library warnings).
if(NOT errors STREQUAL "")
  message(FATAL_ERROR "octopoint-tradeoff succeeded but wrote to stderr: ${errors}")
endif()
file(STRINGS ${OUT}/sweep.csv lines)
list(LENGTH lines count)
if(NOT count EQUAL 17)
  message(FATAL_ERROR "sweep.csv has ${count} lines, expected a header and 2 x 2 x 4 rows")
endif()
foreach(line IN LISTS lines)
  string(REPLACE "," ";" fields "${line}")
  list(LENGTH fields field_count)
  if(NOT field_count EQUAL 20)
    message(FATAL_ERROR "sweep.csv line '${line}' has ${field_count} fields, expected 20")
  endif()
  # No frame of a model beats its palette ceiling (lab/palette_ceiling.h), real frames included.
  list(GET fields 11 psnr)
  list(GET fields 13 ceiling)
  if(NOT psnr STREQUAL "psnr_db" AND psnr GREATER ceiling)
    message(FATAL_ERROR
            "sweep.csv line '${line}': PSNR ${psnr} above its palette ceiling ${ceiling}")
  endif()
endforeach()
file(READ ${OUT}/sweep.md page)
foreach(expected "| 160x120 | 4 |" "Targets, from the numbers" "Empty share of the silhouette"
        "Palette ceiling" "Box and smooth splats" "Smooth at zoom 2 and beyond")
  string(FIND "${page}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "sweep.md lacks '${expected}'")
  endif()
endforeach()
foreach(picture 64x48_zoom1.png 160x120_zoom4.png 160x120_zoom4_centre.png 160x120_zoom4_empty.png
        160x120_zoom4_splats.png 160x120_zoom4_splats_centre.png)
  if(NOT EXISTS ${OUT}/pictures/${picture})
    message(FATAL_ERROR "no picture ${picture}")
  endif()
endforeach()
