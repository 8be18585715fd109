# The C interface of the page (web/octopoint_web.h) and what it compiles beside the renderer: for
# the wasm build (web/CMakeLists.txt) and the native benchmark and tests of the same code.
set(octopoint_web_sources
    ${PROJECT_SOURCE_DIR}/web/octopoint_web.cpp
    ${PROJECT_SOURCE_DIR}/web/octopoint_web_stream.cpp
    # Walk mode, in the embedded model or a chunked one streamed (its held parts).
    ${PROJECT_SOURCE_DIR}/web/octopoint_web_walk.cpp
    ${PROJECT_SOURCE_DIR}/web/held_parts_frame.cpp
    ${PROJECT_SOURCE_DIR}/web/web_canvas.cpp
    # The native client's choice of the next byte range (transport-free), so that the page asks
    # for what octopoint-view would.
    ${PROJECT_SOURCE_DIR}/net/fetch_planner.cpp)
# With the default model compiled in (OCTOPOINT_WEB_EMBEDDED_MODEL=1, what the benchmark and the
# tests use); the wasm build also makes the page without it.
set(octopoint_web_definitions OCTOPOINT_WEB_EMBEDDED_MODEL=1)
