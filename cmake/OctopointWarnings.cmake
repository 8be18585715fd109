# Warnings as an interface target, so every octopoint target opts in with one link and
# third-party headers (PCL, OpenCV: imported, hence SYSTEM) stay quiet.
add_library(octopoint_warnings INTERFACE)
target_compile_options(octopoint_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                 -Wcast-align -Wunused -Woverloaded-virtual -Wnull-dereference>)
