# The interactive renderer (included from renderer/CMakeLists.txt): the dual-resolution
# render threads and their event sources. A library of its own so that the core renderer needs
# no threads; still no OpenCV and no floating point, so it builds for the device too.
find_package(Threads REQUIRED)
add_library(octopoint_interactive STATIC
  dual_resolution_renderer.cpp
  view_events.cpp)
add_library(octopoint::interactive ALIAS octopoint_interactive)
target_link_libraries(octopoint_interactive PUBLIC octopoint_renderer Threads::Threads
                      PRIVATE octopoint_warnings)
