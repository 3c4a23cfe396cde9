// Operations the chain's blocks share, written once for every number type: Q formats, double
// and float alike. They use only what all of them have (comparison, +, -, fx::mul_wide and
// fx::narrow); what differs between them is in the number policy (fixed_numbers.hpp).
#pragma once

#include <fixedpoint/wide.hpp>

namespace qr::chain {

namespace detail {
// A factor as a plain register on RV32: GCC 12 lowers a widening product whose factor it tracks as
// a 64-bit value, or knows as a constant, as a 64 x 32 one (mulhu and a multiply per sign) where
// mul + mulh is the whole of it. The value is the same. Used by product_sat, whose callers (the
// angle loops, the drag feed-forward) gained by it (attitude 340 -> 325 instructions a tick), and
// at the estimator's and rate loop's products whose factor comes from a select or a narrowed sum
// (estimator 486 -> 458, attitude 333 -> 318). Not everywhere: in product it cost more than it
// saved (the sensor units' constant scales: filter 416 -> 452), and hiding a constant factor
// (dt) costs an instruction to load it where GCC would fold it.
template <class T>
constexpr T in_register(T x) {
#if defined(__riscv) && __riscv_xlen == 32
  if constexpr (fx::is_q<T>) {
    if (!__builtin_is_constant_evaluated()) {
      auto raw = x.raw();
      asm("" : "+r"(raw));
      return T::from_raw(raw);
    }
  }
#endif
  return x;
}
}  // namespace detail

// a x b in Out's format, rounded once (exact in floating point).
template <class Out, class A, class B>
constexpr Out product(A a, B b) {
  return fx::narrow<Out>(fx::mul_wide(a, b));
}
// The same, clamped to Out's range for Q (floating point has no range to clamp to: callers that
// need a limit clamp to it explicitly, and the limit is well inside every Q range).
template <class Out, class A, class B>
constexpr Out product_sat(A a, B b) {
  return fx::narrow_sat<Out>(fx::mul_wide(detail::in_register(a), detail::in_register(b)));
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
