// A firmware that fails: the devboard's scheduler and board fly a task set that puts the engines
// at flight values, then one task commits the fault this build was made with (FAULT, below) on a
// later tick. The board must cut the engines, report the fault, its address and the task, and
// halt with a failure status (fault_fails_safe.py checks what it prints).
//   FAULT_ILLEGAL_INSTRUCTION   an instruction the CPU does not have
//   FAULT_STALLED_TASK          a task that never returns (the watchdog)
//   FAULT_STACK_OVERFLOW        a task that recurses through the stack (the PMP guard)
//   FAULT_UNEXPECTED_INTERRUPT  the machine software interrupt, which nothing handles
#include <qr/boards/rv32virt/fail_safe.hpp>
#include <qr/boards/rv32virt/virt_board.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/scheduler.hpp>

namespace {

constexpr uint32_t kFaultTick = 20;  // flying a while first: the engines have values to lose
constexpr qr::EngineCommand kFlying{{300, 310, 320, 330}};

// Deeper than any stack: each call keeps a frame the compiler cannot drop.
[[gnu::noinline]] uint32_t descend(uint32_t depth) {
  volatile uint32_t frame[16];
  frame[0] = depth;
  if (depth == 0) return frame[0];
  const uint32_t below = descend(depth - 1);
  asm volatile("" ::: "memory");
  return below + frame[0];
}

struct FaultyFlight {
  static constexpr uint8_t kTaskCount = 2;
  static constexpr uint8_t kSetCount = 1;
  static constexpr qr::Task<FaultyFlight> task(uint8_t id);
  static constexpr uint8_t kSet[] = {0, 1};
  static constexpr qr::TaskSet task_set(uint8_t) { return {kSet, 2}; }

  uint32_t ticks = 0;
  qr::EngineCommand out;

  uint8_t current_set() const { return 0; }
  void begin_tick(uint32_t, const qr::SensorSample&) { ++ticks; }
  uint32_t rx_space() const { return 0; }
  void receive(uint8_t) {}
  bool tx_peek(uint8_t&) const { return false; }
  void tx_pop() {}
  qr::EngineCommand engines() const { return out; }
  uint8_t leds() const { return 0; }
  bool running() const { return true; }
  template <class Stats>
  void account(const qr::TickReport&, const Stats&) {}

  void fly() { out = kFlying; }

  // What the board's lock-step answer reads (qrsim --devboard): a flight with nothing to score.
  struct Chain {
    using Numbers = qr::chain::FixedNumbers;
    Numbers::Angle roll() const { return {}; }
    Numbers::Angle pitch() const { return {}; }
    Numbers::Angle roll_setpoint() const { return {}; }
    Numbers::Angle pitch_setpoint() const { return {}; }
    Numbers::Rate yaw_rate_setpoint() const { return {}; }
  };
  using ChainType = Chain;
  uint8_t mode() const { return 2; }  // manual: the engines are the flight's
  uint8_t telemetry_flags() const { return 0; }
  Chain chain() const { return {}; }
  void fail() {
    if (ticks < kFaultTick) return;
#if defined(FAULT_ILLEGAL_INSTRUCTION)
    asm volatile(".word 0");  // all-zero word: always an illegal instruction on RISC-V
#elif defined(FAULT_STALLED_TASK)
    for (;;) asm volatile("");  // a loop the compiler keeps
#elif defined(FAULT_STACK_OVERFLOW)
    const uint32_t deepest = descend(100000);
    asm volatile("" ::"r"(deepest));
#elif defined(FAULT_UNEXPECTED_INTERRUPT)
    constexpr uintptr_t kMsip = 0x02000000u;  // CLINT software interrupt, hart 0 (QEMU virt)
    asm volatile("csrs mie, %0" ::"r"(1u << 3));
    *reinterpret_cast<volatile uint32_t*>(kMsip) = 1;
    for (;;) {
    }
#else
#error \
    "say which fault: FAULT_ILLEGAL_INSTRUCTION, FAULT_STALLED_TASK, FAULT_STACK_OVERFLOW or FAULT_UNEXPECTED_INTERRUPT"
#endif
  }
};

constexpr const char* kNames[] = {"fly", "fault"};
constexpr qr::Task<FaultyFlight> kTasks[FaultyFlight::kTaskCount] = {
    {kNames[0], [](FaultyFlight& f) { f.fly(); }, 1, 0, 1000},
    {kNames[1], [](FaultyFlight& f) { f.fail(); }, 1, 0, 1000},
};
constexpr qr::Task<FaultyFlight> FaultyFlight::task(uint8_t id) { return kTasks[id]; }

}  // namespace

int main() {
  static rv32virt::VirtBoard board(qr::kControlHz);
  static FaultyFlight flight;
  static qr::Scheduler<rv32virt::VirtBoard, FaultyFlight> scheduler(board, flight);
  rv32virt::watch_running_task(scheduler.running_task_cell(), kNames, FaultyFlight::kTaskCount);
  // On the sensor link (qrsim --devboard) every tick is answered, as the flight firmware does.
  while (scheduler.tick()) board.answer(flight, scheduler.stats().deadline_misses, scheduler.sensor_stage());
  return 0;  // never: running() stays true
}
