# The constrained device (docs/design.md section 8): an ARMv5TE CPU without FPU, like the paper's
# phones. Debian's arm-linux-gnueabi cross compiler (package g++-arm-linux-gnueabi) with soft-float
# code, so every floating-point operation becomes a libgcc helper call (__aeabi_fadd, __aeabi_d2iz,
# ...), which targets/armel/check_no_soft_float.cmake can see with nm. Programs are linked
# statically and run under qemu-arm (package qemu-user) without a target sysroot; ctest does that
# through CMAKE_CROSSCOMPILING_EMULATOR. Used by the `armel` preset (docs/device.md).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR armv5te)

set(octopoint_device_triple arm-linux-gnueabi)
set(CMAKE_C_COMPILER ${octopoint_device_triple}-gcc)
set(CMAKE_CXX_COMPILER ${octopoint_device_triple}-g++)

# -Wno-psabi: GCC notes on every std::sort of 64-bit values that their parameter passing "changed
# in GCC 7.1". Everything in these static programs is built by this one compiler, so the note
# can never matter here; it only buried real warnings in the build log.
set(octopoint_device_flags "-march=armv5te -mfloat-abi=soft -Wno-psabi")
set(CMAKE_C_FLAGS_INIT "${octopoint_device_flags}")
set(CMAKE_CXX_FLAGS_INIT "${octopoint_device_flags}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")

set(CMAKE_CROSSCOMPILING_EMULATOR qemu-arm)

# Libraries and headers come from the cross sysroot only; build tools from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${octopoint_device_triple})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
