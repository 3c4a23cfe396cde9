// One axis of the vehicle as the loops see it, and that model in discrete time at the control rate.
//
//   rate'(t) = gain x (a(t) + lead x a'(t)) - damping x rate(t) + c,    tau_m a'(t) = m(t - delay) - a(t)
//
// m is the moment the mixer was asked for (thrust units, engine_mixer.hpp), held over each control
// period (the engines keep a command until the next tick); a is the moment the motors give, m
// through their speed lag; c a constant disturbance (rad/s^2: a centre of mass off the middle,
// unequal motors), fitted and then dropped (no loop margin depends on it). lead and damping are 0
// for roll and pitch. For yaw, lead is the rotors' reaction: a motor speeding up twists the
// airframe the way its extra drag will, at once (J_rotor / (2 k_m omega_hover), 0.23 s on the
// default vehicle); damping is the rotors' drag against a turning airframe (0.8 1/s there).
//
// What the loops measure is the rate through the sensor low-pass (sensor_lowpass.hpp). The model
// keeps the two apart: delay_s is the pure delay beyond the sample-and-hold of the control period
// and beyond the low-pass, which the fit and the design both model exactly (the low-pass from its
// cut-off, the hold by integrating over each period). So a vehicle whose moment acts from the
// tick that asked for it (the simulator: the engines change at the tick, the gyro is sampled at
// the next one) has delay 0; an ESC's latency, a sensor's own filter, a tick of computation appear
// in it.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace tune {

struct AxisModel {
  double gain = 0;           // rad/s^2 per thrust unit
  double motor_tau_s = 0;    // the motors' first-order lag
  double delay_s = 0;        // pure delay, the control period's hold and the sensor low-pass not included
  double lead_s = 0;         // yaw's rotor-reaction lead (0 for roll and pitch)
  double damping_per_s = 0;  // yaw's drag damping of the rate (0 for roll and pitch)
  // The fit's normalised equation error (axis_fit.hpp): RMS of (measured - modelled) angular
  // acceleration over the RMS of the measured one, both smoothed as the fit smooths them. 0 for a
  // model not fitted.
  double residual = 0;
};

// The model stepped once per control period, exactly: the moment is constant over each period
// (a whole number of periods of delay, then a fraction), the lag and the integral are solved in
// closed form over the parts of the period, so there is no discretisation error at any rate. (The
// damping is stepped by its period's start, an error of (damping T)^2 / 2, 3e-7 at 1 kHz.)
class SampledAxis {
 public:
  // At rest: no moment asked for so far, the rate 0.
  SampledAxis(const AxisModel& model, double sample_hz);
  // As if `moment` had been asked for long enough for the motors to give it (a record starts in
  // flight).
  void settle(double moment);

  // What one period with this tick's moment does, per unit gain: the motors' mean moment over the
  // period and their moment's change per second. The rate changes by gain x T x (mean + lead x
  // change - damping x rate) (+ c T).
  struct Increment {
    double mean, change;
  };
  Increment increment(double moment);
  // One period with this tick's moment (thrust units) and a disturbance (rad/s^2): the rate at the
  // next sample.
  double step(double moment, double disturbance = 0);
  double rate() const { return rate_; }

  // Moment asked for -> rate at the samples (unfiltered), at z = e^(j omega T).
  std::complex<double> response(double omega_rad_s) const;

 private:
  double gain_, lead_, damping_, period_;
  int whole_;                         // whole periods of delay
  double e_, carry_old_, carry_new_;  // a(k+1) = e a(k) + carry_old m(k-whole-1) + carry_new m(k-whole)
  double int_a_, int_old_, int_new_;  // integral of a over the period / T = int_a a + int_old .. + int_new ..
  std::vector<double> past_;          // the last whole + 2 moments, a ring
  std::size_t newest_ = 0;
  double motor_ = 0, rate_ = 0;
};

}  // namespace tune
