# octopoint-view (issue 5; included from app/CMakeLists.txt): the interactive window, OpenCV highgui.
find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs highgui)
add_executable(octopoint-view view_main.cpp model_source.cpp)
target_link_libraries(octopoint-view PRIVATE octopoint_cli octopoint_interactive octopoint_models opencv_core
                      opencv_imgproc opencv_imgcodecs opencv_highgui octopoint_warnings)
