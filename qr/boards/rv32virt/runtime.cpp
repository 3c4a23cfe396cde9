// Start-up, console and exit for the QEMU `virt` devboard.
#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/boards/rv32virt/fail_safe.hpp>

namespace {

// 16550 UART (QEMU virt: 0x1000'0000). Polled: wait for the holding register to be empty.
volatile uint8_t* const kUart = reinterpret_cast<volatile uint8_t*>(0x10000000u);
constexpr uint32_t kUartThr = 0;
constexpr uint32_t kUartLsr = 5;
constexpr uint8_t kLsrThrEmpty = 0x20;

// SiFive test device (QEMU virt: 0x10'0000): 0x5555 = pass, (code << 16) | 0x3333 = fail(code).
volatile uint32_t* const kTestDevice = reinterpret_cast<volatile uint32_t*>(0x100000u);
constexpr uint32_t kFinisherPass = 0x5555;
constexpr uint32_t kFinisherFail = 0x3333;

constexpr uint32_t kStackCanary = 0xC0DEF00Du;

constexpr uint32_t kInterrupt = 0x80000000u;  // mcause bit 31
constexpr uint32_t kMachineTimer = 7;
constexpr uint32_t kMachineExternal = 11;

uint32_t read_mepc() {
  uint32_t v;
  asm volatile("csrr %0, mepc" : "=r"(v));
  return v;
}

// The stack guard (link.ld): PMP entry 0 covers it as one NAPOT region with no access, locked,
// because only a locked entry binds machine mode (RISC-V privileged spec, "Physical Memory
// Protection"). Every other address matches no entry, which machine mode may access. Locked, the
// entry stays until reset: nothing the firmware does later can open the guard.
void guard_the_stack(uint32_t guard, uint32_t size) {
  const uint32_t napot = (guard >> 2) | ((size >> 3) - 1u);  // base | (size/8 - 1): a NAPOT range
  constexpr uint32_t kLocked = 0x80, kNapot = 0x18;          // pmpcfg: L, A = NAPOT, R = W = X = 0
  asm volatile("csrw pmpaddr0, %0" ::"r"(napot));
  asm volatile("csrw pmpcfg0, %0" ::"r"(kLocked | kNapot));
}

}  // namespace

extern "C" {
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_guard[], __stack_limit[];
using InitFn = void (*)();
extern InitFn __init_array_start[], __init_array_end[];
}

namespace rv32virt {

void putc(char c) {
  while ((kUart[kUartLsr] & kLsrThrEmpty) == 0) {
  }
  kUart[kUartThr] = static_cast<uint8_t>(c);
}

void puts(const char* s) {
  while (*s != '\0') putc(*s++);
}

void put_u32(uint32_t v) {
  char digits[10];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v != 0);
  while (n > 0) putc(digits[--n]);
}

void put_i32(int32_t v) {
  if (v < 0) {
    putc('-');
    put_u32(0u - static_cast<uint32_t>(v));
  } else {
    put_u32(static_cast<uint32_t>(v));
  }
}

void put_ratio(uint32_t num, uint32_t den) {
  const uint64_t hundredths = (static_cast<uint64_t>(num) * 100u + den / 2u) / den;
  put_u32(static_cast<uint32_t>(hundredths / 100u));
  putc('.');
  const uint32_t frac = static_cast<uint32_t>(hundredths % 100u);
  putc(static_cast<char>('0' + frac / 10u));
  putc(static_cast<char>('0' + frac % 10u));
}

void exit(int code) {
  if (__stack_limit[0] != kStackCanary) {
    puts("\nrv32virt: stack overflow (canary overwritten)\n");
    code = code != 0 ? code : 3;
  }
  *kTestDevice = code == 0 ? kFinisherPass : (static_cast<uint32_t>(code) << 16) | kFinisherFail;
  for (;;) {
  }
}

}  // namespace rv32virt

extern "C" [[noreturn]] void rv32virt_start() {
  for (uint32_t* p = __bss_start; p < __bss_end; ++p) *p = 0;
  __stack_limit[0] = kStackCanary;
  guard_the_stack(reinterpret_cast<uint32_t>(__stack_guard),
                  reinterpret_cast<uint32_t>(__stack_limit) - reinterpret_cast<uint32_t>(__stack_guard));
  for (InitFn* f = __init_array_start; f < __init_array_end; ++f) (*f)();
  rv32virt::exit(main());
}

// Interrupt handlers a program may define; without one, that interrupt is a fault.
extern "C" [[gnu::weak]] void rv32virt_timer_interrupt() {
  rv32virt::fail_safe(rv32virt::Fault::unexpected_interrupt, kInterrupt | kMachineTimer, read_mepc(), 0);
}
extern "C" [[gnu::weak]] void rv32virt_external_interrupt() {
  rv32virt::fail_safe(rv32virt::Fault::unexpected_interrupt, kInterrupt | kMachineExternal, read_mepc(), 0);
}

// Called from the trap entry for every interrupt (exceptions go to fail_safe.cpp on their own
// stack). The two the board uses return to the interrupted code; any other is a fault.
extern "C" void rv32virt_interrupt(uint32_t mcause) {
  if (mcause == (kInterrupt | kMachineTimer)) {
    rv32virt_timer_interrupt();
    return;
  }
  if (mcause == (kInterrupt | kMachineExternal)) {
    rv32virt_external_interrupt();
    return;
  }
  rv32virt::fail_safe(rv32virt::Fault::unexpected_interrupt, mcause, read_mepc(), 0);
}
