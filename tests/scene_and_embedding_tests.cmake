# Scene files through the real CLI (included by tests/CMakeLists.txt): each bad scene gets one line
# naming the problem, a non-zero exit and no output; a good one prepares a pruned model.
set(scenes ${CMAKE_CURRENT_SOURCE_DIR}/scenes)
function(scene_error_test name expected scene)
  prepare_error_test(scene_${name} "${expected}" ${bad}/good_small.pcd --scene ${scenes}/${scene}
                     -o ${cli_out}/scene_${name} --name m)
  set_tests_properties(cli.prepare.scene_${name} PROPERTIES FIXTURES_REQUIRED test_scans)
endfunction()
scene_error_test(syntax_error "syntax_error.json: not valid JSON: parse error at line 3"
                 syntax_error.json)
scene_error_test(unknown_key "unknown_key.json: key 'colour': unknown key" unknown_key.json)
scene_error_test(empty_range "empty_range.json: key 'yaw': empty range" empty_range.json)
scene_error_test(zoom_zero "zoom_zero.json: key 'zoom': zoom must be greater than 0" zoom_zero.json)
scene_error_test(depth_zero "depth_zero.json: key 'depths': 0 is outside 1..16" depth_zero.json)
scene_error_test(depth_too_deep "depth_too_deep.json: key 'depths': 17 is outside 1..16"
                 depth_too_deep.json)
scene_error_test(missing_file "missing.json: no such file" missing.json)
# An eye the perspective camera cannot hold, refused once the cube is known (docs/scene.md).
scene_error_test(eye_too_far "good_small.pcd: scene eye 0: the eye is 1e+03 cube edges from the \
model's centre along x; the camera holds at most 128" eye_too_far.json)
prepare_error_test(scene_with_depths "--depths: not allowed with --scene" ${bad}/good_small.pcd
                   --scene ${scenes}/frontal.json --depths 7 -o ${cli_out}/scene_with_depths
                   --name m)

# A good scene on the synthetic sphere: the model is written and the report names the pruning.
add_test(NAME cli.prepare.scene_frontal
         COMMAND octopoint-prepare ${test_scans}/sphere.pcd --scene ${scenes}/frontal.json
                 -o ${cli_out}/scene_frontal --name frontal_sphere)
set_tests_properties(cli.prepare.scene_frontal PROPERTIES FIXTURES_REQUIRED test_scans
  PASS_REGULAR_EXPRESSION
    "depths auto: 6\\.\\.7.*left out depths 7:.*depth  6 pruned from [0-9]+ views")

# Embedding: the example app, built against the installed package, embeds two models cut out of
# the real tabletop scan (the milk carton pruned to a frontal scene, the Clorox bottle all around)
# and draws them.
add_test(NAME embedding.example_app_from_installed_package
         COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR}
                 -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                 -DWORK=${CMAKE_CURRENT_BINARY_DIR}/embedding_example
                 -DSCAN=${PROJECT_SOURCE_DIR}/data/scans/milk_cartoon_all_small_clorox.pcd
                 -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
                 -DBUILD_TYPE=${CMAKE_BUILD_TYPE} "-DCXX_FLAGS=${CMAKE_CXX_FLAGS}"
                 "-DLINKER_FLAGS=${CMAKE_EXE_LINKER_FLAGS}"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/embedding_example.cmake)
set_tests_properties(embedding.example_app_from_installed_package PROPERTIES FIXTURES_REQUIRED
                     test_scans)
prepare_error_test(bad_emit "--emit: 'hex' is not one of strings, bytes" ${bad}/good_small.pcd
                   --emit hex -o ${cli_out}/bad_emit --name m)
