// Explicit conversion between Q formats. Fewer fractional bits round half up; a value the
// target cannot hold wraps (convert) or clamps (convert_sat). Gaining fractional bits is exact.
#pragma once

#include <fixedpoint/q.hpp>

namespace fx {
namespace detail {

// The value of `from` in To's fractional bits, exact or rounded, before it is fitted into To's
// storage. int64 holds it: at most 31 bits of magnitude shifted by at most 31.
template <typename To, int F, typename R>
constexpr int64_t rescaled(Q<F, R> from) {
  constexpr int shift = To::frac_bits - F;
  const int64_t raw = from.raw();
  if constexpr (shift >= 0) {
    return shl_wrap(raw, shift);
  } else {
    return round_shr(raw, -shift);
  }
}

}  // namespace detail

template <typename To, int F, typename R>
  requires is_q<To>
constexpr To convert(Q<F, R> from) {
  return To::from_raw(detail::wrap<typename To::raw_type>(detail::rescaled<To>(from)));
}

template <typename To, int F, typename R>
  requires is_q<To>
constexpr To convert_sat(Q<F, R> from) {
  return To::from_raw(detail::saturate<typename To::raw_type>(detail::rescaled<To>(from)));
}

}  // namespace fx
