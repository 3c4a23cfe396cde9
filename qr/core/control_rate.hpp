// The control period is the core's unit of time. Slower tasks run at integer dividers of it.
#pragma once

#include <stdint.h>

#ifndef QR_CONTROL_HZ
#define QR_CONTROL_HZ 1000
#endif

namespace qr {

inline constexpr uint32_t kControlHz = QR_CONTROL_HZ;
inline constexpr uint32_t kPeriodUs = 1000000u / kControlHz;
static_assert(kControlHz >= 100 && 1000000u % kControlHz == 0,
              "the control rate must divide one second into whole microseconds");

// Divider that runs a task at `hz` (rounded down to what the control rate allows, at least 1).
constexpr uint16_t divider_for(uint32_t hz) {
  const uint32_t d = hz == 0 || hz >= kControlHz ? 1u : kControlHz / hz;
  return static_cast<uint16_t>(d > 0xFFFFu ? 0xFFFFu : d);
}

}  // namespace qr
