// The model of one axis (axis_model.hpp) fitted to an identification record: the vehicle hovering
// in closed loop, a pseudo-random binary sequence added to one axis' moment, the moment asked for
// and the rate the loops saw logged at the control rate.
//
// Method: equation error on the rate's change, with the model's unknown dynamics (motor lag,
// delay) searched and its linear parameters (gain, and for yaw lead and damping; disturbance)
// solved by least squares.
// For a trial lag and delay, the logged moment is run through the model's motor path at unit gain
// (SampledAxis: exact over each period) and through the same sensor low-pass the rate passed; the
// rate's change per period must then be gain x that (yaw: + gain x lead x the motors' change -
// damping x the rate) + a constant. Both sides are smoothed by one more low-pass (20 Hz) before they are compared:
// differencing the rate lifts its noise at high frequency, where the excitation has little power,
// and the same filter on both sides leaves the equation exact. A coarse grid over lag and delay,
// then a pattern search from its best point, finds the least squared error.
//
// Why this and not another:
// - Equation error, not output error: the rate is the integral of the moment, so a simulated
//   output drifts with anything not modelled (a disturbance that changes, the mixer's limits) and
//   a small gain error grows without bound over the record; the change per period is local.
// - Closed loop: the moment depends on the measured rate, so its noise reaches the regressors.
//   Here it reaches them only through the controller, the motors' lag and the delay, a path much
//   slower than the noise is white, and the excitation dominates the moment (the record is refused
//   when it does not): the bias stays far inside the 5 % the tests ask (tests/tune/axis_fit_test.cpp).
// - The low-pass is modelled from its cut-off, not folded into the delay: a second-order
//   Butterworth is not a delay (its phase is not linear in frequency), and the design models it
//   exactly too, so a change of filter_cutoff_hz needs no new flight.
// - Lag and delay by search, gain by least squares: the error is quadratic in gain, lead and
//   disturbance, so only two dimensions are searched, and the result is the global least-squares
//   fit within the searched range, not a local one an iteration happened to reach.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <tune/axis_model.hpp>

namespace tune {

struct AxisRecord {
  double sample_hz = 0;
  std::vector<double> moment;    // per tick: asked of the mixer on this axis (thrust units, after the clamp)
  std::vector<double> rate;      // per tick: the rate the loops saw (rad/s, through the sensor low-pass)
  double filter_cutoff_hz = 20;  // the low-pass the rate passed (filter_cutoff_hz); 0: none
  bool yaw = false;              // fit the rotors' reaction lead and drag damping too
};

// The search's bounds and the record's requirements (the reasons a record is refused).
struct FitBounds {
  static constexpr double kMinTauS = 0.002, kMaxTauS = 0.25;  // motor lag searched
  static constexpr double kMaxDelayS = 0.08;                  // pure delay searched (from 0)
  static constexpr double kSettleS = 0.25;     // the record's first part, where the filters settle: not fitted
  static constexpr double kMinSeconds = 2.0;   // fitted part at least
  static constexpr double kMinExcitation = 3;  // thrust units RMS of the smoothed moment about its mean
  static constexpr double kMaxResidual = 0.5;  // the model must explain three quarters of the variance
};

// The fitted model, or nothing and why (in `why_not`): a record too short, without excitation,
// with samples that are not numbers, or one the model does not explain.
std::optional<AxisModel> fit_axis(const AxisRecord& record, std::string* why_not = nullptr);

}  // namespace tune
