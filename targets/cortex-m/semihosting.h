#pragma once
// The little a bare-metal test program needs from its host (docs/device.md): text out and an exit
// status through Arm semihosting (qemu-system-arm -semihosting-config enable=on), an instruction
// clock, and the stack's high-water mark. No libc stdio: nothing here formats with a division.

#include <cstdint>

namespace octopoint::mcu {

// The program, called by the reset handler (targets/cortex-m/startup.cpp) once RAM is set up; 0 is
// success.
int programMain();

void print(const char* text);
void printUnsigned(std::uint64_t value);  // decimal, by subtracting powers of ten
void printHex(std::uint32_t value);       // 8 digits
[[noreturn]] void exitProgram(bool success);

// Instructions executed since startInstructionClock, to within 40. qemu runs with -icount shift=0,
// so one instruction is one nanosecond of virtual time; the mps2 boards' timer 0 counts their 25
// MHz clock in that virtual time, so one tick is 40 instructions (wrapping after 171 s, 1.7 * 10^11
// instructions). calibrateInstructionClock checks that relation on a loop of known length.
void startInstructionClock();
std::uint64_t instructionsNow();
bool calibrateInstructionClock();

// Stack painting: paintStack fills the unused stack (from the stack's bottom to just below the
// caller's frame) with a pattern; stackHighWater returns how many bytes of the stack region have
// ever been written since, counted from its top. stackBytes is the region's size.
void paintStack();
std::uint32_t stackHighWater();
std::uint32_t stackBytes();

}  // namespace octopoint::mcu
