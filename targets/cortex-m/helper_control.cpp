// The control image for targets/cortex-m/check_no_helpers.cmake: it divides and uses float on
// purpose, so the linked image must contain the helpers the check looks for; a check that cannot
// see them fails. The division is 64-bit: a Cortex-M4 divides 32-bit integers in hardware, but no
// Cortex-M divides 64-bit ones, so both targets call __aeabi_ldivmod for it.
#include <cstdint>

volatile std::int64_t numerator = 7, denominator = 3;
volatile float value = 1.5f;

extern "C" void Reset_Handler() {
  numerator = numerator / denominator;
  value = value * static_cast<float>(numerator);
  for (;;) {
  }
}

extern "C" std::uint32_t __stack_top[];
using Handler = void (*)();
__attribute__((section(".vectors"), used))
const Handler kVectors[2] = {reinterpret_cast<Handler>(__stack_top), Reset_Handler};
