# Bare-metal ARM Cortex-M (docs/device.md), shared by toolchain-cortex-m0plus.cmake and
# toolchain-cortex-m4.cmake, which set octopoint_mcu_cpu_flags and octopoint_mcu_qemu_machine first.
# Debian's gcc-arm-none-eabi with newlib (nano) and libstdc++-arm-none-eabi-newlib for the C++
# headers. No operating system, no heap: the startup code and linker scripts are in
# targets/cortex-m/, and nothing provides _sbrk, so a program that would call malloc does not link.
# Soft float (-mfloat-abi=soft) on both: the M0+ has no FPU, and on the M4 a float operation would
# become a visible libgcc helper call instead of an FPU instruction
# (targets/cortex-m/check_no_helpers.cmake). Programs run under qemu-system-arm with semihosting and
# an exact instruction clock (-icount shift=0: one nanosecond of virtual time per instruction),
# through CMAKE_CROSSCOMPILING_EMULATOR.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)  # no executable links without our startup code

# -fno-tree-loop-distribute-patterns: newlib nano's memset and memcpy are byte loops (it prefers
# size), so word loops (a band's clear: 7,680 words for 24 rows) stay word loops instead of
# becoming calls to them.
string(CONCAT octopoint_mcu_flags
  "${octopoint_mcu_cpu_flags} -fno-tree-loop-distribute-patterns -ffunction-sections "
  "-fdata-sections -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-unwind-tables "
  "-fno-asynchronous-unwind-tables")
set(CMAKE_C_FLAGS_INIT "${octopoint_mcu_cpu_flags} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${octopoint_mcu_flags}")
# -O2, not -O3: on Thumb-1, -O3's inlining and unrolling triple the decoders' code and spill the
# cursors a decoder returns through memcpy calls; -O2 runs the default model's frame in fewer
# instructions (docs/device.md).
set(CMAKE_C_FLAGS_RELEASE "-O2 -DNDEBUG" CACHE STRING "Flags of Release builds")
set(CMAKE_CXX_FLAGS_RELEASE "-O2 -DNDEBUG" CACHE STRING "Flags of Release builds")
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "${octopoint_mcu_cpu_flags} --specs=nano.specs -nostartfiles -Wl,--gc-sections")

set(OCTOPOINT_MCU_QEMU_MACHINE ${octopoint_mcu_qemu_machine} CACHE STRING
    "qemu-system-arm machine that runs the images")
set(CMAKE_CROSSCOMPILING_EMULATOR
    qemu-system-arm -M ${octopoint_mcu_qemu_machine} -nographic -monitor none -serial none
    -semihosting-config enable=on,target=native -icount shift=0,sleep=off -kernel)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
