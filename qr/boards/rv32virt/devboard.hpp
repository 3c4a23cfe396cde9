// The QEMU `virt` devboard as seen by our bare-metal programs: console output on the 16550
// UART, an exit status through the SiFive test device, and the retired-instruction counter.
#pragma once

#include <stdint.h>

namespace rv32virt {

void putc(char c);
void puts(const char* s);
void put_u32(uint32_t v);
void put_i32(int32_t v);
// Prints num/den with two decimals, rounded, without floating point (den > 0).
void put_ratio(uint32_t num, uint32_t den);

// Instructions retired since reset (`minstret`); under QEMU `-icount` this is exact. Inline: the
// scheduler reads it twice around every task, so a call would be part of what it measures.
inline uint32_t instret() {
  uint32_t v;
  asm volatile("csrr %0, minstret" : "=r"(v));
  return v;
}

// Ends the run; QEMU exits with `code` (0 = success).
[[noreturn]] void exit(int code);

}  // namespace rv32virt

// Each devboard program provides this; its return value is the exit status.
int main();
