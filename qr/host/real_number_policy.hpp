// The number policy of the signal chain in floating point: double is the accuracy reference the
// tests hold the flight build (fixed_numbers.hpp) against, float the speed comparison. Same
// members as FixedNumbers; every quantity is the floating type, so nothing is rounded except by
// the type itself, and the design table holds the exact designs.
//
// Math supplies what the policy needs of a math library, so the policy itself stays freestanding:
//   static double ldexp(double, int);      static int32_t round_half_up(R);   (saturated)
//   static R sqrt(R);                      static R atan2(R, R);
// The host uses <cmath> (real_numbers.hpp); the RV32 float bench, which has no libm, its own.
// Outside qr/core on purpose: the flight code has no floating point, not even in templates.
#pragma once

#include <stdint.h>

namespace qr::chain {

template <class R, class Math>
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
  using Height = R;
  using Climb = R;
  using VerticalAccel = R;
  using HeightGain = R;
  using HeightStep = R;
  static constexpr int kPressureFrac = 14;  // the Q format's: raw pressures arrive scaled by it
  using Pressure = R;

  template <int Frac>
  static R fixed(int32_t raw) {
    return static_cast<R>(Math::ldexp(static_cast<double>(raw), -Frac));
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
  static int32_t round_to_int(R x) { return Math::round_half_up(x); }
  static R widen(R x) { return x; }
  static R sqrt(R x) { return x > R(0) ? Math::sqrt(x) : R(0); }
  // +0 for a zero y, as fixed point has no -0: atan2(0, x < 0) is +pi in both.
  static R atan2(R y, R x) { return Math::atan2(y == R(0) ? R(0) : y, x); }
};

}  // namespace qr::chain
