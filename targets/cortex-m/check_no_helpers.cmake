# mcu.no_hidden_helpers (docs/device.md): fails when a linked bare-metal image contains a libgcc
# soft-float helper or a division helper, that is, when any code in it (the renderer's per-frame
# code, its set-up, the test harness) does floating-point arithmetic or divides on a CPU without
# FPU or divide instruction. Linked with --gc-sections, an image holds only what something in it
# calls, so a helper absent from the image is referenced by nothing. CONTROL is an image that
# divides and multiplies floats on purpose: the check must find helpers there, or it is blind.
# usage: cmake -DNM=<arm-none-eabi-nm> -DCONTROL=<elf> -DIMAGES=<a.elf;b.elf> -P
# check_no_helpers.cmake

# Soft float: __aeabi_f*/d* (arithmetic, compare, conversion), __aeabi_[u]i2f/d, [u]l2f/d, h2f and
# the generic names (__addsf3, __divdf3, __fixsfsi, __floatsisf, __eqdf2, ...), as in
# targets/armel/check_no_soft_float.cmake. Division: __aeabi_idiv(mod), __aeabi_uidiv(mod),
# __aeabi_ldivmod, __aeabi_uldivmod and the generic __divsi3, __udivsi3, __modsi3, __umodsi3,
# __divdi3, __udivdi3, __moddi3, __umoddi3, __udivmoddi4, __divmoddi4.
string(CONCAT float_pattern
  "^(__aeabi_([fd][a-z0-9]+|u?[il]2[fd]|h2f)|__(add|sub|mul|div|neg|abs)[sdtxh]f[23]"
  "|__(extend|trunc)[sdtxh]f[sdtxh]f2|__fix(uns)?[sdtxh]f[sdt]i|__float(un)?[sdt]i[sdtxh]f"
  "|__(eq|ne|gt|ge|lt|le|cmp|unord)[sdtxh]f2|__powi[sdtxh]f2|__(mul|div)[sdtxh]c3)$")
set(division_pattern "^(__aeabi_(u?idiv(mod)?|u?ldivmod)|__(u?div|u?mod)[sd]i3|__u?divmoddi4)$")

foreach(required NM CONTROL IMAGES)
  if(NOT ${required})
    message(FATAL_ERROR "check_no_helpers: ${required} is not set")
  endif()
endforeach()

function(findHelpers image out_hits)
  execute_process(COMMAND ${NM} ${image} OUTPUT_VARIABLE listing ERROR_VARIABLE error
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "check_no_helpers: ${NM} failed on ${image}: ${error}")
  endif()
  string(REPLACE "\n" ";" lines "${listing}")
  set(hits "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^[0-9a-fA-F ]+ [A-Za-z] ([^ ]+)$")
      set(symbol "${CMAKE_MATCH_1}")
      if(symbol MATCHES "${float_pattern}" OR symbol MATCHES "${division_pattern}")
        list(APPEND hits "${symbol}")
      endif()
    endif()
  endforeach()
  set(${out_hits} "${hits}" PARENT_SCOPE)
endfunction()

findHelpers("${CONTROL}" control_hits)
set(saw_float FALSE)
set(saw_division FALSE)
foreach(hit IN LISTS control_hits)
  if(hit MATCHES "${float_pattern}")
    set(saw_float TRUE)
  endif()
  if(hit MATCHES "${division_pattern}")
    set(saw_division TRUE)
  endif()
endforeach()
if(NOT saw_float OR NOT saw_division)
  message(FATAL_ERROR
    "check_no_helpers: the control image ${CONTROL} shows no float or no division "
                      "helper (${control_hits}), so this check cannot see them")
endif()
message(STATUS "control image: ${control_hits}")

set(violations "")
foreach(image IN LISTS IMAGES)
  findHelpers("${image}" hits)
  foreach(hit IN LISTS hits)
    list(APPEND violations "${image}: ${hit}")
  endforeach()
  if(NOT hits)
    message(STATUS "${image}: no soft-float or division helper")
  endif()
endforeach()
if(violations)
  string(REPLACE ";" "\n  " listed "${violations}")
  message(FATAL_ERROR "helpers in bare-metal images:\n  ${listed}")
endif()
