// The flight computer's board on QEMU `virt`: the CLINT timer interrupt is the kick, the UART
// receives by interrupt into a ring and transmits a bounded number of bytes per tick, sensor
// samples come from a recording in memory (or a vehicle resting level when there is none).
#pragma once

#include <stdint.h>

#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/boards/rv32virt/recording.hpp>
#include <qr/core/board.hpp>

namespace rv32virt {

class VirtBoard {
 public:
  // Starts the kick at `control_hz` and the UART receive interrupt.
  explicit VirtBoard(uint32_t control_hz);

  uint32_t wait_kick(uint32_t seen);
  uint32_t kicks() const;
  uint32_t now_us() const;
  uint32_t cycles() const { return instret(); }  // instructions retired: exact and repeatable under -icount
  qr::SensorSample read_sensors() const;
  qr::ControlInput recorded_sticks() const;
  bool recording_ended() const;
  void set_engines(qr::EngineCommand engines) { engines_ = engines; }
  qr::EngineCommand engines() const { return engines_; }
  bool serial_read(uint8_t& byte);
  bool serial_write(uint8_t byte);
  void set_leds(uint8_t leds) { leds_ = leds; }
  qr::LogArea log_area();

  const Recording& recording() const { return recording_; }
  uint32_t rx_overruns() const;

 private:
  Recording recording_;
  uint32_t first_kick_ = 0;
  qr::EngineCommand engines_;
  uint8_t leds_ = 0;
};

}  // namespace rv32virt
