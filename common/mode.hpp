// Flight modes as numbered on the wire (the mode change request and the telemetry mode field).
// The QR's safety machine numbers its modes the same way.
#pragma once

#include <stdint.h>

namespace wire {

enum class Mode : uint8_t { safe = 0, panic = 1, manual = 2, calibration = 3, yaw_control = 4, full_control = 5 };

inline constexpr uint8_t kModeCount = 6;

constexpr bool valid_mode(Mode mode) { return static_cast<uint8_t>(mode) < kModeCount; }

}  // namespace wire
