# ctest city.walk_collision (docs/city.md, "Collision"): a small generated city (2 x 2 blocks,
# make_city and octopoint-prepare as scripts/make-city runs them, depths 5..8), then 10,000
# seeded random walk steps through it flying and 10,000 with gravity (tests/support/city_walk):
# the eye never inside a building nor under the ground, and sliding along walls. Then
# octopoint-render --city --path --collide: a path from a street into a slab stops at its wall
# (frames stopped, the last frame not the one drawn without --collide).
# usage: cmake -DMAKE_CITY=... -DPREPARE=... -DCITY_WALK=... -DRENDER=... -DOUT=DIR -P this
include(${CMAKE_CURRENT_LIST_DIR}/small_city.cmake)
execute_process(COMMAND ${CITY_WALK} ${OUT}/city.json --steps 10000 --seed 33
                        --solid tower.oct,slab.oct,hall.oct,house.oct
                        --ground street.oct,pavement.oct
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "city_walk failed")
endif()

# From the street at x = 0 west into the lot at x = -2, z = -2 (a slab in seed 4's city).
file(WRITE ${OUT}/into.json [=[
{"fov": 70, "keys": [{"time": 0, "eye": [0, -0.053, -2], "look": [-90, 0]},
                     {"time": 4, "eye": [-2, -0.053, -2.3], "look": [-90, 0]}]}
]=])
foreach(walk collide free)
  set(extra)
  if(walk STREQUAL "collide")
    set(extra --collide --eye-height 0.053)
  endif()
  execute_process(COMMAND ${RENDER} --city ${OUT}/city.json --path ${OUT}/into.json --frames 4
                          --size 160x120 ${extra} -o ${OUT}/${walk}.png
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "octopoint-render --city --path ${extra} failed:\n${output}")
  endif()
  if(walk STREQUAL "collide")
    if(NOT output MATCHES "stopped or turned in [1-4] of 4 frames")
      message(FATAL_ERROR "--collide did not stop the eye at the slab:\n${output}")
    endif()
  endif()
endforeach()
file(SHA256 ${OUT}/collide_0003.png collided)
file(SHA256 ${OUT}/free_0003.png free)
if(collided STREQUAL free)
  message(FATAL_ERROR "the last frame with --collide is the one drawn without it")
endif()
