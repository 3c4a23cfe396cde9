// One step of a 1st- or 2nd-order IIR filter in direct form I, generic over the signal type T
// and the coefficient type C: Q formats in flight (e.g. T = Q<16>, C = Q<30>), double for the
// host reference, float for the target's speed comparison. Written once, for all three.
//
// Direct form I because its state holds past inputs and outputs in the signal's own format:
// the only rounding is the one narrow() per step, and intermediate sums live in the wide
// accumulator, so there is no internal node to overflow (unlike direct form II).
//
// The coefficients are the caller's (the filter design lives elsewhere). a0 is normalised to
// 1; note the minus signs on the a terms, as in the usual transfer function
//   H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2).
// A coefficient set that is a compile-time constant lets the compiler keep the coefficients
// as immediates; the state is one small struct, loaded and stored once per step.
#pragma once

#include <fixedpoint/wide.hpp>

namespace fx {

template <typename C>
struct Iir1Coefficients {
  C b0, b1, a1;
};

template <typename T>
struct Iir1State {
  T x1{}, y1{};
};

template <typename C>
struct Iir2Coefficients {
  C b0, b1, b2, a1, a2;
};

template <typename T>
struct Iir2State {
  T x1{}, x2{}, y1{}, y2{};
};

// y = b0 x + b1 x1 - a1 y1
template <typename T, typename C>
constexpr T iir1_step(Iir1State<T>& s, const Iir1Coefficients<C>& c, T x) {
  const T y = narrow<T>(mul_wide(c.b0, x) + mul_wide(c.b1, s.x1) - mul_wide(c.a1, s.y1));
  s.x1 = x;
  s.y1 = y;
  return y;
}

// y = b0 x + b1 x1 + b2 x2 - a1 y1 - a2 y2
template <typename T, typename C>
constexpr T iir2_step(Iir2State<T>& s, const Iir2Coefficients<C>& c, T x) {
  const T y = narrow<T>(mul_wide(c.b0, x) + mul_wide(c.b1, s.x1) + mul_wide(c.b2, s.x2) - mul_wide(c.a1, s.y1) -
                        mul_wide(c.a2, s.y2));
  s.x2 = s.x1;
  s.x1 = x;
  s.y2 = s.y1;
  s.y1 = y;
  return y;
}

}  // namespace fx
