// Sine and cosine of an angle in rad, in any Q format and of any size; the result in Out,
// by default Q<30>.
//
// Max error 5.6e-9 with the default Q<30> result, for any input format and value: the largest
// error against long double measured over 5e7 samples was 5.51e-9 (where |sin| is near 1),
// rounded up; tests/fixedpoint/sincos_test.cpp asserts it. Budget: A&S 4.3.97 itself 2.3e-9,
// coefficient and Horner rounding ~3 lsb of Q<30> (2.8e-9), range reduction < 1.5e-9 (one
// unit of 2^-32 turn, which matters where the slope is large, i.e. not where the other two
// peak). A coarser Out adds half its lsb. cos(0) is 1 - 3 lsb, the polynomial's own error.
#pragma once

#include <fixedpoint/convert.hpp>
#include <fixedpoint/detail/horner.hpp>
#include <fixedpoint/detail/series.hpp>
#include <fixedpoint/q.hpp>

namespace fx {
namespace detail {

// Angle -> fraction of a turn in 32 bits (2^32 = one turn), so that wrapping is the reduction
// modulo 2 pi. With x = raw / 2^F the turn count is raw * c, c = 2^(32-F) / (2 pi) in units of
// 2^-32 turn. c's integer part times raw is exact modulo 2^32; its 32-bit fraction times raw
// is rounded. 2^64 / (2 pi) is carried as an integer because a double's 53 bits are too few
// for c with F = 0. Error < 1 unit (0.5 from c, 0.5 from rounding) = 1.5e-9 rad.
inline constexpr uint64_t kTurnsPerRadQ64 = 0x28BE60DB9391054Aull;  // round(2^64 / (2 pi))

template <int F>
constexpr uint32_t turns(int32_t raw) {
  constexpr uint64_t c = kTurnsPerRadQ64 >> F;
  constexpr uint32_t c_int = static_cast<uint32_t>(c >> 32);
  constexpr int64_t c_frac = static_cast<int64_t>(c & 0xFFFFFFFFu);
  const uint32_t whole = static_cast<uint32_t>(raw) * c_int;
  const uint32_t part = static_cast<uint32_t>(round_shr(raw * c_frac, 32));
  return whole + part;
}

inline constexpr auto kQuarterSine = to_q<30>(quarter_sine_over_u());

// sin(2 pi turn / 2^32) in Q<30>: the quadrant from the top two bits, the polynomial on the
// rest (mirrored in the 2nd and 4th quadrants, negated in the 3rd and 4th).
constexpr Q<30> sin_of_turns(uint32_t turn) {
  constexpr uint32_t kQuarter = 1u << 30;
  const uint32_t quadrant = turn >> 30;
  const uint32_t within = turn & (kQuarter - 1);
  const Q<30> u = Q<30>::from_raw(static_cast<int32_t>((quadrant & 1) ? kQuarter - within : within));
  const Q<30> s = u * horner(kQuarterSine.c, u * u);
  return quadrant >= 2 ? -s : s;
}

}  // namespace detail

template <typename Out = Q<30>, int F, typename R>
  requires is_q<Out>
constexpr Out sin(Q<F, R> angle) {
  static_assert(Out::int_bits >= 1, "sin: Out must hold 1");
  return convert<Out>(detail::sin_of_turns(detail::turns<F>(angle.raw())));
}

template <typename Out = Q<30>, int F, typename R>
  requires is_q<Out>
constexpr Out cos(Q<F, R> angle) {
  static_assert(Out::int_bits >= 1, "cos: Out must hold 1");
  return convert<Out>(detail::sin_of_turns(detail::turns<F>(angle.raw()) + (1u << 30)));
}

}  // namespace fx
