// Constants and helpers of compile-time design maths, written once for every layer: pi, and exact
// powers of two as doubles. constexpr only in the flight build (a call at run time on the target
// would pull in soft-float).
#pragma once

namespace fx {

inline constexpr double kPi = 3.14159265358979323846;

constexpr double pow2(int n) {
  double p = 1.0;
  for (; n > 0; --n) p *= 2.0;
  for (; n < 0; ++n) p *= 0.5;
  return p;
}

}  // namespace fx
