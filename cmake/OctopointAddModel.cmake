# octopoint_add_model(TARGET app NAME face SCAN scan.pcd SCENE scene.json [EMIT strings|bytes])
#
# Prepares a model from a range scan at build time and compiles it into `app`: runs
# octopoint-prepare SCAN --scene SCENE --single-source into
# ${CMAKE_CURRENT_BINARY_DIR}/octopoint_models/NAME, adds the generated NAME.cpp to the target, puts
# NAME.h on its include path and links the renderer. EMIT picks the spelling of the arrays
# (octopoint-prepare --emit; default: the preparer's, strings). The preparer runs again only when
# the scan, the scene or the preparer itself changes.
# Call it in the directory that defines `app` (CMake attaches a custom command's outputs to the
# targets of its own directory). SCAN and SCENE are relative to the current source directory.
# The app then uses the model as `octopoint::models::NAME` (an EmbeddedModel, see
# octopoint/model.h and ModelView::fromEmbedded).
function(octopoint_add_model)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;NAME;SCAN;SCENE;EMIT" "")
  foreach(required TARGET NAME SCAN SCENE)
    if(NOT arg_${required})
      message(FATAL_ERROR "octopoint_add_model: ${required} is missing")
    endif()
  endforeach()
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "octopoint_add_model: unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET ${arg_TARGET})
    message(FATAL_ERROR "octopoint_add_model: ${arg_TARGET} is not a target")
  endif()
  set(emit)
  if(arg_EMIT)
    set(emit --emit ${arg_EMIT})
  endif()
  # The installed package's preparer, or the one being built in the octopoint tree itself.
  if(TARGET octopoint::octopoint-prepare)
    set(prepare octopoint::octopoint-prepare)
  elseif(TARGET octopoint-prepare)
    set(prepare octopoint-prepare)
  else()
    message(FATAL_ERROR
            "octopoint_add_model: no octopoint-prepare: call find_package(octopoint) first, "
            "and install an octopoint built with its preparer (OCTOPOINT_BUILD_PREPARER=ON, "
            "needs PCL)")
  endif()
  get_filename_component(scan "${arg_SCAN}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  get_filename_component(scene "${arg_SCENE}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  set(out "${CMAKE_CURRENT_BINARY_DIR}/octopoint_models/${arg_NAME}")
  add_custom_command(
    OUTPUT "${out}/${arg_NAME}.h" "${out}/${arg_NAME}.cpp"
    COMMAND ${prepare} "${scan}" --scene "${scene}" -o "${out}" --name ${arg_NAME}
            --single-source ${emit}
    DEPENDS ${prepare} "${scan}" "${scene}"
    COMMENT "octopoint: preparing model ${arg_NAME} from ${arg_SCAN}"
    VERBATIM)
  target_sources(${arg_TARGET} PRIVATE "${out}/${arg_NAME}.cpp" "${out}/${arg_NAME}.h")
  target_include_directories(${arg_TARGET} PRIVATE "${out}")
  target_link_libraries(${arg_TARGET} PRIVATE octopoint::renderer)
endfunction()
