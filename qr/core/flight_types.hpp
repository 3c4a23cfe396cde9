// Data that crosses between the link, the signal chain and the safety machine: the pilot's
// sticks and the modes. Shared here so the chain needs nothing of the safety machine.
#pragma once

#include <stdint.h>

#include <common/mode.hpp>
#include <common/nack_reason.hpp>

namespace qr {

// Pilot's set-points as they come off the link: lift 0..1000, roll/pitch/yaw -1000..1000,
// centred at 0.
struct ControlInput {
  uint16_t lift = 0;
  int16_t roll = 0;
  int16_t pitch = 0;
  int16_t yaw = 0;

  bool neutral() const { return lift == 0 && roll == 0 && pitch == 0 && yaw == 0; }
};

// Who flies (parameter pilot): the PC link's control frames or the radio receiver's channels.
// The PC link always keeps telemetry, logs, parameters and the abort key (safe, panic, exit).
enum class Pilot : uint8_t { pc = 0, radio = 1 };

using wire::Mode;
using wire::NackReason;  // the safety machine's refusals are the first reasons on the wire's list

constexpr uint8_t index(Mode m) { return static_cast<uint8_t>(m); }
inline constexpr uint8_t kModeCount = wire::kModeCount;

}  // namespace qr
