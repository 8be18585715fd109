# The small generated city of the city tests (tests/city_walk.cmake, tests/city_stream_walk.cmake):
# 2 x 2 blocks of seed 4, 6 cm spacing, made by make_city and prepared by octopoint-prepare as
# scripts/make-city does, at depths 5..8, with ${CITY_PREPARE_OPTIONS} (e.g. --chunked), into
# ${OUT} (emptied first).
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${MAKE_CITY} --blocks 2 --spacing 6 --seed 4 -o ${OUT}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "make_city failed:\n${output}")
endif()
file(GLOB plys ${OUT}/*.ply)
foreach(ply ${plys})
  get_filename_component(name ${ply} NAME_WE)
  execute_process(COMMAND ${PREPARE} ${ply} -o ${OUT}/prepared --name ${name} --depths 5..8
                          --colours 24 --single-source ${CITY_PREPARE_OPTIONS}
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "octopoint-prepare ${ply} failed:\n${output}")
  endif()
  file(RENAME ${OUT}/prepared/${name}.oct ${OUT}/${name}.oct)
  file(REMOVE ${ply})
endforeach()
