# Cortex-M0+ (ARMv6-M, Thumb only, no FPU, no divide instruction): an RP2040 or STM32F0 class MCU.
# Run under qemu-system-arm's mps2-an385, a Cortex-M3 board: qemu has no M0+ machine, and ARMv6-M
# is a subset of ARMv7-M, so the M3 executes the M0+ binary unchanged (the instruction count is
# the M0+ code's; the cycles per instruction are not modelled). See docs/device.md.
set(octopoint_mcu_cpu_flags "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(octopoint_mcu_qemu_machine mps2-an385)
set(OCTOPOINT_MCU_TARGET cortex-m0plus CACHE STRING "linker script targets/cortex-m/<target>.ld")
include(${CMAKE_CURRENT_LIST_DIR}/toolchain-arm-none-eabi.cmake)
