// Published polynomial approximations the math functions evaluate, kept as the doubles they
// were published as; each function turns them into its own Q format at compile time (and the
// bench into float), so the numbers are written down once.
#pragma once

#include <stddef.h>
#include <fixedpoint/design_constants.hpp>
#include <fixedpoint/q.hpp>

namespace fx::detail {

using fx::kPi;

// Coefficients of c[0] + c[1] x + c[2] x^2 + ... in a polynomial of x = t^2.
template <size_t N>
struct Series {
  double c[N];
};

// Abramowitz & Stegun, Handbook of Mathematical Functions (1964), 4.4.49:
//   arctan t / t = 1 + a2 t^2 + a4 t^4 + ... + a16 t^16 + e(t),  |e| <= 2e-8 for 0 <= t <= 1.
inline constexpr Series<9> kArctanOverT{{1.0, -0.3333314528, 0.1999355085, -0.1420889944, 0.1065626393, -0.0752896400,
                                         0.0429096138, -0.0161657367, 0.0028662257}};

// Abramowitz & Stegun 4.3.97:
//   sin x / x = 1 + a2 x^2 + a4 x^4 + ... + a10 x^10 + e(x),  |e| <= 2e-9 for 0 <= x <= pi/2.
inline constexpr Series<6> kSineOverX{{1.0, -0.1666666664, 0.0083333315, -0.0001984090, 0.0000027526, -0.0000000239}};

// 4.3.97 with x = pi/2 u: sin(pi/2 u) / u as a polynomial of u^2 on 0 <= u <= 1, whose
// coefficients are a_2k (pi/2)^(2k+1). Working in quarter turns means the reduced angle never
// has to be multiplied by pi/2 at run time.
consteval Series<6> quarter_sine_over_u() {
  Series<6> s{};
  double scale = kPi / 2;
  for (size_t k = 0; k < 6; ++k) {
    s.c[k] = kSineOverX.c[k] * scale;
    scale *= (kPi / 2) * (kPi / 2);
  }
  return s;
}

template <int Frac, size_t N>
struct QSeries {
  Q<Frac> c[N];
};

template <int Frac, size_t N>
consteval QSeries<Frac, N> to_q(const Series<N>& s) {
  QSeries<Frac, N> q{};
  for (size_t k = 0; k < N; ++k) q.c[k] = Q<Frac>(s.c[k]);
  return q;
}

}  // namespace fx::detail
