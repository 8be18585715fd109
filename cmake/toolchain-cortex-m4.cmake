# Cortex-M4 (ARMv7E-M) built with -mfloat-abi=soft: the FPU, if the part has one, is not used, so
# the integer renderer is proven float-free there too. Runs under qemu-system-arm's mps2-an386
# (a Cortex-M4 board). See docs/device.md.
set(octopoint_mcu_cpu_flags "-mcpu=cortex-m4 -mthumb -mfloat-abi=soft")
set(octopoint_mcu_qemu_machine mps2-an386)
set(OCTOPOINT_MCU_TARGET cortex-m4 CACHE STRING "linker script targets/cortex-m/<target>.ld")
include(${CMAKE_CURRENT_LIST_DIR}/toolchain-arm-none-eabi.cmake)
