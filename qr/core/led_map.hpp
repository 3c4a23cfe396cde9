// The QR's LEDs: one per state the pilot must see at a glance. Bit 0 safe, bit 1 panic, bit 2 a
// flight mode or the motor test (engines may turn), bit 3 battery warning.
#pragma once

#include <stdint.h>

#include <common/mode.hpp>

namespace qr {

inline constexpr uint8_t kLedSafe = 1, kLedPanic = 2, kLedFlying = 4, kLedBatteryWarning = 8;

constexpr uint8_t led_pattern(wire::Mode mode, bool battery_warning) {
  return static_cast<uint8_t>((mode == wire::Mode::safe ? kLedSafe : 0) | (mode == wire::Mode::panic ? kLedPanic : 0) |
                              (wire::flies(mode) || mode == wire::Mode::motor_test ? kLedFlying : 0) |
                              (battery_warning ? kLedBatteryWarning : 0));
}

}  // namespace qr
