// The tests' own closed loop, independent of tune/'s discrete model: the axis integrated in
// continuous time (20 steps a control period), the firmware's controllers themselves
// (qr/core/chain/controllers.hpp in double), the firmware's Butterworth design for the gyro
// low-pass, an estimator that integrates the filtered rate, and what an identification flight adds:
// a pseudo-random binary sequence on the moment, gyro noise and a constant disturbance moment.
// It makes the records the fit must read, and it is the judge of the design's margins and steps.
#pragma once

#include <stdint.h>

#include <vector>

#include <tune/axis_fit.hpp>
#include <tune/axis_model.hpp>

namespace tune::test {

// Raw parameter values, as the firmware takes them.
struct RawGains {
  int32_t p1 = 1408, p2 = 3520, i = 1280, d = 2048;  // roll/pitch (the table's defaults)
  int32_t yaw_p = 4800, yaw_i = 4800;
};

struct FlightSetup {
  AxisModel truth;   // gain, motor_tau_s, delay_s (and for yaw lead_s, damping_per_s)
  bool yaw = false;  // the yaw rate loop, else roll's cascade
  RawGains gains;
  double seconds = 4;
  double control_hz = 1000;
  double filter_cutoff_hz = 20;
  double prbs_amplitude = 40;  // thrust units; 0: no excitation
  double prbs_bit_s = 0.02;
  double gyro_noise = 0.01;  // rad/s RMS per sample, white, before the low-pass
  double disturbance = 15;   // thrust units, a constant moment on the airframe
  double setpoint = 0;       // angle (rad) or yaw rate (rad/s) from the start
  double initial_rate = 0;   // rad/s: a kick to see whether the loop rings down or up
  uint32_t seed = 1;
  // Perturbations at the two places the loops are broken for their margins: the plant's gain and
  // an extra delay at the moment; a gain and a delay (whole periods) on the angle the angle loop reads.
  double plant_gain_scale = 1;
  double extra_delay_s = 0;
  double angle_gain_scale = 1;
  int angle_delay_ticks = 0;
};

struct Flight {
  AxisRecord record;          // the moment asked for and the rate the loops saw, per tick
  std::vector<double> angle;  // true angle at each tick (roll)
  std::vector<double> rate;   // true rate at each tick
};

Flight fly(const FlightSetup& setup);

// Largest |x| over [from, to) seconds of a per-tick trace.
double peak(const std::vector<double>& x, double control_hz, double from, double to);

}  // namespace tune::test
