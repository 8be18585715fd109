#include "targets/cortex-m/semihosting.h"

namespace octopoint::mcu {
namespace {

// Semihosting: operation in r0, argument in r1, BKPT 0xAB on M-profile; the result comes in r0.
std::uint32_t semihost(std::uint32_t operation, const void* argument) {
  register std::uint32_t r0 asm("r0") = operation;
  register const void* r1 asm("r1") = argument;
  asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

constexpr std::uint32_t kSysWrite0 = 0x04;
constexpr std::uint32_t kSysExit = 0x18;
constexpr std::uint32_t kApplicationExit = 0x20026;  // ADP_Stopped_ApplicationExit: status 0
constexpr std::uint32_t kRunTimeError = 0x20023;     // ADP_Stopped_RunTimeErrorUnknown: status 1

// Timer 0 of the mps2 boards (an ARM CMSDK APB timer at 0x40000000): a 32-bit down counter at
// the 25 MHz peripheral clock. Free running from 0xFFFFFFFF, it wraps after 2^32 ticks, 172 s of
// virtual time, so a difference of two readings is exact for anything shorter.
volatile std::uint32_t& timerControl() {
  return *reinterpret_cast<volatile std::uint32_t*>(0x40000000);
}
volatile std::uint32_t& timerValue() {
  return *reinterpret_cast<volatile std::uint32_t*>(0x40000004);
}
volatile std::uint32_t& timerReload() {
  return *reinterpret_cast<volatile std::uint32_t*>(0x40000008);
}
constexpr std::uint32_t kInstructionsPerTick = 40;  // 1 ns per instruction, 25 MHz ticks

constexpr std::uint32_t kPaint = 0xC0FFEE5Au;

}  // namespace

}  // namespace octopoint::mcu

// From the linker script (targets/cortex-m/sections.ld).
extern "C" std::uint32_t __stack_bottom[];
extern "C" std::uint32_t __stack_top[];

namespace octopoint::mcu {

void print(const char* text) { semihost(kSysWrite0, text); }

void printUnsigned(std::uint64_t value) {
  // Each digit by repeated subtraction of its power of ten (at most 9 times): no divide.
  constexpr std::uint64_t kPowers[] = {1u,
                                       10u,
                                       100u,
                                       1000u,
                                       10000u,
                                       100000u,
                                       1000000u,
                                       10000000u,
                                       100000000u,
                                       1000000000u,
                                       10000000000u,
                                       100000000000u,
                                       1000000000000u,
                                       10000000000000u,
                                       100000000000000u,
                                       1000000000000000u,
                                       10000000000000000u,
                                       100000000000000000u,
                                       1000000000000000000u,
                                       10000000000000000000u};
  char text[21];
  int n = 0;
  int at = 19;
  while (at > 0 && kPowers[at] > value) --at;
  for (; at >= 0; --at) {
    char digit = '0';
    while (value >= kPowers[at]) {
      value -= kPowers[at];
      ++digit;
    }
    text[n++] = digit;
  }
  text[n] = '\0';
  print(text);
}

void printHex(std::uint32_t value) {
  char text[9];
  for (int i = 0; i < 8; ++i) {
    const std::uint32_t nibble = value >> (28 - 4 * i) & 0xF;
    text[i] = static_cast<char>(nibble < 10 ? '0' + nibble : 'a' + nibble - 10);
  }
  text[8] = '\0';
  print(text);
}

void exitProgram(bool success) {
  semihost(kSysExit, reinterpret_cast<const void*>(success ? kApplicationExit : kRunTimeError));
  for (;;) {
  }
}

void startInstructionClock() {
  timerControl() = 0;
  timerReload() = 0xFFFFFFFFu;
  timerValue() = 0xFFFFFFFFu;
  timerControl() = 1;  // enable, no interrupt
}

std::uint64_t instructionsNow() {
  // Ticks since the start, as long as fewer than 2^32 have passed.
  return std::uint64_t{0xFFFFFFFFu - timerValue()} * kInstructionsPerTick;
}

bool calibrateInstructionClock() {
  // 2 instructions per iteration (subs, bne), 10^7 iterations: 2 * 10^7 instructions.
  constexpr std::uint32_t kIterations = 10'000'000;
  const std::uint64_t start = instructionsNow();
  std::uint32_t count = kIterations;
  asm volatile(".syntax unified\n1: subs %0, %0, #1\n bne 1b" : "+l"(count) : : "cc");
  const std::uint64_t spent = instructionsNow() - start;
  print("instruction clock: a loop of 20000000 instructions measured ");
  printUnsigned(spent);
  print("\n");
  return spent >= 2 * kIterations - 400 && spent <= 2 * kIterations + 400;
}

void paintStack() {
  std::uint32_t marker;  // this frame's own address: paint only below it
  for (std::uint32_t* word = __stack_bottom; word + 16 < &marker; ++word) *word = kPaint;
}

std::uint32_t stackHighWater() {
  const std::uint32_t* word = __stack_bottom;
  while (word < __stack_top && *word == kPaint) ++word;
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(__stack_top) -
                                    reinterpret_cast<std::uintptr_t>(word));
}

std::uint32_t stackBytes() {
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(__stack_top) -
                                    reinterpret_cast<std::uintptr_t>(__stack_bottom));
}

}  // namespace octopoint::mcu
