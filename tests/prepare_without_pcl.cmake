# octopoint-prepare links no PCL (codegen/whole_scan.h), so that it starts in milliseconds: its
# dynamic section names no PCL or VTK library, and it streams a LAS file alone. A scan it does not
# stream (a binary_compressed PCD) it hands to octopoint-prepare-pcl from its own directory; a copy
# of octopoint-prepare without that program beside it says so in one line, exit 1, no output.
# cmake -DPREPARE=octopoint-prepare -DLAS=FILE.las -DPCD=FILE.pcd -DOUT=DIR -P
# prepare_without_pcl.cmake
execute_process(COMMAND readelf -d ${PREPARE} OUTPUT_VARIABLE dynamic RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "readelf -d ${PREPARE} failed (${status})")
endif()
if(dynamic MATCHES "lib(pcl|vtk|boost)[^] \n]*")
  message(FATAL_ERROR "octopoint-prepare loads ${CMAKE_MATCH_0} at every start:\n${dynamic}")
endif()

file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/alone)
file(COPY ${PREPARE} DESTINATION ${OUT}/alone)
get_filename_component(program ${PREPARE} NAME)
set(alone ${OUT}/alone/${program})
function(prepare expected_status scan output)
  execute_process(COMMAND ${ARGN} ${scan} -o ${output} --name m --depths 6
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL expected_status)
    message(FATAL_ERROR
            "${ARGN} ${scan}: exit ${status}, expected ${expected_status}\n${out}${err}")
  endif()
  set(err "${err}" PARENT_SCOPE)
endfunction()

prepare(0 ${LAS} ${OUT}/las ${alone})  # streamed: no helper needed
if(NOT EXISTS ${OUT}/las/m.oct)
  message(FATAL_ERROR "no model from ${LAS}")
endif()
prepare(1 ${PCD} ${OUT}/pcd_alone ${alone})
string(CONCAT expected_err "^[^\n]*: this scan is read whole through PCL, by [^\n]*"
       "octopoint-prepare-pcl, which cannot be run \\(No such file or directory\\)\n$")
if(NOT err MATCHES "${expected_err}")
  message(FATAL_ERROR "unexpected message without octopoint-prepare-pcl:\n${err}")
endif()
if(EXISTS ${OUT}/pcd_alone)
  message(FATAL_ERROR "output written without octopoint-prepare-pcl")
endif()
prepare(0 ${PCD} ${OUT}/pcd ${PREPARE})  # beside its helper
if(NOT EXISTS ${OUT}/pcd/m.oct)
  message(FATAL_ERROR "no model from ${PCD} through octopoint-prepare-pcl")
endif()
message(STATUS
        "octopoint-prepare links no PCL; streams LAS alone; hands PCD to octopoint-prepare-pcl")
