// What the flight asks of a signal chain, as the Board concept says what it asks of a board: the
// chain's tasks and entry actions (called from the task and mode tables, flight_tasks.hpp) and the
// read-outs the safety machine uses; what telemetry, the logs and streams read is named by the
// observables' readers (observable_readers.hpp). FlightChain (chain/flight_chain.hpp)
// is the one that flies; tests use scripted ones.
#pragma once

#include <stdint.h>

#include <common/parameter_table.hpp>
#include <qr/core/board.hpp>
#include <qr/core/chain/engine_sources.hpp>
#include <qr/core/chain/gyro_turns.hpp>
#include <qr/core/flight_types.hpp>

namespace qr {

template <class T>
concept ConvertibleToEngines = requires(T t) {
  EngineCommand{t};
};

template <class C>
concept SignalChain = requires(C& c, const C& cc, const wire::ParameterValues& p, const ControlInput& sticks,
                               const SensorSample& sample) {
  {C::kAccelDivider};   // the accelerometer-angle task's divider of the control rate
  {C::kHeightDivider};  // the height estimate's
  c.set_parameters(p);  // when a parameter changes, never per tick
  c.set_pilot(sticks);
  // tasks
  c.filter(sample);
  {c.calibrate()};  // true once the running calibration has finished
  // then, once, a gyro scale measurement's result when the run measured turns, else nullptr
  {c.take_gyro_turns()};
  c.estimate_accel_angles();
  c.estimate();
  c.estimate_height();
  c.control_vertical();
  c.control_attitude();
  c.control_yaw();
  { c.mix() } -> ConvertibleToEngines;
  { c.mix(chain::kOpenLoop) } -> ConvertibleToEngines;  // the manual set's mixer: the sticks, open loop
  c.restart_estimator();                                // at rest on the ground: start over from the accelerometer
  // entry actions
  c.enter_calibration();
  c.enter_attitude_control();
  c.enter_yaw_control();
  c.enter_height_hold();
  c.enter_identification();     // the autotune's: its sequence starts (chain/identification.hpp)
  c.start_descent(uint16_t{});  // a panic that lands, from the lift that was flying
  c.fly(chain::kOpenLoop);      // the door: where each axis and the lift come from (engine_sources.hpp)
  // read-outs: the safety machine's, in its parameters' units
  {cc.calibrated()};
  {cc.calibration_refused()};  // the last run's axis that read gravity off body z (none: taken)
  {cc.wrong_sign()};           // the sign check's verdict (chain/sign_check.hpp)
  {cc.landed()};
  {cc.identification_over()};  // the autotune's sequence has ended (or never started)
  {cc.hover_lift()};           // engine units, 0: not learnt
  {cc.height_valid()};
  {cc.tilt_mrad()};
  {cc.height_mm()};
  {cc.gyro_filtered(0)};   // the sensor log's, in counts
  {cc.accel_filtered(0)};  // ...
  // The rest is read by the observables' readers (observable_readers.hpp: the attitude, rates,
  // set-points, the controllers' terms), each named there once, by its observable, in the
  // chain's own numbers: telemetry, the logs and streams read them through the readers.
  typename C::Numbers;  // the number policy those values are in (the readers convert with it)
};

}  // namespace qr
