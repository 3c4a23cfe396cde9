// Flight modes, numbered as on the wire and on the keyboard (0-5).
#pragma once

#include <stdint.h>

namespace qr {

enum class Mode : uint8_t { safe = 0, panic = 1, manual = 2, calibration = 3, yaw = 4, full = 5 };
inline constexpr uint8_t kModeCount = 6;

constexpr uint8_t index(Mode m) { return static_cast<uint8_t>(m); }

}  // namespace qr
