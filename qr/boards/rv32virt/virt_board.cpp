#include <qr/boards/rv32virt/virt_board.hpp>

#include <common/byte_ring.hpp>
#include <qr/boards/rv32virt/fail_safe.hpp>
#include <qr/boards/rv32virt/paced_transmitter.hpp>
#include <qr/boards/rv32virt/sensor_link_port.hpp>
#include <qr/boards/rv32virt/virt_map.hpp>

namespace rv32virt {
namespace {

using map::reg;

constexpr uint32_t kUartRbr = 0, kUartThr = 0, kUartIer = 1, kUartFcr = 2, kUartLcr = 3, kUartMcr = 4, kUartLsr = 5;
constexpr uint32_t kUartDll = 0, kUartDlm = 1;  // with LCR's divisor latch bit set
constexpr uint8_t kLsrDataReady = 0x01, kLsrThrEmpty = 0x20;
constexpr uint32_t kMieTimer = 1u << 7, kMieExternal = 1u << 11, kMstatusMie = 1u << 3;

// Shared with the interrupt handlers. The ring is single-producer (the UART interrupt) and
// single-consumer (the main loop); its counters are word-sized, so neither sees a torn update.
wire::ByteRing<256> g_rx;
volatile uint32_t g_rx_overruns = 0;
volatile uint32_t g_rx_bytes = 0;  // every byte the UART received, ring or overrun: the link counts them
volatile uint32_t g_kicks = 0;
volatile uint32_t g_kick_time_us = 0;   // time of the last kick, µs, wraps like now_us
volatile uint32_t g_kick_mtime_lo = 0;  // mtime (low word) of the last kick
uint64_t g_next_kick_mtime = 0;
uint32_t g_period_ticks = 0;
uint32_t g_period_us = 0;

// The watchdog (docs/devboard.md "Faults"): a tick that has not completed this many periods after
// it began is stalled, and the timer interrupt cuts the engines. A tick of the flight firmware
// takes at most about 8000 instructions (half a period on a 16 MHz core), and a late one is a
// deadline miss the scheduler counts and skips; ten periods is none of those. Like Crazyflie's
// rate supervisor it judges the main loop from outside it, so a loop stuck in a task cannot
// silence it.
constexpr uint32_t kStallPeriods = 10;
volatile uint32_t g_alive_kick = 0;  // the kick the main loop last came to wait on
volatile bool g_watching = false;    // from the first wait: start-up may take longer

VirtBoard* g_board = nullptr;  // the one board, for the fail-safe's cut
SensorLinkPort g_link;         // the sensor link, when QEMU has it
PacedTransmitter g_ground_tx;
PacedReceiver g_ground_rx;
bool g_linked = false;  // on the sensor link (VirtBoard::on_sensor_link), for the interrupt
// On its own: the bytes QEMU has handed the UART that the line has not brought yet (a console
// can write to the pty faster than the line runs, and QEMU, held up by the host, hands over the
// backlog at once). 2 KiB: 180 ms of the line.
wire::ByteRing<2048> g_line;

// 256 KiB: 3640 lines in each log, 36 s of flight at the default 100 lines a second.
uint8_t g_log_memory[256 * 1024];

void barrier() { asm volatile("" ::: "memory"); }

uint64_t read_mtime() {
  for (;;) {
    const uint32_t hi = reg<uint32_t>(map::kMtime + 4);
    const uint32_t lo = reg<uint32_t>(map::kMtime);
    if (reg<uint32_t>(map::kMtime + 4) == hi) return (static_cast<uint64_t>(hi) << 32) | lo;
  }
}

// The board's own clock, on its own: mtime at the 10 MHz timebase (the instruction count under
// -icount).
uint64_t board_time_ns() { return read_mtime() * (1000000000u / map::kTimebaseHz); }

void write_mtimecmp(uint64_t t) {
  // High word to all ones first, so no value between the two writes is reached by mtime.
  reg<uint32_t>(map::kMtimecmp + 4) = 0xFFFFFFFFu;
  reg<uint32_t>(map::kMtimecmp) = static_cast<uint32_t>(t);
  reg<uint32_t>(map::kMtimecmp + 4) = static_cast<uint32_t>(t >> 32);
}

uint32_t read_mepc() {
  uint32_t v;
  asm volatile("csrr %0, mepc" : "=r"(v));
  return v;
}

[[noreturn]] void stalled() {
  constexpr uint32_t kMachineTimerInterrupt = 0x80000007u;
  fail_safe(Fault::stalled, kMachineTimerInterrupt, read_mepc(), 0);
}

void set_csr_mie(uint32_t bits) { asm volatile("csrs mie, %0" ::"r"(bits)); }
void enable_interrupts() { asm volatile("csrs mstatus, %0" ::"r"(kMstatusMie)); }
void disable_interrupts() { asm volatile("csrc mstatus, %0" ::"r"(kMstatusMie)); }
}  // namespace
}  // namespace rv32virt

using namespace rv32virt;

// On its own the board's timer is the kick, and the watchdog looks at every one. On the sensor link
// the timer is only the watchdog, armed for each tick: any interrupt is a stall.
extern "C" void rv32virt_timer_interrupt() {
  if (g_board != nullptr && g_board->on_sensor_link()) stalled();
  if (g_watching && g_kicks - g_alive_kick >= kStallPeriods) stalled();
  g_kick_mtime_lo = static_cast<uint32_t>(g_next_kick_mtime);
  g_next_kick_mtime += g_period_ticks;
  write_mtimecmp(g_next_kick_mtime);
  g_kick_time_us = g_kick_time_us + g_period_us;
  g_kicks = g_kicks + 1;
}

namespace rv32virt {
namespace {
// What the UART holds, taken by its interrupt (and by the link's kick wait, interrupts off).
// On the link the bytes go straight to the receive ring: the simulator's line has paced them, and
// every byte a sensors frame counts must be in before that frame's kick. On its own the board
// takes them into the line buffer, which the kick wait passes on to the ring at the line's pace
// (release_line); when the buffer is full the interrupt is turned off and QEMU keeps the rest.
void drain_uart() {
  volatile uint8_t* uart = &reg<uint8_t>(map::kUart);
  while ((uart[kUartLsr] & kLsrDataReady) != 0) {
    if (g_linked) {
      if (!g_rx.push(uart[kUartRbr])) g_rx_overruns = g_rx_overruns + 1;
      g_rx_bytes = g_rx_bytes + 1;
    } else if (g_line.space() == 0) {
      uart[kUartIer] = 0x00;
      return;
    } else {
      g_line.push(uart[kUartRbr]);
    }
  }
}

// On its own, once a kick: the bytes the line has brought by now, from the line buffer into the
// receive ring, where the firmware reads them. A byte the ring has no room for is an overrun.
void release_line() {
  const uint64_t now = board_time_ns();
  uint8_t byte = 0;
  for (;;) {
    barrier();  // the interrupt pushes meanwhile (one producer, one consumer: no lock)
    if (!g_line.peek(byte) || !g_ground_rx.take(now, g_line.size() > PacedReceiver::kFifoBytes)) break;
    g_line.pop(byte);
    barrier();
    if (!g_rx.push(byte)) g_rx_overruns = g_rx_overruns + 1;
    g_rx_bytes = g_rx_bytes + 1;
  }
  reg<uint8_t>(map::kUart + kUartIer) = 0x01;  // room again, if the buffer had filled
}
}  // namespace
}  // namespace rv32virt

extern "C" void rv32virt_external_interrupt() {
  const uint32_t source = reg<uint32_t>(map::kPlicClaim);
  if (source == map::kUartIrq) drain_uart();
  reg<uint32_t>(map::kPlicClaim) = source;  // complete
}

namespace rv32virt {

VirtBoard::VirtBoard(uint32_t control_hz) : recording_(reinterpret_cast<const uint8_t*>(map::kRecording)) {
  g_period_ticks = map::kTimebaseHz / control_hz;
  g_period_us = 1000000u / control_hz;

  volatile uint8_t* uart = &reg<uint8_t>(map::kUart);
  // FIFOs on and cleared, the receive interrupt at 14 bytes. QEMU hands the UART at most as many
  // bytes at a time as the trigger level allows: at 1 byte, one byte per trip through its main
  // loop, which on a loaded host took in only 2,300-7,000 of the line's 11,520 bytes a second.
  // A frame's tail below the trigger comes with the character timeout (the divisor below), and
  // on the link the kick wait drains the FIFO as it spins.
  uart[kUartFcr] = 0xC7;
  uart[kUartMcr] = 0x08;                              // OUT2: the 16550's interrupt line enable
  reg<uint32_t>(map::kPlic + 4 * map::kUartIrq) = 1;  // priority
  reg<uint32_t>(map::kPlicEnable) = 1u << map::kUartIrq;
  reg<uint32_t>(map::kPlicThreshold) = 0;

  // The divisor for 115200 baud on virt's 399 193 Hz baud base (3: 133 kbaud, the nearest),
  // which only sets the receive FIFO's character timeout in QEMU: 4 characters, 0.3 ms, so a
  // frame's tail below the trigger level comes promptly.
  uart[kUartLcr] = 0x80;
  uart[kUartDll] = 3;
  uart[kUartDlm] = 0;
  uart[kUartLcr] = 0x03;  // 8N1
  uart[kUartIer] = 0x01;  // interrupt on received data

  g_board = this;
  linked_ = g_link.start();
  g_linked = linked_;
  if (linked_) {
    if (reg<uint32_t>(map::kCoreSpeed) == map::kCoreSpeedMagic) {
      const uint32_t mhz = reg<uint32_t>(map::kCoreSpeed + 4);
      core_mhz_ = mhz >= 1 && mhz <= 1000 ? mhz : 0;
    }
    // The simulator's frames are the kick: the timer is only the watchdog, armed while a tick
    // runs (no timer deadline for QEMU's -icount to jump to while the board waits).
    write_mtimecmp(0xFFFFFFFFFFFFFFFFull);
    set_csr_mie(kMieTimer | kMieExternal);
    enable_interrupts();
    // Ready: an engines frame for kick 0 tells the simulator that the UART is set up, so the
    // ground bytes it sends from now on are all counted.
    g_link.send_engines(simlink::EngineFrame{});
    return;
  }

  const uint64_t now = read_mtime();
  g_kick_mtime_lo = static_cast<uint32_t>(now);
  g_next_kick_mtime = now + g_period_ticks;
  write_mtimecmp(g_next_kick_mtime);
  set_csr_mie(kMieTimer | kMieExternal);
  enable_interrupts();
  first_kick_ = g_kicks;
}

uint32_t VirtBoard::wait_kick([[maybe_unused]] uint32_t seen) {
  if (linked_) {
    write_mtimecmp(0xFFFFFFFFFFFFFFFFull);  // the watchdog rests while the simulator computes
    // Lock-step: wait for the simulator's next sensors frame and the ground bytes it counts. The
    // link is polled, not interrupt-driven: with its virtio interrupt and wfi, a frame QEMU had
    // delivered now and then left the board asleep (a lost wake-up, about once in a few hundred
    // ticks). Polling costs the host CPU while the board waits, and the firmware nothing: the
    // wait is before the tick's count starts.
    for (;;) {
      disable_interrupts();
      // In lock-step every frame is the next kick, unless a core of a given speed ran a tick past
      // the frame's period (the scheduler has counted it seen, a deadline miss).
      if (const simlink::SensorFrame* frame = g_link.take_kick(g_rx_bytes)) {
        enable_interrupts();
        time_ns_ += static_cast<uint64_t>(frame->time_us - time_us_) * 1000u;
        time_us_ = frame->time_us;
        if (core_mhz_ != 0 && static_cast<int32_t>(frame->kick - seen) <= 0) {
          answer_missed(frame->kick);
          continue;
        }
        kick_ = frame->kick;
        for (int axis = 0; axis < 3; ++axis) {
          sample_.gyro[axis] = frame->gyro[axis];
          sample_.accel[axis] = frame->accel[axis];
        }
        sample_.battery_mv = frame->battery_mv;
        sample_.pressure_pa = frame->pressure_pa;
        sensors_on_i2c_ = frame->sensors_on_i2c != 0;
        // The watchdog for this tick, on the virtual clock (instructions under -icount).
        write_mtimecmp(read_mtime() + static_cast<uint64_t>(kStallPeriods) * g_period_ticks);
        kick_instret_ = instret();
        return kick_;
      }
      g_link.poll();
      drain_uart();
      enable_interrupts();
    }
  }
  // The main loop is here, so the tick before has completed: the watchdog's sign of life.
  g_alive_kick = g_kicks;
  g_watching = true;
  // Spin rather than wfi: under QEMU -icount an idle CPU's time is taken from the host clock, so
  // a host that wakes QEMU late hands the firmware a late kick (the 60 s run saw ~1.5 deadline
  // misses a second that way, with no tick longer than half a period). Spinning keeps the board's
  // time a count of instructions, like a soft-core's cycle counter.
  for (;;) {
    disable_interrupts();
    const uint32_t k = g_kicks;
    enable_interrupts();
    if (k != seen) {
      release_line();
      return k;
    }
  }
}

// On the link, the kick flown now: in lock-step no frame comes while a tick runs, and one that
// came before the scheduler started must not count as seen.
// With a core speed, the kicks that came while the tick ran are the periods its instructions
// took beyond the first.
uint32_t VirtBoard::kicks() const { return linked_ ? kick_ + core_us_since_kick() / g_period_us : g_kicks; }

uint32_t VirtBoard::core_us_since_kick() const {
  return core_mhz_ == 0 ? 0 : (instret() - kick_instret_) / core_mhz_;  // MHz: instructions a µs
}

uint32_t VirtBoard::now_us() const {
  // On the link, the stamp: standing still while a tick runs, as in the host simulator, or run on
  // by the core's instructions.
  if (linked_) return time_us_ + core_us_since_kick();
  disable_interrupts();
  const uint32_t base_us = g_kick_time_us;
  const uint32_t base_mtime = g_kick_mtime_lo;
  const uint32_t mtime_lo = static_cast<uint32_t>(read_mtime());
  enable_interrupts();
  return base_us + (mtime_lo - base_mtime) / (map::kTimebaseHz / 1000000u);
}


qr::SensorSample VirtBoard::read_sensors() const {
  if (linked_) return sample_;
  if (!recording_.valid()) {
    qr::SensorSample level;  // at rest, level: the accelerometer feels 1 g upwards
    level.accel[2] = -8192;
    level.battery_mv = 12000;
    level.pressure_pa = 101325;  // a barometer at ISA sea level
    return level;
  }
  const uint32_t tick = g_kicks - first_kick_;
  return recording_.at(tick % recording_.count()).sample;
}

LinkI2cBus& VirtBoard::i2c() { return g_link.i2c(); }

qr::ControlInput VirtBoard::recorded_sticks() const {
  if (!recording_.valid()) return {};
  return recording_.at((g_kicks - first_kick_) % recording_.count()).sticks;
}

bool VirtBoard::recording_ended() const { return recording_.valid() && g_kicks - first_kick_ >= recording_.count(); }

bool VirtBoard::serial_read(uint8_t& byte) {
  barrier();
  const bool got = g_rx.pop(byte);
  barrier();
  return got;
}

bool VirtBoard::serial_write(uint8_t byte) {
  volatile uint8_t* uart = &reg<uint8_t>(map::kUart);
  if ((uart[kUartLsr] & kLsrThrEmpty) == 0) return false;
  // At the line's pace on the board's clock: the frame's stamp on the link, else mtime (100 ns).
  if (!g_ground_tx.accept(linked_ ? time_ns_ : board_time_ns())) return false;
  ++ground_sent_;
  uart[kUartThr] = byte;
  return true;
}

qr::LogArea VirtBoard::log_area() { return {g_log_memory, sizeof g_log_memory}; }

uint32_t VirtBoard::rx_overruns() const { return g_rx_overruns; }

void VirtBoard::send_engines(simlink::EngineFrame& frame) {
  if (task_stats_ != nullptr) {
    const uint8_t row = static_cast<uint8_t>(kick_ % (task_count_ + 1u));
    const qr::CycleStats& s = row == task_count_ ? *tick_stats_ : task_stats_[row];
    frame.stats_row = row;
    frame.stats[frame.count] = s.count, frame.stats[frame.max] = s.max, frame.stats[frame.overruns] = s.overruns;
    frame.stats[frame.sum_low] = s.sum_low, frame.stats[frame.sum_high] = s.sum_high;
  }
  if (core_mhz_ != 0) {
    // A tick that ended in a later period: in this one the outputs kept their engines; the new
    // ones go out with the period it ended in (answer_missed).
    const uint32_t ended = kicks();
    if (ended != kick_) {
      pending_ = engines_;
      pending_kick_ = ended;
      for (int i = 0; i < 4; ++i) frame.engines[i] = held_.value[i];
    } else {
      held_ = engines_;
    }
    last_answer_ = frame;
  }
  g_link.send_engines(frame);
}

void VirtBoard::answer_missed(uint32_t kick) {
  if (kick == pending_kick_) held_ = pending_;
  simlink::EngineFrame f = last_answer_;
  f.kick = kick;
  for (int i = 0; i < 4; ++i) f.engines[i] = held_.value[i];
  g_link.send_engines(f);
}

void VirtBoard::cut_engines() {
  engines_ = qr::EngineCommand{};
  if (!linked_) return;
  // The plant's engines are the ones in the engines frame: answer the kick flown now with zero.
  simlink::EngineFrame f;
  f.kick = kick_;
  f.ground_bytes = ground_sent_;
  g_link.send_engines(f);
}

void cut_engines() {
  if (g_board != nullptr) g_board->cut_engines();
}

void read_engines(uint16_t out[4]) {
  const qr::EngineCommand e = g_board != nullptr ? g_board->engines() : qr::EngineCommand{};
  for (int i = 0; i < 4; ++i) out[i] = e.value[i];
}

static_assert(qr::Board<VirtBoard>);
static_assert(qr::I2cBoard<VirtBoard>);

}  // namespace rv32virt
