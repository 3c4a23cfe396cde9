// Where each part of the engines' command comes from: one row per mode (qr/core/flight_tasks.hpp,
// kFlightModes), handed to the chain when the mode is entered (FlightChain::fly). The attitude and
// yaw tasks read it for what to aim at, the mixer for which moment and which lift it mixes; nothing
// else decides. Roll and pitch always share their source. As Crazyflie's setpoint gives each axis
// a mode (absolute, velocity, disabled), a new way of flying is a new row, not new flags.
#pragma once

#include <stdint.h>

namespace qr::chain {

// Roll and pitch.
enum class Tilt : uint8_t {
  stick,  // the sticks' moments, open loop (manual, yaw control)
  angle,  // the angle loop around the rate loop, to the sticks' angles (full control, height hold)
  level,  // the same loops, to level (a landing)
  rate,   // the rate loop alone, to the sticks' rates (acro)
};

// Yaw.
enum class Yaw : uint8_t {
  stick,  // the stick's moment, open loop (manual)
  rate,   // the yaw rate loop, to the stick's rate
  still,  // the yaw rate loop, to no turn (a landing)
};

// The lift.
enum class Lift : uint8_t {
  stick,    // the pilot's lift stick
  hold,     // the vertical loops, holding the height at entry (height hold)
  descend,  // the vertical loops, descending until the touchdown (a landing)
};

// A known moment added to the loops' (the autotune's identification flight, identification.hpp).
enum class Excite : uint8_t {
  none,
  prbs,  // a pseudo-random binary sequence on one axis at a time
};

struct EngineSources {
  Tilt tilt;
  Yaw yaw;
  Lift lift;
  Excite excite = Excite::none;
};

inline constexpr EngineSources kOpenLoop{Tilt::stick, Yaw::stick, Lift::stick};
inline constexpr EngineSources kLanding{Tilt::level, Yaw::still, Lift::descend};

}  // namespace qr::chain
