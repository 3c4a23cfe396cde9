// The number policy of the flight build: which Q format each quantity of the signal chain uses,
// and the few operations that differ between Q formats and floating point. The chain's blocks are
// templates over a policy N and never name a format themselves. The floating-point policies
// (qr/host/real_number_policy.hpp) provide the same members; they are kept out of qr/core so
// the freestanding code never sees floating point.
//
// Why a policy with static members rather than free functions found by argument-dependent
// lookup: double and float have no associated namespace, so an unqualified sqrt(x) in a template
// could only find a double overload declared before the template, i.e. inside qr/core.
//
// Formats (lsb, range): docs/signal-chain.md has the reasoning and the measured errors.
#pragma once

#include <stdint.h>

#include <fixedpoint/fixedpoint.hpp>

namespace qr::chain {

struct FixedNumbers {
  // A number with Frac fractional bits: parameters and counts come in as such raw integers.
  template <int Frac>
  using Fixed = fx::Q<Frac>;

  using Rate = fx::Q<27>;         // rad/s; +-16, lsb 7.5e-9 (gyro full scale 8.7 rad/s)
  using Accel = fx::Q<27>;        // g (specific force); +-16, lsb 7.5e-9 (full scale 4 g)
  using Magnitude = fx::Q<24>;    // g, for sqrt(fy^2 + fz^2) (up to 5.7 g); +-128
  using Angle = fx::Q<28>;        // rad; +-8, so the difference of two angles in [-pi, pi) fits
  using Coefficient = fx::Q<30>;  // filter coefficients; +-2 (a1 of a 2nd-order low-pass is near -2)
  using Scale = fx::Q<31>;        // constants below 1: rad/s per count, dt, per-mille factors
  using CountScale = fx::Q<17>;   // counts per unit (3752.9 per rad/s, 8192 per g); +-16384
  using AngleGain = fx::Q<30>;    // 1 / C1, in [1/65535, 1]
  using BiasGain = fx::Q<24>;     // fs / C2 in 1/s; up to 128
  using BiasSum = fx::Wide<52>;   // gyro bias accumulator: Angle x BiasGain, exact, +-2048 rad/s
  using Thrust = fx::Q<16>;       // thrust units (1000 = one engine at full speed); +-32768
  // Height estimate (height_estimator.hpp)
  using Height = fx::Q<16>;         // m; +-32768, lsb 1.5e-5
  using Climb = fx::Q<24>;          // m/s; +-128, lsb 6e-8
  using VerticalAccel = fx::Q<24>;  // m/s²; +-128 (the accelerometer's 4 g per axis is 39)
  using HeightGain = fx::Q<27>;     // 3/tau (1/s) and 3/tau² (1/s²); +-16
  using HeightStep = fx::Q<24>;     // the run's time step, s: speed x step and height x step add in Wide<48>
  static constexpr int kPressureFrac = 14;
  using Pressure = fx::Q<kPressureFrac>;  // Pa; +-131072 (the MS5611 reads up to 120000), lsb 6e-5

  template <int Frac>
  static constexpr fx::Q<Frac> fixed(int32_t raw) {
    return fx::Q<Frac>::from_raw(raw);
  }

  // num / den rounded half up, saturated to T. A 64-bit division: for parameter changes only.
  template <class T>
  static constexpr T ratio(int32_t num, int32_t den) {
    constexpr int F = T::frac_bits;
    const bool negative = (num < 0) != (den < 0);
    const uint64_t n = static_cast<uint64_t>(num < 0 ? -static_cast<int64_t>(num) : num) << F;
    const uint64_t d = static_cast<uint64_t>(den < 0 ? -static_cast<int64_t>(den) : den);
    if (d == 0) return num > 0 ? T::max() : num < 0 ? T::min() : T{};
    const uint64_t q = (2 * n + d) / (2 * d);  // |num| < 2^31 and F < 32: 2n < 2^64
    const uint64_t limit = static_cast<uint64_t>(INT32_MAX);
    if (negative) return q > limit + 1 ? T::min() : T::from_raw(static_cast<int32_t>(-static_cast<int64_t>(q)));
    return q > limit ? T::max() : T::from_raw(static_cast<int32_t>(q));
  }

  // Between formats, rounding half up; a value that does not fit wraps (convert) or clamps
  // (convert_sat). From a Wide accumulator this is fx::narrow / fx::narrow_sat.
  template <class To, int F, class R>
  static constexpr To convert(fx::Q<F, R> x) {
    return fx::convert<To>(x);
  }
  template <class To, int F>
  static constexpr To convert(fx::Wide<F> x) {
    return fx::narrow<To>(x);
  }
  template <class To, int F, class R>
  static constexpr To convert_sat(fx::Q<F, R> x) {
    return fx::convert_sat<To>(x);
  }
  template <class To, int F>
  static constexpr To convert_sat(fx::Wide<F> x) {
    return fx::narrow_sat<To>(x);
  }

  // Nearest integer, halves up, saturated to int32.
  template <int F, class R>
  static constexpr int32_t round_to_int(fx::Q<F, R> x) {
    return x.to_int();
  }
  template <int F>
  static constexpr int32_t round_to_int(fx::Wide<F> x) {
    return fx::narrow_sat<fx::Q<0>>(x).raw();
  }

  static constexpr BiasSum widen(Rate x) { return fx::mul_wide(x, fx::Q<25>(1.0)); }

  template <class T>
  static constexpr T sqrt(T x) {
    return fx::sqrt(x);  // correctly rounded; 0 for x <= 0
  }
  template <class T>
  static constexpr Angle atan2(T y, T x) {
    return fx::atan2<Angle>(y, x);  // within 1.7e-8 rad + half an lsb of Angle
  }
};

}  // namespace qr::chain
