// A signal chain for firmware tests: it does what the test sets, so the tests exercise the
// flight context (link, safety, telemetry, task sets) without the physics of a real chain.
#pragma once

#include <stdint.h>

#include <common/parameter_table.hpp>
#include <qr/core/board.hpp>
#include <qr/core/chain/engine_sources.hpp>
#include <qr/core/flight_types.hpp>

namespace qr::test {

struct ScriptedChain {
  static constexpr uint32_t kAccelDivider = 4;
  static constexpr uint32_t kHeightDivider = 4;

  // Scripted behaviour
  uint32_t calibration_samples = 10;
  int32_t tilt = 0;
  bool landed_now = false;      // what landed() says
  uint16_t hover_lift_now = 0;  // what hover_lift() says
  bool height_known = true;     // what height_valid() says

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

  int16_t roll_e4() const { return 123; }
  int16_t pitch_e4() const { return -45; }
  int16_t yaw_e4() const { return 6; }
  int16_t p_e3() const { return 7; }
  int16_t q_e3() const { return 8; }
  int16_t r_e3() const { return 9; }
  int16_t roll_setpoint_e4() const { return 0; }
  int16_t pitch_setpoint_e4() const { return 0; }
  int16_t yaw_rate_setpoint_e3() const { return 0; }
  int32_t tilt_mrad() const { return tilt; }
  int16_t gyro_filtered(int axis) const { return static_cast<int16_t>(10 + axis); }
  int16_t accel_filtered(int axis) const { return static_cast<int16_t>(-20 - axis); }
  // The controllers' terms: a distinct value for each term and axis, so a test sees which one a
  // reader took.
  int16_t rate_setpoint_e3(int axis) const { return static_cast<int16_t>(100 + axis); }
  int32_t p_term_e1(int axis) const { return 200 + axis; }
  int32_t d_term_e1(int axis) const { return -300 - axis; }
  int32_t integral_e1(int axis) const { return 400 + axis; }
  int32_t moment_e1(int axis) const { return -500 - axis; }
  int32_t climb_setpoint_mm_s() const { return 601; }
  int32_t vertical_p_term_mm_s2() const { return -602; }
  int32_t vertical_integral_mm_s2() const { return 603; }
  int32_t vertical_thrust_e1() const { return 2604; }

 private:
  static EngineCommand all(uint16_t v) { return EngineCommand{{v, v, v, v}}; }
  uint32_t run_samples_ = 0;
  bool calibrated_ = false;
};

}  // namespace qr::test
