// Proves the devboard runner end to end: UART output arrives, the counter counts, and the exit
// status set here is the one scripts/devboard returns.
#include <qr/boards/rv32virt/devboard.hpp>

#ifndef RUNNER_EXIT_CODE
#define RUNNER_EXIT_CODE 0
#endif

int main() {
  const uint32_t before = rv32virt::instret();
  volatile uint32_t sink = 0;
  for (uint32_t i = 0; i < 100; ++i) sink = sink + i;
  const uint32_t spent = rv32virt::instret() - before;
  rv32virt::puts("devboard ok: loop of 100 took ");
  rv32virt::put_u32(spent);
  rv32virt::puts(" instructions, ratio 7/3=");
  rv32virt::put_ratio(7, 3);
  rv32virt::putc('\n');
  return spent >= 100 ? RUNNER_EXIT_CODE : 99;
}
