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

// Sums kept biased by half an lsb of the format they are read in (AngleIntegral's angle, the
// estimator's gyro bias): the floor of the biased sum is the true sum rounded half up, as
// narrow() and narrow_sat() round it, and a floor is a shift where rounding adds the dropped
// bit. In floating point the bias is 0 and a read is the plain conversion.
template <class T, class W>
constexpr W half_lsb() {
  if constexpr (fx::is_q<T>) {
    constexpr int kShift = W::frac_bits - T::frac_bits;
    static_assert(kShift >= 1 && kShift <= 31, "a biased sum is read by a right shift of 1..31");
    return W::from_raw(int64_t{1} << (kShift - 1));
  } else {
    return W{};
  }
}
// narrow<T>(sum) for the sum + half_lsb it is given: wraps as narrow() does.
template <class T, class W>
constexpr T read_biased(W biased) {
  if constexpr (fx::is_q<T>) {
    constexpr int kShift = W::frac_bits - T::frac_bits;
    return T::from_raw(fx::detail::wrap<typename T::raw_type>(biased.raw() >> kShift));
  } else {
    return fx::narrow<T>(biased);
  }
}
// narrow_sat<T>(sum) for the sum + half_lsb it is given, for a 32-bit T: the floor fits when the
// high word shifted by kShift - 1 is 0 or -1 (as in fx::narrow_sat), else it saturates by sign.
// Correct while sum + half_lsb does not wrap 64 bits, which a sum kept inside T's range cannot.
// The range check is written out here as in fx::detail::narrow_sat_words, not shared with it:
// through one helper returning the floor and its verdict, GCC 12 made the full-control tick 73
// instructions dearer (estimator, attitude and yaw rows; scripts/devboard --bench).
template <class T, class W>
constexpr T read_biased_sat(W biased) {
  if constexpr (fx::is_q<T>) {
    static_assert(sizeof(typename T::raw_type) == 4, "a 32-bit format");
    constexpr int kShift = W::frac_bits - T::frac_bits;
    const int64_t v = biased.raw();
    const int32_t high = static_cast<int32_t>(v >> 32);
    const int32_t top = high >> (kShift - 1);
    if (static_cast<uint32_t>(top) + 1u > 1u) return top < 0 ? T::min() : T::max();
    return T::from_raw(
        static_cast<int32_t>((static_cast<uint32_t>(high) << (32 - kShift)) | (static_cast<uint32_t>(v) >> kShift)));
  } else {
    return fx::narrow_sat<T>(biased);
  }
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
