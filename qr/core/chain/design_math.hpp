// Double-precision math for filter design at compile time. The freestanding build has no <cmath>,
// and the design must be a constant expression, so the few functions it needs are series here.
// Only constexpr/consteval code may call these in the flight build: a call at run time would pull
// in soft-float (the rv32 soft-float check would find it). The host tool qrfilter calls them at
// run time on purpose, to print exactly the design the firmware uses.
#pragma once

#include <stdint.h>

#include <fixedpoint/design_constants.hpp>

namespace qr::chain::design {

using fx::kPi;
inline constexpr double kSqrt2 = 1.41421356237309504880;

// sin and cos by their Taylor series, for |x| <= pi/4, where 13 terms leave a remainder below
// x^27/27! < 1e-31: the result is as good as double rounding allows.
constexpr double sin_near_zero(double x) {
  double term = x, sum = x;
  for (int n = 1; n <= 13; ++n) {
    term *= -x * x / ((2.0 * n) * (2.0 * n + 1.0));
    sum += term;
  }
  return sum;
}

constexpr double cos_near_zero(double x) {
  double term = 1.0, sum = 1.0;
  for (int n = 1; n <= 13; ++n) {
    term *= -x * x / ((2.0 * n - 1.0) * (2.0 * n));
    sum += term;
  }
  return sum;
}

// tan(x) for 0 <= x < pi/2 (the bilinear pre-warp tan(pi fc / fs) with fc < fs / 2). Above pi/4
// it is cot(pi/2 - x), so the small cosine near pi/2 comes from a sine series, which keeps its
// relative accuracy.
constexpr double tan_first_quadrant(double x) {
  if (x <= kPi / 4) return sin_near_zero(x) / cos_near_zero(x);
  const double y = kPi / 2 - x;
  return cos_near_zero(y) / sin_near_zero(y);
}

// floor(v + 1/2) as an integer: round half up, the rounding the fixed-point library uses for its
// constants. |v| must stay below 2^62.
constexpr int64_t round_half_up(double v) {
  const double shifted = v + 0.5;
  int64_t n = static_cast<int64_t>(shifted);  // truncates toward zero
  if (static_cast<double>(n) > shifted) --n;
  return n;
}

using fx::pow2;

}  // namespace qr::chain::design
