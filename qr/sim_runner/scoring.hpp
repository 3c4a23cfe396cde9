// Flight figures from recorded traces: step response (rise, overshoot, settling), RMS, recovery
// after a disturbance. Pure functions of (time, value) samples, so they are tested on traces
// whose figures are known in closed form (tests/sim/scoring_test.cpp).
#pragma once

#include <cmath>
#include <limits>
#include <vector>

namespace qrsim {

inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

struct Sample {
  double t;
  double value;
};
using Trace = std::vector<Sample>;

struct StepFigures {
  double rise_s = kNotMeasured;         // 10 % to 90 % of the step, first crossings
  double overshoot_pct = kNotMeasured;  // peak beyond the target, % of the step (0 if none)
  double settle_s = kNotMeasured;       // from the step until the value stays within the band
};

// The response in `trace` to a set-point step at `t_step` from `from` to `to`; the band is
// absolute (same unit as the values), around `to`. Only samples at or after t_step count.
// Crossing times are interpolated between samples. A step that never reaches 90 % has no rise
// time; one that is outside the band at the last sample has no settling time.
StepFigures step_response(const Trace& trace, double t_step, double from, double to, double band);

// Root mean square of the values with t in [t0, t1].
double rms(const Trace& trace, double t0, double t1);

// Largest |value| with t in [t0, t1].
double peak_abs(const Trace& trace, double t0, double t1);

// Mean of the values with t in [t0, t1].
double mean(const Trace& trace, double t0, double t1);

// Time from t0 until |value| stays within `band` for good (to the end of the trace); NaN if it
// is outside at the last sample.
double recovery_time(const Trace& trace, double t0, double band);

}  // namespace qrsim
