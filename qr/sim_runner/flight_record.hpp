// What a scenario flight records from t0 on, every control period, for the figures: the truth
// from the plant, the firmware's estimate and set-points, and the events that happen once
// (panic, touchdown). scenario.cpp fills it; scenario_score.cpp turns it into figures.
#pragma once

#include <stdint.h>

#include <string>

#include <qr/sim_runner/scoring.hpp>

namespace qrsim {

struct FlightRecord {
  double t0 = -1;                                                       // the manoeuvre's start (s of simulated time)
  double t_end = 0;                                                     // the window's end
  Trace roll_true, pitch_true, roll_est, pitch_est, roll_sp, pitch_sp;  // degrees, every tick
  Trace r_true;                                                         // rad/s
  Trace tilt;                                                           // degrees from vertical
  // Ticks in full control or height hold only, where the attitude loops fly the pilot's
  // set-points (the attitude figures judge the flight, not a panic's descent):
  Trace att_err;       // √((e_φ² + e_θ²)/2) of truth - set-point
  Trace axis_err;      // max(|e_φ|, |e_θ|) of truth - set-point
  Trace est_err;       // √((x_φ² + x_θ²)/2) of estimate - truth
  Trace est_err_axis;  // max(|x_φ|, |x_θ|)
  Trace saturated;     // full-control ticks airborne only: 0 or 100
  Trace worst_err;     // every tick: max(|e_φ|, |e_θ|), for the recovery after a push

  bool entered_panic = false;
  double panic_at = kNotMeasured, safe_at = kNotMeasured;
  double rested_v_at_panic = kNotMeasured;
  // Why, as the firmware announced it on its debug text ("battery low", "link lost", ...: the
  // names of qr::kPanicCauseNames); empty when no announcement was heard by the window's end.
  std::string panic_cause;
  double battery_v_min = kNotMeasured, rested_v_min = kNotMeasured;
  double touchdown_speed = kNotMeasured;  // m/s, the first after having been airborne
  double touchdown_at = kNotMeasured, engines_stopped_at = kNotMeasured;
  double panic_engines_zero_at = kNotMeasured;  // the first tick from the panic on with every engine at 0
  double max_clearance = 0;                     // m, the lowest contact point's highest above the ground
  // What the firmware believed against the truth, from t0 on:
  bool belief_seen = false;                  // the firmware's flying/landed verdict was read
  bool believed_flying = false;              // ... and what it was last tick
  uint8_t belief_mode = 0;                   // the mode last tick
  double left_ground_at = kNotMeasured;      // the truth: first tick airborne after one on the ground
  double flying_seen_at = kNotMeasured;      // the firmware's first "flying" from then on
  int false_takeoffs = 0;                    // landed -> flying while on the ground, thrust below weight
  double declared_clearance = kNotMeasured;  // the largest true clearance at a flying -> landed with lift
  // Height hold: the first stay in it
  double hold_entry_height = kNotMeasured;  // true height, m, at the first tick in height hold
  Trace hold_height_err;                    // true height minus that, m, every tick in height hold
  int hold_lift = -1;                       // the lift stick the QR had read when it held
  double hold_lift_changed_at = kNotMeasured, hold_left_at = kNotMeasured;
};

// The plant and firmware at the end, for the figures that need them.
struct EndState {
  double yaw_rate_setpoint = 0;    // rad/s, the firmware's
  double yaw_rate_p_only = 0;      // rad/s, where the P term alone settles
  double battery_panic_volts = 0;  // the firmware's parameter
};

}  // namespace qrsim
