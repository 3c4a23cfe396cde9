// Serve mode: the simulated QR in real time, its serial line on a pseudo terminal (or on stdin and
// stdout), so the ground console talks to it exactly as to the hardware. A host that runs it late
// pauses the world rather than skip simulated time (serve_clock.hpp); a console that does not
// read loses the QR's oldest frames rather than stop the world (serve_output.hpp).
#pragma once

#include <stdint.h>

#include <string>

#include <sim/vehicle.hpp>

namespace qrsim {

struct ServeOptions {
  bool stdio = false;  // the line on stdin/stdout instead of a pseudo terminal
  uint64_t seed = 1;
  sim::VehicleParams vehicle = sim::default_vehicle();
  double seconds = 0;   // > 0: stop after this much time (for tests); 0: until exit or a signal
  bool status = false;  // a status line on stderr once a second
  int truth_fd = -1;    // >= 0: the side channel (truth lines out, pushes in; truth_channel.hpp)
  // Non-empty: this RV32 ELF flies on the emulated devboard (devboard_qr.hpp) instead of the host
  // build; the console's bytes reach its UART through the simulated line, as the host build's do.
  std::string devboard_elf;
  uint32_t devboard_core_mhz = 0;  // --core-mhz N (scenario.hpp)
  // --esc dshot: the engines go out as DShot frames to simulated ESCs that answer with their eRPM
  // (the QR reports RPM: telemetry_rpm, the rpm_* observables).
  bool dshot = false;
  // The QR's receiver line carries a radio (--rc crsf, host build only): the console's sticks go
  // through it as CRSF frames at 150 Hz and the side channel moves its switches (serve_radio.hpp).
  bool radio = false;
  // --sensors drivers: the firmware's drivers read the chip models over the board's I2C bus, as in
  // a scenario (scenario.hpp). Not the default here: the MPU answers nothing for its first 100 ms
  // and streams from about 0.28 s, and until then the QR refuses to leave safe (safety.md rule
  // 20), which a console that asks at once (the tests', a script's) would have to wait out.
  bool sensor_drivers = false;
};

// Runs until the firmware stops (the console sent exit), SIGINT or SIGTERM (within a second,
// whatever it is doing), or `seconds` of simulated time. Returns the process exit code.
int serve(const ServeOptions& options);

}  // namespace qrsim
