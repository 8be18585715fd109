# octopoint-view (included from tools/CMakeLists.txt): the interactive window. SDL2 for the window
# and its events (key presses and releases, wheel, resizes), OpenCV for the overlay text and PNGs.
find_package(SDL2 REQUIRED)
add_executable(octopoint-view view_main.cpp viewer.cpp viewer_walk.cpp view_keys.cpp view_stream.cpp
                              view_overlay.cpp view_window.cpp)
target_link_libraries(octopoint-view PRIVATE octopoint_tool_scenes octopoint_tool_models
                      octopoint_interactive opencv_core
                      opencv_imgproc opencv_imgcodecs SDL2::SDL2 octopoint_warnings)
