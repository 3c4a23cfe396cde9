// A signal chain for firmware tests: it does what the test sets, so the tests exercise the
// flight context (link, safety, telemetry, task sets) without the physics of a real chain.
#pragma once

#include <stdint.h>

#include <common/parameter_table.hpp>
#include <qr/core/board.hpp>
#include <qr/core/chain/engine_sources.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/sensor_calibration.hpp>
#include <qr/core/chain/sign_check.hpp>
#include <qr/core/flight_types.hpp>

namespace qr::test {

struct ScriptedChain {
  static constexpr uint32_t kAccelDivider = 4;
  static constexpr uint32_t kHeightDivider = 4;

  // Scripted behaviour
  uint32_t calibration_samples = 10;
  int32_t tilt = 0;
  bool landed_now = false;                                                    // what landed() says
  uint16_t hover_lift_now = 0;                                                // what hover_lift() says
  bool height_known = true;                                                   // what height_valid() says
  chain::SignAxis sign_verdict = chain::SignAxis::none;                       // what wrong_sign() says
  chain::CalibrationAxis calibration_verdict = chain::CalibrationAxis::none;  // what calibration_refused() says

  // What the firmware did to it
  uint32_t filtered = 0;
  uint32_t estimated = 0;
  uint32_t accel_angles = 0;
  uint32_t height_estimated = 0;
  uint32_t calibrations_entered = 0;
  uint32_t attitude_entered = 0;
  uint32_t yaw_entered = 0;
  uint32_t yaw_controlled = 0;
  uint32_t attitude_controlled = 0;
  uint32_t parameter_updates = 0;
  uint32_t estimator_restarts = 0;
  uint32_t vertical_controlled = 0;
  uint32_t height_holds_entered = 0;
  uint32_t identifications_entered = 0;
  bool identification_done = true;
  uint32_t descents_started = 0;
  uint16_t descent_from_lift = 0;
  uint16_t descent_engines = 0;  // what mix() gives while descending (the chain flies the lift)
  uint16_t hold_engines = 0;     // what mix() gives while holding the height
  bool holding = false, descending = false;
  chain::EngineSources sources = chain::kOpenLoop;
  int32_t yaw_p = 0;
  ControlInput pilot;

  void set_parameters(const wire::ParameterValues& p) {
    ++parameter_updates;
    yaw_p = p.get(wire::ParamId::yaw_p);
  }
  void set_pilot(const ControlInput& c) { pilot = c; }
  void filter(const SensorSample&) { ++filtered; }
  bool calibrate() {
    if (run_samples_ < calibration_samples) ++run_samples_;
    if (run_samples_ == calibration_samples) calibrated_ = true;
    return run_samples_ == calibration_samples;
  }
  bool calibrated() const { return calibrated_; }
  chain::CalibrationAxis calibration_refused() const { return calibration_verdict; }
  chain::SignAxis wrong_sign() const { return sign_verdict; }
  // A run with turns: what the next finished calibration run says the turns gave, once.
  bool turns_scripted = false;
  chain::GyroTurnsResult turns_result{};
  const chain::GyroTurnsResult* take_gyro_turns() {
    if (!turns_scripted) return nullptr;
    turns_scripted = false;
    return &turns_result;
  }
  void enter_calibration() {
    ++calibrations_entered;
    run_samples_ = 0;
  }
  void estimate_accel_angles() { ++accel_angles; }
  void estimate() { ++estimated; }
  void estimate_height() { ++height_estimated; }
  void control_vertical() { ++vertical_controlled; }
  void enter_height_hold() { ++height_holds_entered; }
  // The autotune: entering starts the sequence, which a test ends by setting identification_done.
  void enter_identification() {
    ++identifications_entered;
    identification_done = false;
  }
  bool identification_over() const { return identification_done; }
  void start_descent(uint16_t flying_lift) {
    ++descents_started;
    descent_from_lift = flying_lift;
  }
  // The door's sources (engine_sources.hpp): who flies the lift.
  void fly(chain::EngineSources s) {
    sources = s;
    holding = s.lift == chain::Lift::hold;
    descending = s.lift == chain::Lift::descend;
  }
  bool landed() const { return landed_now; }
  uint16_t hover_lift() const { return hover_lift_now; }
  bool height_valid() const { return height_known; }
  int32_t height_mm() const { return 0; }
  int32_t climb_mm_s() const { return 0; }
  void restart_estimator() { ++estimator_restarts; }
  void enter_attitude_control() { ++attitude_entered; }
  void enter_yaw_control() { ++yaw_entered; }
  void control_yaw() { ++yaw_controlled; }
  void control_attitude() { ++attitude_controlled; }
  // Every engine at the lift stick: enough to see that the mixer ran and what the safety
  // machine then did with it.
  EngineCommand mix(chain::EngineSources from) const {
    return all(from.lift == chain::Lift::descend ? descent_engines
               : from.lift == chain::Lift::hold  ? hold_engines
                                                 : pilot.lift);
  }
  EngineCommand mix() const { return mix(sources); }

  // The read-outs, in the flight chain's numbers (the observables' readers convert them): the
  // attitude 123, -45 and 6 in 1e-4 rad, the rates 7, 8 and 9 in 1e-3 rad/s.
  using Numbers = chain::FixedNumbers;
  using Angle = Numbers::Angle;
  using Rate = Numbers::Rate;
  using Thrust = Numbers::Thrust;
  Angle roll() const { return Angle(0.0123); }
  Angle pitch() const { return Angle(-0.0045); }
  Angle yaw() const { return Angle(0.0006); }
  Rate p() const { return Rate(0.007); }
  Rate q() const { return Rate(0.008); }
  Rate r() const { return Rate(0.009); }
  Angle roll_setpoint() const { return {}; }
  Angle pitch_setpoint() const { return {}; }
  Rate yaw_rate_setpoint() const { return {}; }
  int32_t tilt_mrad() const { return tilt; }
  int16_t gyro_filtered(int axis) const { return static_cast<int16_t>(10 + axis); }
  int16_t accel_filtered(int axis) const { return static_cast<int16_t>(-20 - axis); }
  Numbers::Climb climb() const { return {}; }
  // The controllers' terms: a distinct value for each term and axis, so a test sees which one a
  // reader took. In the wire's units: rate set-points 100 + axis (1e-3 rad/s); P terms 200 +
  // axis, D terms -300 - axis, integrals 400 + axis, moments -500 - axis (0.1 thrust units); the
  // vertical loops' climb set-point 601 mm/s, P term -602 and integral 603 mm/s², thrust 2604.
  Rate rate_setpoint(int axis) const { return kRateSetpoints[axis]; }
  Thrust p_term(int axis) const { return kPTerms[axis]; }
  Thrust d_term(int axis) const { return kDTerms[axis]; }
  Thrust integral(int axis) const { return kIntegrals[axis]; }
  Thrust moment(int axis) const { return kMoments[axis]; }
  Numbers::Climb climb_setpoint() const { return Numbers::Climb(0.601); }
  Numbers::VerticalAccel vertical_p_term() const { return Numbers::VerticalAccel(-0.602); }
  Numbers::VerticalAccel vertical_integral() const { return Numbers::VerticalAccel(0.603); }
  Thrust vertical_thrust() const { return Thrust(260.4); }

 private:
  static EngineCommand all(uint16_t v) { return EngineCommand{{v, v, v, v}}; }
  static constexpr Rate kRateSetpoints[3] = {Rate(0.100), Rate(0.101), Rate(0.102)};
  static constexpr Thrust kPTerms[3] = {Thrust(20.0), Thrust(20.1), Thrust(20.2)};
  static constexpr Thrust kDTerms[3] = {Thrust(-30.0), Thrust(-30.1), Thrust(-30.2)};
  static constexpr Thrust kIntegrals[3] = {Thrust(40.0), Thrust(40.1), Thrust(40.2)};
  static constexpr Thrust kMoments[3] = {Thrust(-50.0), Thrust(-50.1), Thrust(-50.2)};
  uint32_t run_samples_ = 0;
  bool calibrated_ = false;
};

}  // namespace qr::test
