// The DShot special commands (values 1..47) and the rules the ESC firmwares put on them: an ESC
// acts on a command only while its motor is stopped, and the ones that change a setting only when
// they arrive 6 times in a row (BLHeli_32 "Dshotprog spec"; Bluejay and AM32 follow it), each sent
// with the telemetry request bit set. The table says per command; the sequencer keeps the rules.
#pragma once

#include <stdint.h>

#include <common/drivers/dshot.hpp>

namespace drivers {

enum class DshotCommand : uint8_t {
  motor_stop = 0,
  beep1 = 1,
  beep2 = 2,
  beep3 = 3,
  beep4 = 4,
  beep5 = 5,
  esc_info = 6,
  spin_direction_1 = 7,
  spin_direction_2 = 8,
  mode_3d_off = 9,
  mode_3d_on = 10,
  settings_request = 11,
  save_settings = 12,
  extended_telemetry_enable = 13,
  extended_telemetry_disable = 14,
  spin_direction_normal = 20,
  spin_direction_reversed = 21,
  led0_on = 22,
  led1_on = 23,
  led2_on = 24,
  led3_on = 25,
  led0_off = 26,
  led1_off = 27,
  led2_off = 28,
  led3_off = 29,
  audio_stream_mode = 30,
  silent_mode = 31,
  signal_line_telemetry_disable = 32,
  signal_line_telemetry_enable = 33,
  signal_line_continuous_erpm = 34,
  signal_line_continuous_erpm_period = 35,
  signal_line_temperature = 42,
  signal_line_voltage = 43,
  signal_line_current = 44,
  signal_line_consumption = 45,
  signal_line_erpm = 46,
  signal_line_erpm_period = 47,
};

inline constexpr uint8_t kDshotCommandMax = 47;

// How many frames in a row a command needs before an ESC acts on it.
inline constexpr uint8_t kDshotSettingRepeats = 6;

// Commands that change a setting of the ESC: 7-14, 20, 21, 32-35. Sent once they could be a
// glitch; the ESC waits for 6 in a row.
constexpr uint8_t dshot_repeats(uint8_t command) {
  constexpr uint8_t kSettingRanges[][2] = {{7, 14}, {20, 21}, {32, 35}};
  for (const auto& range : kSettingRanges) {
    if (command >= range[0] && command <= range[1]) return kDshotSettingRepeats;
  }
  return 1;
}

// One engine's command queue: a command waits for the motor to be stopped, then goes out its
// repeat count in a row in place of the throttle frames; engines that start turning meanwhile win
// (the command is dropped: an ESC would ignore it under throttle, and a half-sent setting counts
// for nothing).
class DshotCommandSequencer {
 public:
  // False when refused: not a command (0 or above 47), or the engine is turning now.
  bool request(uint8_t command, uint16_t engine_now) {
    if (command == 0 || command > kDshotCommandMax || engine_now != 0) return false;
    command_ = command;
    left_ = dshot_repeats(command);
    return true;
  }
  bool busy() const { return left_ != 0; }

  // The frame for this period: the throttle of `engine` (0..1000), or the next repeat of a pending
  // command while the engine is at 0.
  uint16_t next_frame(uint16_t engine, DshotLine line, bool telemetry_request) {
    if (engine != 0) left_ = 0;
    if (left_ == 0) return dshot_frame(dshot_throttle(engine), telemetry_request, line);
    --left_;
    return dshot_frame(command_, true, line);
  }

 private:
  uint8_t command_ = 0;
  uint8_t left_ = 0;
};

}  // namespace drivers
