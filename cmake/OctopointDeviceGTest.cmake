# GoogleTest for the device build. Debian ships no ARM libgtest, but libgtest-dev installs the
# sources in /usr/src/googletest: compile them with the cross toolchain. Its CMakeLists defines the
# same GTest::gtest / GTest::gtest_main targets as find_package(GTest), so tests/ and targets/armel/
# link them either way.
set(octopoint_googletest_source /usr/src/googletest CACHE PATH
    "GoogleTest sources (Debian libgtest-dev)")
if(NOT EXISTS ${octopoint_googletest_source}/CMakeLists.txt)
  message(FATAL_ERROR
          "No GoogleTest sources in ${octopoint_googletest_source}: apt-get install libgtest-dev")
endif()
set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
add_subdirectory(${octopoint_googletest_source} ${CMAKE_BINARY_DIR}/googletest EXCLUDE_FROM_ALL)
# GCC 12's false -Wrestrict in std::string, inlined into gtest.cc: not our code, not our warning.
target_compile_options(gtest PRIVATE -Wno-restrict)
# No name service on the device: GoogleTest's result streaming is the only user of getaddrinfo,
# whose static glibc version makes the linker warn on every test program
# (targets/armel/no_name_service.cpp says why and what happens instead).
target_sources(gtest PRIVATE ${PROJECT_SOURCE_DIR}/targets/armel/no_name_service.cpp)
target_link_options(gtest INTERFACE LINKER:--wrap=getaddrinfo,--wrap=freeaddrinfo)
