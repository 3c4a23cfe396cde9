// The console's one clock: monotonic milliseconds as a wrapping uint32, the time type of the core.
#pragma once

#include <stdint.h>
#include <time.h>

namespace qrterm {

inline uint32_t monotonic_ms() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<uint32_t>(static_cast<uint64_t>(ts.tv_sec) * 1000u + static_cast<uint64_t>(ts.tv_nsec) / 1000000u);
}

}  // namespace qrterm
