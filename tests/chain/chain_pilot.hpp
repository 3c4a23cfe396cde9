// A FlightChain driven tick by tick as the flight's task sets drive it (qr/core/flight_tasks.hpp),
// for the tests that fly the chain itself: the accelerometer angles every kAccelDivider-th tick,
// the modes' entry actions on a change of mode.
#pragma once

#include <gtest/gtest.h>

#include <qr/core/chain/flight_chain.hpp>

#include "chain_test_support.hpp"

namespace qr::chain::test {

enum class Mode { manual, yaw, full, none };

template <class Chain>
struct Pilot {
  Chain chain;
  uint32_t ticks_run = 0;
  bool in_full = false;
  Mode last_mode_ = Mode::none;

  void calibrate_level(const double (&gyro_offset)[3] = {0, 0, 0}, const double (&accel_offset)[3] = {0, 0, 0}) {
    chain.enter_calibration();
    in_full = false;
    for (int32_t n = 0;; ++n) {
      chain.set_pilot({});
      chain.filter(sample_at(0, 0, 0, 0, 0, gyro_offset, accel_offset));
      if (chain.calibrate()) break;
      ASSERT_LT(n, 10000);
    }
  }
  // The modes' sources as the flight's mode table gives them (flight_tasks.hpp); a landing's
  // (start_descent) stays until the mode changes.
  static chain::EngineSources sources_of(Mode mode) {
    using chain::Lift, chain::Tilt, chain::Yaw;
    return mode == Mode::manual ? chain::kOpenLoop
           : mode == Mode::yaw  ? chain::EngineSources{Tilt::stick, Yaw::rate, Lift::stick}
                                : chain::EngineSources{Tilt::angle, Yaw::rate, Lift::stick};
  }
  EngineCommand tick(Mode mode, const SensorSample& s, const ControlInput& sticks) {
    if (mode == Mode::full && !in_full) chain.enter_attitude_control();
    if (mode != last_mode_ && chain.sources().lift != chain::Lift::descend) chain.fly(sources_of(mode));
    last_mode_ = mode;
    in_full = mode == Mode::full;
    chain.set_pilot(sticks);
    chain.filter(s);
    if (ticks_run++ % Chain::kAccelDivider == 0) chain.estimate_accel_angles();
    chain.estimate();
    if (mode == Mode::manual) return chain.mix(chain::kOpenLoop);
    if (mode == Mode::full) chain.control_attitude();
    chain.control_yaw();
    return chain.mix();
  }
  EngineCommand run(Mode mode, const SensorSample& s, const ControlInput& sticks, int ticks) {
    EngineCommand e;
    for (int n = 0; n < ticks; ++n) e = tick(mode, s, sticks);
    return e;
  }
};

inline ControlInput sticks(uint16_t lift, int16_t roll = 0, int16_t pitch = 0, int16_t yaw = 0) {
  ControlInput c;
  c.lift = lift;
  c.roll = roll;
  c.pitch = pitch;
  c.yaw = yaw;
  return c;
}

// Level, at rest in the air, reading `g` along the thrust (1 g: hovering, more: climbing off).
inline SensorSample climbing(double g) {
  SensorSample s = sample_at(0, 0);
  s.accel[2] = counts(-g * sensor::kAccelCountsPerG);
  return s;
}

}  // namespace qr::chain::test
