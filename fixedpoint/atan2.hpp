// Four-quadrant arctangent of y / x in rad, e.g. for the tilt of the accelerometer vector.
// Inputs are any Q format (only their ratio matters); the result is in Out, by default Q<29>,
// which holds [-pi, pi] with 1.9e-9 rad resolution.
//
// Max error 1.7e-8 rad with the default Q<29> result: the largest error against long double
// measured over sweeps of 2.5e7 samples was 1.67e-8 to 1.69e-8 (seed to seed), rounded up;
// tests/fixedpoint/atan2_test.cpp asserts it. Budget: A&S 4.4.49 itself 1.4e-8 (the book
// states 2e-8), the ratio truncated to Q<30> and Horner rounding ~3e-9. A coarser Out adds
// half its lsb.
// atan2(0, 0) is 0; atan2(0, x < 0) is +pi (fixed point has no -0).
#pragma once

#include <fixedpoint/convert.hpp>
#include <fixedpoint/detail/divide.hpp>
#include <fixedpoint/detail/horner.hpp>
#include <fixedpoint/detail/raw.hpp>
#include <fixedpoint/detail/series.hpp>
#include <fixedpoint/q.hpp>

namespace fx {
namespace detail {

inline constexpr auto kArctan = to_q<30>(kArctanOverT);

// arctan(t) for t in [0, 1], Q<30> in and out.
constexpr Q<30> arctan_unit(Q<30> t) { return t * horner(kArctan.c, t * t); }

}  // namespace detail

template <typename Out = Q<29>, int F, typename R>
  requires is_q<Out>
constexpr Out atan2(Q<F, R> y, Q<F, R> x) {
  static_assert(Out::int_bits >= 2, "atan2: Out must hold pi");
  const uint32_t ax = detail::magnitude<uint32_t>(static_cast<int32_t>(x.raw()));
  const uint32_t ay = detail::magnitude<uint32_t>(static_cast<int32_t>(y.raw()));
  if (ax == 0 && ay == 0) return Out{};

  // Fold into the first octant: t = small / large in [0, 1], truncated to Q<30>. The dividend's
  // high word, small >> 2, is below large, so the quotient fits 32 bits and RV32IM's 32-bit
  // divisions make it (detail/divide.hpp), not libgcc's 64-bit one.
  const bool steep = ay > ax;
  const uint32_t small = steep ? ax : ay;
  const uint32_t large = steep ? ay : ax;
  const Q<30> t = Q<30>::from_raw(
      static_cast<int32_t>(detail::divide_below(static_cast<uint64_t>(small) << 30, large).quotient));

  // Unfold, on magnitudes in Q<30> as uint32: pi * 2^30 still fits 32 bits unsigned.
  constexpr uint32_t kHalfPi = static_cast<uint32_t>(Q<30>(detail::kPi / 2).raw());
  constexpr uint32_t kPiRaw = 3373259426u;  // round(pi * 2^30); Q<30> cannot hold it signed
  uint32_t angle = static_cast<uint32_t>(detail::arctan_unit(t).raw());
  if (steep) angle = kHalfPi - angle;
  if (x.raw() < 0) angle = kPiRaw - angle;

  // To Out: round half up on the magnitude, then the sign of y.
  constexpr int kDrop = 30 - Out::frac_bits;
  const uint32_t rounded = (angle >> kDrop) + ((angle >> (kDrop - 1)) & 1u);
  const auto out = static_cast<typename Out::raw_type>(rounded);
  return Out::from_raw(y.raw() < 0 ? static_cast<typename Out::raw_type>(-out) : out);
}

}  // namespace fx
