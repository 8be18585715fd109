# device.no_soft_float_helpers: fails when an object of the integer libraries references a libgcc
# soft-float helper, that is, does floating-point arithmetic on a CPU without FPU. Objects whose
# source file name contains `float_` (the float reference variants, renderer/render_float_*.cpp)
# are allowed to. CONTROL is an object that must reference helpers, so a blind check fails too.
# usage: cmake -DNM=<arm nm> -DCONTROL=<object> -DLIBRARIES=<a;b;...> -P check_no_soft_float.cmake

# The libgcc soft-float families, in their ARM EABI and generic names:
#   __aeabi_f* / __aeabi_d*          single/double add, sub, mul, div, compare, to-integer, to-other
#   __aeabi_[u]i2f/d, __aeabi_[u]l2f/d, __aeabi_h2f   integer or half to floating point
#   __addsf3 __subdf3 __mulsf3 __divdf3 __negsf2 ...   arithmetic (sf single, df double, tf/xf long)
#   __extendsfdf2 __truncdfsf2, __fixsfsi __fixunsdfdi, __floatsisf __floatundidf
#   __eqsf2 __ltdf2 __unordsf2 ..., __powisf2, __mulsc3 __divdc3 (complex)
# The integer helpers (__aeabi_idiv, __aeabi_uldivmod, __aeabi_lmul, __aeabi_llsl, memcpy, ...)
# do not match.
string(CONCAT helper_pattern
  "^(__aeabi_([fd]|u?[il]2[fd]|h2f)|__(add|sub|mul|div|neg|abs)[sdtxh]f[23]"
  "|__(extend|trunc)[sdtxh]f[sdtxh]f2|__fix(uns)?[sdtxh]f[sdt]i|__float(un)?[sdt]i[sdtxh]f"
  "|__(eq|ne|gt|ge|lt|le|cmp|unord)[sdtxh]f2|__powi[sdtxh]f2|__(mul|div)[sdtxh]c3)")

foreach(required NM CONTROL LIBRARIES)
  if(NOT ${required})
    message(FATAL_ERROR "check_no_soft_float: ${required} is not set")
  endif()
endforeach()

# Sets `${out_members}` to the object files in `file` and `${out_hits}` to "member: helper" for
# every helper referenced.
function(findHelpers file out_members out_hits)
  execute_process(COMMAND ${NM} -A ${file} OUTPUT_VARIABLE listing ERROR_VARIABLE error
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "check_no_soft_float: ${NM} failed on ${file}: ${error}")
  endif()
  string(REPLACE "\n" ";" lines "${listing}")
  set(members "")
  set(hits "")
  foreach(line IN LISTS lines)
    # "lib.a:member.o:00000000 T symbol" or "lib.a:member.o:         U symbol"
    if(NOT line MATCHES "^(.*):[0-9a-fA-F ]+ ([A-Za-z]) ([^ ]+)$")
      continue()
    endif()
    set(location "${CMAKE_MATCH_1}")
    set(type "${CMAKE_MATCH_2}")
    set(symbol "${CMAKE_MATCH_3}")
    string(REGEX REPLACE "^.*[:/]" "" member "${location}")
    list(APPEND members "${member}")
    if(type STREQUAL "U" AND symbol MATCHES "${helper_pattern}")
      list(APPEND hits "${member}: ${symbol}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES members)
  set(${out_members} "${members}" PARENT_SCOPE)
  set(${out_hits} "${hits}" PARENT_SCOPE)
endfunction()

findHelpers("${CONTROL}" control_members control_hits)
if(NOT control_hits)
  message(FATAL_ERROR "check_no_soft_float: the control object ${CONTROL} references no soft-float "
                      "helper, so this check cannot see any: wrong nm, pattern or float ABI")
endif()
message(STATUS "control object: ${control_hits}")

set(violations "")
foreach(library IN LISTS LIBRARIES)
  findHelpers("${library}" members hits)
  if(NOT members)
    message(FATAL_ERROR "check_no_soft_float: no object files in ${library}")
  endif()
  list(LENGTH members member_count)
  set(allowed "")
  foreach(hit IN LISTS hits)
    if(hit MATCHES "^[^:]*float_[^:]*:")
      list(APPEND allowed "${hit}")
    else()
      list(APPEND violations "${hit}")
    endif()
  endforeach()
  list(LENGTH allowed allowed_count)
  message(STATUS "${library}: ${member_count} objects, ${allowed_count} helper references in "
                 "float_* reference objects")
endforeach()

if(violations)
  string(REPLACE ";" "\n  " listed "${violations}")
  message(FATAL_ERROR
          "soft-float helpers referenced by integer code (object: helper):\n  ${listed}")
endif()
message(STATUS "no soft-float helper outside the float reference variants")
