// A board for unit tests: time moves only when the test (or a task it wrote) says so, sensor
// samples and received bytes are scripted, outputs are recorded.
#pragma once

#include <stdint.h>

#include <deque>
#include <vector>

#include <qr/core/board.hpp>
#include <qr/core/control_rate.hpp>

namespace qr::fake {

class FakeBoard {
 public:
  static constexpr uint32_t kCyclesPerUs = 16;  // a 16 MHz-class core

  // Blocks until a new kick: here that means jumping the clock to the next period boundary.
  uint32_t wait_kick(uint32_t seen) {
    if (kicks() == seen) now_us_ = (seen + 1) * kPeriodUs;
    kick_times_us.push_back(now_us_);
    return kicks();
  }
  uint32_t kicks() const { return now_us_ / kPeriodUs; }
  uint32_t now_us() const { return now_us_; }
  uint32_t cycles() const { return now_us_ * kCyclesPerUs; }

  SensorSample read_sensors() const { return sensors; }
  void set_engines(EngineCommand e) { engines = e; }
  bool serial_read(uint8_t& byte) {
    if (rx.empty()) return false;
    byte = rx.front();
    rx.pop_front();
    return true;
  }
  bool serial_write(uint8_t byte) {
    if (tx.size() >= tx_capacity) return false;
    tx.push_back(byte);
    return true;
  }
  void set_leds(uint8_t l) { leds = l; }
  // A radio receiver's line and bidirectional DShot ESCs' answers, scripted like the serial line.
  bool radio_read(uint8_t& byte) {
    if (radio.empty()) return false;
    byte = radio.front();
    radio.pop_front();
    return true;
  }
  bool esc_answers(EscAnswers& out) {
    if (esc.fresh == 0) return false;
    out = esc;
    esc.fresh = 0;
    return true;
  }
  // DShot special commands, recorded with the engines they went to (bit i: engine i) and the
  // engine values the board was last given. `esc_commands_taken` false: ESCs that take none.
  struct EscCommandSent {
    uint8_t command;
    EngineCommand engines;
    uint32_t at_us;
    uint8_t to;
  };
  bool esc_command(uint8_t command, uint8_t to) {
    esc_commands.push_back({command, engines, now_us_, to});
    return esc_commands_taken;
  }
  LogArea log_area() { return {log_memory, sizeof log_memory}; }
  uint32_t rx_overruns() const { return overruns; }  // scripted: bytes the receiver "lost"

  // Simulated work: a task calls this to take time.
  void spend_us(uint32_t us) { now_us_ += us; }

  SensorSample sensors;
  EngineCommand engines;
  uint8_t leds = 0;
  std::deque<uint8_t> rx;
  uint32_t overruns = 0;
  std::deque<uint8_t> radio;
  EscAnswers esc;
  std::vector<EscCommandSent> esc_commands;
  bool esc_commands_taken = true;
  std::vector<uint8_t> tx;
  size_t tx_capacity = 1u << 20;
  std::vector<uint32_t> kick_times_us;  // when each tick's kick was taken
  uint8_t log_memory[16 * 1024] = {};

 private:
  uint32_t now_us_ = 0;
};

static_assert(Board<FakeBoard> && RadioBoard<FakeBoard> && EscAnswerBoard<FakeBoard> && EscCommandBoard<FakeBoard> &&
              OverrunCountingBoard<FakeBoard>);

}  // namespace qr::fake
