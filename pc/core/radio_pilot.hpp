// The radio as the pilot (docs/safety.md rule 17), as the console sees it: whether the QR says
// its radio flies, which modes the radio's arm switch arms, and what a flight-mode key does then.
// Every part of the console that handles the radio asks here: the mode keys (through the
// simulator's radio), the descent warning's advice, the cockpit's "RADIO FLIES".
#pragma once

#include <stdint.h>

#include <common/mode.hpp>
#include <pc/core/telemetry_model.hpp>

namespace qrterm {

// Which modes the radio's arm switch arms, at which position of its mode switch, is a column of
// the mode table (wire::armed_by_the_radio, wire::mode_at_switch: common/mode.hpp), read by the QR
// and the simulator's radio alike.

// The QR's last telemetry_radio says the radio is the pilot (its parameter `pilot`).
inline bool radio_flies(const TelemetryModel& telemetry) {
  return telemetry.radio && (telemetry.radio->flags & wire::kRadioPilot) != 0;
}

// What a mode key does while the radio flies: the QR takes flight modes from the radio's
// switches then, not from the console's requests.
enum class RadioArming : uint8_t {
  console,  // not the radio's business: the console asks the QR as usual
  arm,      // from safe: the mode switch to the mode, the arm switch off and on
  refused,  // in flight: the arm switch's off-and-on would be rule 17's emergency stop
};

// Only the simulator's radio has switches the console can move; a real radio's are on the
// pilot's transmitter, so on a real QR every request goes out as usual (and the QR refuses it).
RadioArming radio_arming(wire::Mode mode, bool in_safe, bool simulator, const TelemetryModel& telemetry);

}  // namespace qrterm
