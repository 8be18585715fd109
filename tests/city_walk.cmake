# ctest city.walk_collision (docs/city.md, "Collision"): a small generated city (2 x 2 blocks,
# make_city and octopoint-prepare as scripts/make-city runs them, depths 5..8), then 10,000
# seeded random walk steps through it flying and 10,000 with gravity (tests/support/city_walk):
# the eye never inside a building nor under the ground, and sliding along walls.
# usage: cmake -DMAKE_CITY=... -DPREPARE=... -DCITY_WALK=... -DOUT=DIR -P this
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
                          --colours 24 --single-source
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "octopoint-prepare ${ply} failed:\n${output}")
  endif()
  file(RENAME ${OUT}/prepared/${name}.oct ${OUT}/${name}.oct)
  file(REMOVE ${ply})
endforeach()
execute_process(COMMAND ${CITY_WALK} ${OUT}/city.json --steps 10000 --seed 33
                        --solid tower.oct,slab.oct,hall.oct,house.oct
                        --ground street.oct,pavement.oct
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "city_walk failed")
endif()
