// The number policy of the signal chain in floating point, for the host: double is the accuracy
// reference the tests hold the flight build (qr/core/chain/fixed_numbers.hpp) against, float the
// speed comparison. Same members as FixedNumbers; every quantity is the floating type, so nothing
// is rounded except by the type itself, and the design table holds the exact designs.
//
// Host only (<cmath>). An RV32 float bench needs its own sqrt/atan2 (the target has no libm).
#pragma once

#include <climits>
#include <cmath>
#include <cstdint>

namespace qr::chain {

template <class R>
struct RealNumbers {
  template <int Frac>
  using Fixed = R;

  using Rate = R;
  using Accel = R;
  using Magnitude = R;
  using Angle = R;
  using Coefficient = R;
  using Scale = R;
  using CountScale = R;
  using AngleGain = R;
  using BiasGain = R;
  using BiasSum = R;
  using Thrust = R;

  template <int Frac>
  static R fixed(int32_t raw) {
    return static_cast<R>(std::ldexp(static_cast<double>(raw), -Frac));
  }
  template <class T>
  static T ratio(int32_t num, int32_t den) {
    return static_cast<T>(static_cast<double>(num) / static_cast<double>(den));
  }
  template <class To>
  static To convert(R x) {
    return x;
  }
  template <class To>
  static To convert_sat(R x) {
    return x;
  }
  // Halves up, as the Q formats round, saturated to int32.
  static int32_t round_to_int(R x) {
    const double r = std::floor(static_cast<double>(x) + 0.5);
    if (!(r > static_cast<double>(INT32_MIN))) return INT32_MIN;
    if (!(r < static_cast<double>(INT32_MAX))) return INT32_MAX;
    return static_cast<int32_t>(r);
  }
  static R widen(R x) { return x; }
  static R sqrt(R x) { return x > R(0) ? std::sqrt(x) : R(0); }
  // +0 for a zero y, as fixed point has no -0: atan2(0, x < 0) is +pi in both.
  static R atan2(R y, R x) { return std::atan2(y == R(0) ? R(0) : y, x); }
};

using DoubleNumbers = RealNumbers<double>;
using FloatNumbers = RealNumbers<float>;

}  // namespace qr::chain
