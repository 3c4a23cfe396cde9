// Start-up, console and exit for the QEMU `virt` devboard.
#include <qr/boards/rv32virt/devboard.hpp>

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

}  // namespace

extern "C" {
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_limit[];
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
  for (InitFn* f = __init_array_start; f < __init_array_end; ++f) (*f)();
  rv32virt::exit(main());
}

// Interrupt handlers a program may define; without one, that interrupt is a fault.
extern "C" [[gnu::weak]] void rv32virt_timer_interrupt() {
  rv32virt::puts("\nrv32virt: unexpected timer interrupt\n");
  rv32virt::exit(2);
}
extern "C" [[gnu::weak]] void rv32virt_external_interrupt() {
  rv32virt::puts("\nrv32virt: unexpected external interrupt\n");
  rv32virt::exit(2);
}

// Called from the trap entry. Interrupts return to the interrupted code; exceptions end the run.
extern "C" void rv32virt_trap(uint32_t mcause, uint32_t mepc, uint32_t mtval) {
  constexpr uint32_t kInterrupt = 0x80000000u;
  constexpr uint32_t kMachineTimer = 7;
  constexpr uint32_t kMachineExternal = 11;
  if (mcause == (kInterrupt | kMachineTimer)) {
    rv32virt_timer_interrupt();
    return;
  }
  if (mcause == (kInterrupt | kMachineExternal)) {
    rv32virt_external_interrupt();
    return;
  }
  rv32virt::puts("\nrv32virt: trap mcause=");
  rv32virt::put_u32(mcause);
  rv32virt::puts(" mepc=");
  rv32virt::put_u32(mepc);
  rv32virt::puts(" mtval=");
  rv32virt::put_u32(mtval);
  rv32virt::putc('\n');
  rv32virt::exit(2);
}
