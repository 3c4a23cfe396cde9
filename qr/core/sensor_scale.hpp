// Raw sensor counts to physical units (docs/conventions.md). MPU-6050 datasheet, rev. 3.4,
// sections 6.1 and 6.2: FS_SEL = 1 gives 65.5 LSB/(°/s), AFS_SEL = 1 gives 8192 LSB/g.
#pragma once

#include <stdint.h>

#include <fixedpoint/design_constants.hpp>

namespace qr::sensor {

inline constexpr double kGyroCountsPerDegPerSec = 65.5;
inline constexpr double kGyroCountsPerRadPerSec = kGyroCountsPerDegPerSec * 180.0 / fx::kPi;
inline constexpr double kAccelCountsPerG = 8192.0;
inline constexpr double kStandardGravity = 9.80665;  // m/s²

}  // namespace qr::sensor
