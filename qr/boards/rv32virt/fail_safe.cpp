// The fail-safe (fail_safe.hpp): the trap entry (start.S) sends every exception here on a stack
// of its own, the trap dispatcher (runtime.cpp) every interrupt without a handler, the board's
// timer interrupt a stalled tick.
#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/boards/rv32virt/fail_safe.hpp>

extern "C" {
extern uint32_t __stack_guard[], __stack_limit[];
}

namespace rv32virt {
namespace {

const volatile uint8_t* g_running = nullptr;
const char* const* g_task_names = nullptr;
uint8_t g_task_count = 0;
constexpr uint8_t kNoTask = 0xFF;  // qr::kNoTask; the runtime does not include the core

// Exception codes of the RISC-V privileged spec (vol. II, table "machine cause register values
// after trap"), the ones an RV32IM core in machine mode can raise.
constexpr const char* kExceptionNames[] = {
    "instruction address misaligned",
    "instruction access fault",
    "illegal instruction",
    "breakpoint",
    "load address misaligned",
    "load access fault",
    "store address misaligned",
    "store access fault",
    "ecall from U-mode",
    "ecall from S-mode",
    "reserved",
    "ecall from M-mode",
};
constexpr uint32_t kExceptionNameCount = sizeof(kExceptionNames) / sizeof(kExceptionNames[0]);

void put_hex(uint32_t v) {
  puts("0x");
  for (int shift = 28; shift >= 0; shift -= 4) putc("0123456789abcdef"[(v >> shift) & 0xFu]);
}

void put_engines(const uint16_t e[4]) {
  for (int i = 0; i < 4; ++i) {
    if (i != 0) putc(' ');
    put_u32(e[i]);
  }
}

const char* what(Fault fault, uint32_t mcause) {
  switch (fault) {
    case Fault::exception: return mcause < kExceptionNameCount ? kExceptionNames[mcause] : "exception";
    case Fault::unexpected_interrupt: return "unexpected interrupt";
    case Fault::stalled: return "stalled (no tick completed)";
    case Fault::stack_overflow: return "stack overflow";
  }
  return "fault";
}

}  // namespace

void watch_running_task(const volatile uint8_t* running, const char* const* names, uint8_t count) {
  g_running = running;
  g_task_names = names;
  g_task_count = count;
}

[[gnu::weak]] void cut_engines() {}
[[gnu::weak]] void read_engines(uint16_t out[4]) {
  for (int i = 0; i < 4; ++i) out[i] = 0;
}

void fail_safe(Fault fault, uint32_t mcause, uint32_t mepc, uint32_t mtval) {
  asm volatile("csrci mstatus, 8");  // no interrupt from here on: nothing may run the engines again
  uint16_t before[4];
  read_engines(before);
  cut_engines();  // first, before anything that could fail in its turn
  uint16_t after[4];
  read_engines(after);

  // A load or store fault inside the guard is the stack running out, whatever the CPU calls it.
  const uint32_t guard = reinterpret_cast<uint32_t>(__stack_guard);
  const uint32_t limit = reinterpret_cast<uint32_t>(__stack_limit);
  if (fault == Fault::exception && (mcause == 5 || mcause == 7) && mtval >= guard && mtval < limit) {
    fault = Fault::stack_overflow;
  }

  // One line, so a test or a person reading the serial line sees it whole.
  puts("\nrv32virt: fail-safe: ");
  puts(what(fault, mcause));
  puts(" mcause=");
  put_hex(mcause);
  puts(" mepc=");
  put_hex(mepc);
  puts(" mtval=");
  put_hex(mtval);
  puts(" task=");
  const uint8_t task = g_running != nullptr ? *g_running : kNoTask;
  if (task == kNoTask) {
    puts("none");
  } else {
    put_u32(task);
    if (task < g_task_count) {
      putc(' ');
      puts(g_task_names[task]);
    }
  }
  puts(" engines ");
  put_engines(before);
  puts(" -> ");
  put_engines(after);
  putc('\n');
  exit(exit_status(fault));
}

}  // namespace rv32virt

// Every exception, from the trap entry on the fault stack (start.S).
extern "C" [[noreturn]] void rv32virt_exception(uint32_t mcause, uint32_t mepc, uint32_t mtval) {
  rv32virt::fail_safe(rv32virt::Fault::exception, mcause, mepc, mtval);
}
