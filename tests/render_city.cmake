# octopoint-render --city end to end (docs/city.md):
# - a scene of one model at the identity transform draws the very PNG that model draws alone from
#   the same eye (the scene's eye in scene edges, the model's in the scan's units through the cube
#   its --info prints), byte for byte;
# - bad scene files are refused with one line naming the file and the field, exit 1, no PNG;
# - options that do not go with --city are refused.
# usage: cmake -DRENDER=... -DOUT=DIR -DMODEL_FILE=M.oct -P this
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

include(${CMAKE_CURRENT_LIST_DIR}/render_checks.cmake)  # render_ok, render_refused

# Refused in one line (render_checks.cmake), and no PNG left.
function(render_refused_without_png expected)
  render_refused("${expected}" ${ARGN})
  if(EXISTS ${OUT}/refused.png)
    message(FATAL_ERROR "octopoint-render ${ARGN} was refused but wrote ${OUT}/refused.png")
  endif()
endfunction()

# The model alone, its eye in the scan's units: the cube's centre plus the scene eye times the
# edge (y and z turned about x for a y-up scan, as tools/scan_eye.h places it).
render_ok(info --file ${MODEL_FILE} --info)
string(REGEX MATCH "\ncube ([-0-9.e+]+),([-0-9.e+]+),([-0-9.e+]+) ([0-9.e+]+)\n" found "${info}")
if(NOT found)
  message(FATAL_ERROR "no cube in --info:\n${info}")
endif()
set(x0 ${CMAKE_MATCH_1})
set(y0 ${CMAKE_MATCH_2})
set(z0 ${CMAKE_MATCH_3})
set(e ${CMAKE_MATCH_4})
set(flip 1)
if(info MATCHES "y-up")
  set(flip -1)
endif()
execute_process(
  COMMAND awk "BEGIN { printf \"%.17g,%.17g,%.17g\", ${x0} + 0.75 * ${e}, \
          ${y0} + (${flip} * -0.125 + 0.5) * ${e}, ${z0} + (${flip} * -1.5 + 0.5) * ${e} }"
  OUTPUT_VARIABLE scan_eye)
file(WRITE ${OUT}/one.json "{\"models\": [\"${MODEL_FILE}\"], \"instances\": [[0, 0, 0, 0, 0, 0]]}")
render_ok(city --city ${OUT}/one.json --eye 0.25,-0.125,-1.5 --look 10,-5 --size 160x120
          -o ${OUT}/city.png)
if(NOT city MATCHES "1 instances drawn")
  message(FATAL_ERROR "--city printed:\n${city}")
endif()
render_ok(alone --file ${MODEL_FILE} --eye ${scan_eye} --look 10,-5 --size 160x120
          -o ${OUT}/alone.png)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/city.png ${OUT}/alone.png
                RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "one instance at the identity is not the model drawn alone (eye ${scan_eye})")
endif()

# Bad scene files: one line naming the file and the field.
function(bad_scene name text expected)
  file(WRITE ${OUT}/${name}.json "${text}")
  render_refused_without_png("${name}.json.*${expected}" --city ${OUT}/${name}.json --eye 0,0,-2
                 -o ${OUT}/refused.png)
endfunction()
set(m "\"models\": [\"${MODEL_FILE}\"]")
bad_scene(scale_too_large "{${m}, \"instances\": [[0, 0, 0, 0, 0, 9]]}"
          "instances\\[0\\]\\.scale.*outside -8..8")
bad_scene(no_such_model "{${m}, \"instances\": [[0, 0, 0, 0, 0, 0], [1, 0, 0, 0, 0, 0]]}"
          "instances\\[1\\]\\.model.*outside 0..0")
bad_scene(coordinate_too_large "{${m}, \"instances\": [[0, 17592186044417, 0, 0, 0, 0]]}"
          "instances\\[0\\]\\.x.*outside")
bad_scene(coordinate_past_int64 "{${m}, \"instances\": [[0, 0, 18446744073709551615, 0, 0, 0]]}"
          "instances\\[0\\]\\.y")
bad_scene(turn_too_large "{${m}, \"instances\": [[0, 0, 0, 0, 65536, 0]]}"
          "instances\\[0\\]\\.turn.*outside 0..65535")
bad_scene(not_an_integer "{${m}, \"instances\": [[0, 0.5, 0, 0, 0, 0]]}"
          "instances\\[0\\]\\.x.*expected an integer")
bad_scene(short_instance "{${m}, \"instances\": [[0, 0, 0, 0, 0]]}"
          "instances\\[0\\].*expected \\[model, x, y, z, turn, scale\\]")
bad_scene(no_instances "{${m}, \"instances\": []}" "instances.*1 to 1048576")
bad_scene(no_models "{\"models\": [], \"instances\": [[0, 0, 0, 0, 0, 0]]}" "models.*1 to 256")
bad_scene(unknown_key "{${m}, \"instances\": [[0, 0, 0, 0, 0, 0]], \"lights\": 1}"
          "lights.*unknown key")
bad_scene(twice "{${m}, ${m}, \"instances\": [[0, 0, 0, 0, 0, 0]]}" "models")
bad_scene(missing_model "{\"models\": [\"nowhere.oct\"], \"instances\": [[0, 0, 0, 0, 0, 0]]}"
          "models\\[0\\].*nowhere.oct")
bad_scene(no_embedded "{\"models\": [\"nosuchmodel\"], \"instances\": [[0, 0, 0, 0, 0, 0]]}"
          "models\\[0\\].*nosuchmodel")
bad_scene(broken "{${m}, \"instances\": [[0, 0, 0, 0, 0, 0]" "")

# Options that do not go with --city, and an eye the camera cannot hold.
render_refused_without_png("--eye X,Y,Z" --city ${OUT}/one.json -o ${OUT}/refused.png)
render_refused_without_png("--depth" --city ${OUT}/one.json --eye 0,0,-2 --depth 6 -o ${OUT}/refused.png)
render_refused_without_png("--model, --file and --url" --city ${OUT}/one.json --file ${MODEL_FILE}
               --eye 0,0,-2 -o ${OUT}/refused.png)
render_refused_without_png("--yaw" --city ${OUT}/one.json --eye 0,0,-2 --yaw 10 -o ${OUT}/refused.png)
render_refused_without_png("more than 128 scene edges" --city ${OUT}/one.json --eye 200,0,0
               -o ${OUT}/refused.png)
