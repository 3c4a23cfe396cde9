// The float side's sqrt, atan2 and sin: the target links no libm, so these are the same
// algorithms as the Q versions (same published polynomials, same folding), evaluated in float.
// They exist to be measured against, not to be used.
#pragma once

#include <stddef.h>
#include <stdint.h>
#include <fixedpoint/detail/horner.hpp>
#include <fixedpoint/detail/series.hpp>

namespace bench::flt {

template <size_t N>
struct FloatSeries {
  float c[N];
};

template <size_t N>
constexpr FloatSeries<N> to_float(const fx::detail::Series<N>& s) {
  FloatSeries<N> f{};
  for (size_t k = 0; k < N; ++k) f.c[k] = static_cast<float>(s.c[k]);
  return f;
}

inline constexpr auto kArctan = to_float(fx::detail::kArctanOverT);
inline constexpr auto kQuarterSine = to_float(fx::detail::quarter_sine_over_u());
inline constexpr float kPi = static_cast<float>(fx::detail::kPi);
inline constexpr float kTurnsPerRad = static_cast<float>(1 / (2 * fx::detail::kPi));

// A first guess from halving the exponent field, then three Newton steps y = (y + x / y) / 2:
// the guess is within 6 %, so three steps reach float precision.
inline float sqrt(float x) {
  if (!(x > 0.0f)) return 0.0f;
  const uint32_t bits = __builtin_bit_cast(uint32_t, x);
  float y = __builtin_bit_cast(float, (bits >> 1) + (127u << 22));
  for (int i = 0; i < 3; ++i) y = 0.5f * (y + x / y);
  return y;
}

inline float atan2(float y, float x) {
  const float ax = x < 0.0f ? -x : x;
  const float ay = y < 0.0f ? -y : y;
  if (ax == 0.0f && ay == 0.0f) return 0.0f;
  const bool steep = ay > ax;
  const float t = steep ? ax / ay : ay / ax;
  float angle = t * fx::detail::horner(kArctan.c, t * t);
  if (steep) angle = kPi / 2 - angle;
  if (x < 0.0f) angle = kPi - angle;
  return y < 0.0f ? -angle : angle;
}

inline float sin(float x) {
  float turn = x * kTurnsPerRad;
  turn -= static_cast<float>(static_cast<int32_t>(turn));
  if (turn < 0.0f) turn += 1.0f;
  const float quarters = turn * 4.0f;
  const int32_t quadrant = static_cast<int32_t>(quarters);
  float u = quarters - static_cast<float>(quadrant);
  if ((quadrant & 1) != 0) u = 1.0f - u;
  const float s = u * fx::detail::horner(kQuarterSine.c, u * u);
  return quadrant >= 2 ? -s : s;
}

}  // namespace bench::flt
