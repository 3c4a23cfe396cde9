// Wire units. Everything on the wire is an integer; these are the scales.
#pragma once

#include <stdint.h>

namespace wire {

inline constexpr int32_t kAngleUnitsPerRad = 10000;  // angles in 1e-4 rad (int16: +-3.2767 rad)
inline constexpr int32_t kRateUnitsPerRadS = 1000;   // angular rates in 1e-3 rad/s (int16: +-32.767 rad/s)
inline constexpr uint16_t kEngineMax = 1000;         // engine commands 0..1000
inline constexpr uint16_t kLiftMax = 1000;           // lift stick 0..1000 (per mille of full lift)
inline constexpr int16_t kStickMax = 1000;           // roll/pitch/yaw sticks -1000..1000 (per mille)
inline constexpr uint16_t kPermilleMax = 1000;       // CPU load in per mille

// Clamps a wider value into int16 so an out-of-scale reading shows as the scale's end rather than
// wrapping to the opposite sign.
constexpr int16_t saturate_i16(int32_t value) {
  return value > 32767 ? int16_t{32767} : value < -32768 ? int16_t{-32768} : static_cast<int16_t>(value);
}

constexpr uint16_t saturate_u16(uint32_t value) {
  return value > 65535u ? uint16_t{65535} : static_cast<uint16_t>(value);
}

}  // namespace wire
