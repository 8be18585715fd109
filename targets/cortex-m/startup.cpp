// Reset and fault handling for the bare-metal programs (docs/device.md): copies .data from flash,
// clears .bss, paints the stack, runs main and reports its result through semihosting. The
// vector table holds the initial stack pointer and these handlers; the model, the code and every
// const table stay in flash.
#include <cstdint>

#include "targets/cortex-m/semihosting.h"

extern "C" {
// From the linker script (targets/cortex-m/sections.ld).
extern std::uint32_t __data_load[], __data_start[], __data_end[], __bss_start[], __bss_end[];
extern std::uint32_t __stack_top[];

[[noreturn]] void Reset_Handler() {
  for (std::uint32_t *from = __data_load, *to = __data_start; to < __data_end;) *to++ = *from++;
  for (std::uint32_t* word = __bss_start; word < __bss_end; ++word) *word = 0;
  octopoint::mcu::paintStack();
  octopoint::mcu::exitProgram(octopoint::mcu::programMain() == 0);
}

[[noreturn]] void Fault_Handler() {
  octopoint::mcu::print("fault: the program stopped on a processor exception\n");
  octopoint::mcu::exitProgram(false);
}

using Handler = void (*)();
// ARMv6-M's 16 system exceptions: initial SP, reset, NMI, HardFault, 7 reserved (faults on v7-M),
// SVCall, 2 reserved, PendSV, SysTick.
__attribute__((section(".vectors"), used))
const Handler kVectors[16] = {reinterpret_cast<Handler>(__stack_top),
                              Reset_Handler,
                              Fault_Handler,
                              Fault_Handler,
                              Fault_Handler,
                              Fault_Handler,
                              Fault_Handler,
                              nullptr,
                              nullptr,
                              nullptr,
                              nullptr,
                              Fault_Handler,
                              nullptr,
                              nullptr,
                              Fault_Handler,
                              Fault_Handler};
}
