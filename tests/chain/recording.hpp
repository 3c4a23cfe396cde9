// The synthetic flight as replay input CSV text (docs/replay.md): what make-recording prints and
// the committed tests/data/synthetic_flight.csv holds. Times start at 1 s of uptime.
#pragma once

#include <cstdio>
#include <string>

#include <qr/host/replay.hpp>

#include "synthetic_flight.hpp"

namespace qr::chain::test {

template <uint32_t Hz>
std::string synthetic_recording_csv() {
  std::string csv = host::replay_input_header() + "\n";
  synthetic::Flight<Hz> flight;
  for (uint32_t n = 0; n < synthetic::Flight<Hz>::kTicks; ++n) {
    const synthetic::Tick t = flight.next();
    const SensorSample& s = t.sample;
    char line[128];
    std::snprintf(line, sizeof line, "%u,%d,%d,%d,%d,%d,%d,%u,%u,%d,%d,%d,%d\n",
                  synthetic::kStartUs + n * (1000000u / Hz), s.gyro[0], s.gyro[1], s.gyro[2], s.accel[0], s.accel[1],
                  s.accel[2], s.battery_mv, t.sticks.lift, t.sticks.roll, t.sticks.pitch, t.sticks.yaw, s.pressure_pa);
    csv += line;
  }
  return csv;
}

}  // namespace qr::chain::test
