// Operations the chain's blocks share, written once for every number type: Q formats, double
// and float alike. They use only what all of them have (comparison, +, -, fx::mul_wide and
// fx::narrow); what differs between them is in the number policy (fixed_numbers.hpp).
#pragma once

#include <fixedpoint/wide.hpp>

namespace qr::chain {

// a x b in Out's format, rounded once (exact in floating point).
template <class Out, class A, class B>
constexpr Out product(A a, B b) {
  return fx::narrow<Out>(fx::mul_wide(a, b));
}
// The same, clamped to Out's range for Q (floating point has no range to clamp to: callers that
// need a limit clamp to it explicitly, and the limit is well inside every Q range).
template <class Out, class A, class B>
constexpr Out product_sat(A a, B b) {
  return fx::narrow_sat<Out>(fx::mul_wide(a, b));
}

template <class T>
constexpr T clamp(T x, T lo, T hi) {
  return x < lo ? lo : hi < x ? hi : x;
}
template <class T>
constexpr T max_of(T a, T b) {
  return a < b ? b : a;
}
template <class T>
constexpr T min_of(T a, T b) {
  return b < a ? b : a;
}
template <class T>
constexpr T magnitude(T x) {
  return x < T{} ? -x : x;
}

}  // namespace qr::chain
