// Stability margins of a loop from its frequency response, found numerically: the loop gain L is
// evaluated on a dense logarithmic sweep from 0.01 Hz to just below half the sample rate (the
// discrete loop's whole band), its phase unwrapped from the low end.
//
//   phase margin  180 deg + the phase where |L| crosses 1 (the least over all such crossings);
//   crossover     the frequency of that crossing;
//   gain margin   -20 log10 |L| where the phase crosses -180 deg (mod 360) with |L| < 1: by how
//                 much the gain may grow (the least over such crossings; infinite if none).
//
// A phase crossing with |L| > 1 (a loop with two integrators starts at -180 deg) is where the gain
// may not fall, not grow: it is not a gain margin in this sense, and the step response tells
// whether such a loop behaves.
#pragma once

#include <complex>
#include <functional>

namespace tune {

struct Margins {
  double phase_margin_deg = 0;
  double gain_margin_db = 0;  // +infinity when the phase never crosses -180 deg below the gain's 1
  double crossover_hz = 0;
};

Margins margins_of(const std::function<std::complex<double>(double omega_rad_s)>& loop, double sample_hz);

}  // namespace tune
