// Modes as the pilot reads them on the screen and in the log.
#pragma once

#include <common/mode.hpp>

namespace qrterm {

inline constexpr const char* kModeNames[wire::kModeCount] = {"safe", "panic", "manual", "calibration", "yaw control", "full control"};

inline const char* mode_name(wire::Mode mode) {
  return wire::valid_mode(mode) ? kModeNames[static_cast<uint8_t>(mode)] : "?";
}

// Modes the QR flies in (docs/safety.md): the engines may be running.
inline bool is_flight_mode(wire::Mode mode) {
  return mode == wire::Mode::manual || mode == wire::Mode::yaw_control || mode == wire::Mode::full_control;
}

}  // namespace qrterm
