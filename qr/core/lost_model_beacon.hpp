// The lost-model beacon: a QR whose pilot's link has gone silent sits where the link-loss panic
// set it down, in safe. DShot ESCs can beep (special command 1, "beacon 1"), so the QR has them
// beep every 2 s until its pilot's link is back, for the pilot to find it (as flight firmwares do
// with a lost receiver while disarmed). An ESC acts on a command only while its motor is stopped
// (common/drivers/dshot_commands.hpp), and the flight asks for one only in safe with every engine
// at zero and only once a pilot has been heard: docs/safety.md rule 18.
#pragma once

#include <stdint.h>

#include <common/drivers/dshot_commands.hpp>
#include <qr/core/board.hpp>
#include <qr/core/flight_types.hpp>

namespace qr {

inline constexpr uint32_t kBeaconPeriodUs = 2000000;
inline constexpr uint8_t kBeaconCommand = static_cast<uint8_t>(drivers::DshotCommand::beep1);

// The DShot command for the ESCs this tick (0: none). `last_frame_us`: the pilot's link's last
// good frame, 0 if none ever came; one tick in each kBeaconPeriodUs beeps (`period_us`: a tick's).
constexpr uint8_t lost_model_beacon(Mode mode, const EngineCommand& engines, uint32_t now_us, uint32_t last_frame_us,
                                    uint32_t link_timeout_us, uint32_t period_us) {
  if (mode != Mode::safe) return 0;
  for (const uint16_t engine : engines.value) {
    if (engine != 0) return 0;
  }
  if (last_frame_us == 0 || now_us - last_frame_us <= link_timeout_us) return 0;
  return now_us % kBeaconPeriodUs < period_us ? kBeaconCommand : 0;
}

}  // namespace qr
