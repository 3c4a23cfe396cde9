// Wide accumulators for signal chains: the exact product of two Q numbers of any formats, sums
// of such products without rounding in between, and one rounding back at the end.
//
//   y = narrow<Q<16>>(mul_wide(b0, x) + mul_wide(b1, x1) - mul_wide(a1, y1));
//
// The same three names exist for double and float, where they are plain arithmetic, so signal
// code written once over a number type T runs in Q on the target, in double as the host's
// accuracy reference and in float as the target's speed comparison.
#pragma once

#include <fixedpoint/detail/raw.hpp>
#include <fixedpoint/q.hpp>

namespace fx {

// raw / 2^Frac in 64 bits. Sums wrap modulo 2^64. A product of two int32 raws needs up to 63
// bits, so only sums of products whose factors are both near full scale can overflow; and
// even then narrow() is right whenever its result fits, since the bits it keeps survive
// wrapping. narrow_sat() needs the true sum.
template <int Frac>
class Wide {
  static_assert(Frac >= 0 && Frac < 64, "Wide<Frac>: 0 <= Frac < 64");

 public:
  static constexpr int frac_bits = Frac;

  constexpr Wide() = default;
  static constexpr Wide from_raw(int64_t raw) {
    Wide w;
    w.raw_ = raw;
    return w;
  }
  constexpr int64_t raw() const { return raw_; }
  constexpr double to_double() const { return static_cast<double>(raw_) * detail::pow2(-Frac); }

  friend constexpr Wide operator+(Wide a, Wide b) { return from_raw(static_cast<int64_t>(u(a) + u(b))); }
  friend constexpr Wide operator-(Wide a, Wide b) { return from_raw(static_cast<int64_t>(u(a) - u(b))); }
  friend constexpr Wide operator-(Wide a) { return from_raw(static_cast<int64_t>(uint64_t{0} - u(a))); }
  friend constexpr Wide& operator+=(Wide& a, Wide b) { return a = a + b; }
  friend constexpr Wide& operator-=(Wide& a, Wide b) { return a = a - b; }
  friend constexpr bool operator==(Wide a, Wide b) { return a.raw_ == b.raw_; }

 private:
  static constexpr uint64_t u(Wide a) { return static_cast<uint64_t>(a.raw_); }
  int64_t raw_ = 0;
};

// Exact: the product's fractional bits are the sum of the factors'.
template <int Fa, typename Ra, int Fb, typename Rb>
constexpr Wide<Fa + Fb> mul_wide(Q<Fa, Ra> a, Q<Fb, Rb> b) {
  if constexpr (detail::RawTraits<Ra>::bits + detail::RawTraits<Rb>::bits <= 32) {
    // Two int16s: one 32-bit multiply instead of a 64-bit one.
    return Wide<Fa + Fb>::from_raw(static_cast<int32_t>(a.raw()) * b.raw());
  } else {
    return Wide<Fa + Fb>::from_raw(static_cast<int64_t>(a.raw()) * b.raw());
  }
}

namespace detail {

template <typename To, int G>
constexpr int64_t rescaled(Wide<G> from) {
  constexpr int shift = To::frac_bits - G;
  if constexpr (shift >= 0) {
    return shl_wrap(from.raw(), shift);
  } else {
    return round_shr(from.raw(), -shift);
  }
}

// round_shr(v, Shift) saturated to int32, worked on v's two words: the same value as the 64-bit
// shift, add and range check, in about 10 RV32 instructions where those take 14. The floor
// v >> Shift fits int32 exactly when v >> (31 + Shift), the high word shifted by Shift - 1, is 0
// or -1; otherwise it saturates by its sign. The rounding bit then moves a floor that fits out of
// range only from INT32_MAX up (a positive floor plus one), which the signed compare catches.
template <typename To, int Shift>
constexpr To narrow_sat_words(int64_t v) {
  const int32_t high = static_cast<int32_t>(v >> 32);
  const uint32_t low = static_cast<uint32_t>(v);
  const int32_t top = high >> (Shift - 1);
  if (static_cast<uint32_t>(top) + 1u > 1u) return top < 0 ? To::min() : To::max();
  const uint32_t floor = (static_cast<uint32_t>(high) << (32 - Shift)) | (low >> Shift);
  const int32_t rounded = static_cast<int32_t>(floor + ((low >> (Shift - 1)) & 1u));
  return rounded < static_cast<int32_t>(floor) ? To::max() : To::from_raw(rounded);
}

}  // namespace detail

// Back to a Q format, rounding half up; wraps (narrow) or clamps (narrow_sat) when it does not
// fit. The filters use narrow: a filter sized for its signal has headroom, and saturating would
// cost a 64-bit range check on every tick.
template <typename To, int G>
  requires is_q<To>
constexpr To narrow(Wide<G> w) { return To::from_raw(detail::wrap<typename To::raw_type>(detail::rescaled<To>(w))); }

template <typename To, int G>
  requires is_q<To>
constexpr To narrow_sat(Wide<G> w) {
  constexpr int shift = G - To::frac_bits;
  if constexpr (sizeof(typename To::raw_type) == 4 && shift >= 1 && shift <= 31) {
    return detail::narrow_sat_words<To, shift>(w.raw());
  } else {
    return To::from_raw(detail::saturate<typename To::raw_type>(detail::rescaled<To>(w)));
  }
}

// ---- the same vocabulary for the floating-point number types ----
constexpr double mul_wide(double a, double b) { return a * b; }
constexpr float mul_wide(float a, float b) { return a * b; }

template <typename To>
  requires detail::is_same<To, double>
constexpr double narrow(double w) { return w; }
template <typename To>
  requires detail::is_same<To, float>
constexpr float narrow(float w) { return w; }
template <typename To>
  requires detail::is_same<To, double>
constexpr double narrow_sat(double w) { return w; }
template <typename To>
  requires detail::is_same<To, float>
constexpr float narrow_sat(float w) { return w; }

}  // namespace fx
