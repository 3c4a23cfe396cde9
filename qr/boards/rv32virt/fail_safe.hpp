// The devboard's last line of defence. A fault (an exception, an interrupt nobody expects, a tick
// that never ends, a stack that runs into its guard) first writes zero to every engine through
// the board, then reports what happened, where, and in which task, then halts: QEMU exits with
// the fault's status. A vehicle whose flight computer has failed must not keep its last engine
// values; docs/safety.md rule 16, docs/devboard.md "Faults".
#pragma once

#include <stdint.h>

namespace rv32virt {

enum class Fault : uint8_t {
  exception,             // the CPU trapped on an instruction (mcause < 2^31)
  unexpected_interrupt,  // an interrupt no handler was installed for
  stalled,               // the watchdog: no tick completed for kStallPeriods periods
  stack_overflow,        // a load or store into the guard below the stack (PMP)
};

// The exit status of each fault (0 is success, 1 a failed program, 124/125 the runner's own).
constexpr int exit_status(Fault fault) { return fault == Fault::stalled ? 4 : fault == Fault::stack_overflow ? 3 : 2; }

// Where the scheduler keeps the index of the task running now (qr::kNoTask between tasks) and
// the names of its rows, so a fault report can name the task it stopped.
void watch_running_task(const volatile uint8_t* running, const char* const* names, uint8_t count);

// Cuts, reports, halts. `mcause`, `mepc`, `mtval` as the trap left them (for the watchdog: the
// timer interrupt's, mepc being where the main loop was).
[[noreturn]] void fail_safe(Fault fault, uint32_t mcause, uint32_t mepc, uint32_t mtval);

// The board's part. A program without a board (the runner tests) gets versions that have no
// engines to cut; the flight board (virt_board.cpp) provides the real ones.
void cut_engines();                  // zero to every engine now, and on the sensor link to the plant
void read_engines(uint16_t out[4]);  // the engine outputs as the board holds them

}  // namespace rv32virt
