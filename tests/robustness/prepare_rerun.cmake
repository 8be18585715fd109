# A rerun of octopoint-prepare into the same directory leaves exactly its own set of the model:
# the level sources of depths it no longer writes (fewer depths, then --single-source) are gone,
# while a file of the user's and another model's files of a similar name stay.
# usage: cmake -DPREPARE=... -DSCAN=... -DOUT=... -P prepare_rerun.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../run_or_fail.cmake)

function(expect_files expected)
  file(GLOB found RELATIVE ${OUT} ${OUT}/* ${OUT}/.*)
  list(SORT found)
  set(want ${expected} ${ARGN})
  list(SORT want)
  if(NOT found STREQUAL want)
    message(FATAL_ERROR "${OUT} holds\n  ${found}\nexpected\n  ${want}")
  endif()
endfunction()

file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
file(WRITE ${OUT}/m_depth9.cpp "// my notes, not generated\n")
# Another model whose name starts like m's level sources (a name ending in _depth and digits is
# refused: cli.prepare.name_like_a_level_source).
run(${PREPARE} ${SCAN} -o ${OUT} --name m_depth --depths 4)
set(other m_depth.h m_depth.cpp m_depth_depth4.cpp m_depth.oct m_depth9.cpp)
run(${PREPARE} ${SCAN} -o ${OUT} --name m --depths 3,5,7)
expect_files(${other} m.h m.cpp m.oct m_depth3.cpp m_depth5.cpp m_depth7.cpp)
run(${PREPARE} ${SCAN} -o ${OUT} --name m --depths 5,7)
expect_files(${other} m.h m.cpp m.oct m_depth5.cpp m_depth7.cpp)
run(${PREPARE} ${SCAN} -o ${OUT} --name m --depths 5)
expect_files(${other} m.h m.cpp m.oct m_depth5.cpp)
run(${PREPARE} ${SCAN} -o ${OUT} --name m --depths 5,6 --single-source)
expect_files(${other} m.h m.cpp m.oct)
file(READ ${OUT}/m_depth9.cpp notes)
file(READ ${OUT}/m_depth.cpp descriptor)
if(NOT notes STREQUAL "// my notes, not generated\n" OR NOT descriptor MATCHES
   "extern const ::octopoint::EmbeddedModel m_depth ")
  message(FATAL_ERROR "a file that is not one of m's level sources was changed")
endif()
