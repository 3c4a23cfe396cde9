// Polynomial evaluation in one Q format, by Horner's rule. Each step is one rounded multiply
// (half an lsb of error) and one exact add, so N coefficients add at most about N/2 lsb of
// rounding error to the approximation error of the polynomial itself.
#pragma once

#include <stddef.h>

namespace fx::detail {

// c[0] + c[1] x + ... + c[N-1] x^(N-1)
template <typename T, size_t N>
constexpr T horner(const T (&c)[N], T x) {
  T p = c[N - 1];
  for (size_t i = N - 1; i > 0; --i) p = p * x + c[i - 1];
  return p;
}

}  // namespace fx::detail
