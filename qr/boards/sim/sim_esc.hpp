// The simulator's ESCs when they speak DShot (qrsim --esc dshot): each takes the frame the QR's
// board sent, decodes it as an ESC firmware does (a frame with a bad check is dropped and the
// motor keeps the last good value; a special command leaves the motor as it is) and answers, as a
// bidirectional ESC, with its motor's electrical period from the simulated rotor speed
// (common/drivers/dshot.hpp, erpm.hpp; docs/drivers.md). Of the commands it acts on the spin
// direction, as BLHeli_32, Bluejay and AM32 do: "spin direction 1" or "2" (normal, reversed) and
// "save settings" each take effect at their 6th frame in a row with the motor stopped.
#pragma once

#include <stdint.h>

#include <cmath>

#include <common/drivers/dshot.hpp>
#include <common/drivers/dshot_commands.hpp>
#include <common/drivers/erpm.hpp>

namespace qrsim {

class SimEsc {
 public:
  // One frame from the flight computer; the engine command (0..1000) the motor now runs at.
  uint16_t receive(uint16_t frame) {
    const drivers::DshotDecoded d = drivers::dshot_decode(frame, drivers::DshotLine::bidirectional);
    if (!d.valid) {
      ++rejected_;
      return engine_;
    }
    ++accepted_;
    if (d.value == 0 || d.value >= drivers::kDshotThrottleMin) {
      engine_ = drivers::dshot_engine(d.value);
      in_a_row_ = 0;  // a setting needs its frames in a row
    } else {
      ++commands_;
      if (engine_ != 0) {
        ++commands_while_turning_;  // an ESC ignores them; the flight must not send them
      } else {
        take_command(static_cast<uint8_t>(d.value));
      }
    }
    return engine_;
  }

  // The motor turns the other way than its wiring makes it turn (spin direction 2 set).
  bool reversed() const { return reversed_; }
  // The direction kept in the ESC's memory by its last "save settings" (2: reversed).
  bool saved_reversed() const { return saved_reversed_; }

  // The answer to the frame: the electrical period of a motor turning at `rotor_rad_s` with
  // `pole_pairs`, as 21 line bits.
  static uint32_t answer(double rotor_rad_s, uint8_t pole_pairs) {
    const double erpm = std::abs(rotor_rad_s) * 60.0 / (2.0 * M_PI) * pole_pairs;
    const uint32_t period_us = erpm < 1.0 ? 0 : static_cast<uint32_t>(std::lround(60e6 / erpm));
    return drivers::encode_erpm_answer(drivers::erpm_period_code(period_us));
  }

  uint16_t engine() const { return engine_; }
  uint64_t rejected() const { return rejected_; }
  uint64_t accepted() const { return accepted_; }
  // Special command frames received (values 1..47), and those that came while the motor ran.
  uint64_t commands() const { return commands_; }
  uint64_t commands_while_turning() const { return commands_while_turning_; }

 private:
  void take_command(uint8_t command) {
    in_a_row_ = command == last_command_ ? static_cast<uint8_t>(in_a_row_ + 1) : uint8_t{1};
    last_command_ = command;
    if (in_a_row_ != drivers::dshot_repeats(command)) return;  // once, at the frame that completes it
    using drivers::DshotCommand;
    if (command == static_cast<uint8_t>(DshotCommand::spin_direction_1)) reversed_ = false;
    if (command == static_cast<uint8_t>(DshotCommand::spin_direction_2)) reversed_ = true;
    if (command == static_cast<uint8_t>(DshotCommand::save_settings)) saved_reversed_ = reversed_;
  }

  uint16_t engine_ = 0;
  uint8_t last_command_ = 0;
  uint8_t in_a_row_ = 0;
  bool reversed_ = false;
  bool saved_reversed_ = false;
  uint64_t rejected_ = 0;
  uint64_t accepted_ = 0;
  uint64_t commands_ = 0;
  uint64_t commands_while_turning_ = 0;
};

}  // namespace qrsim
