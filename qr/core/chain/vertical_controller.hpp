// The lift when the chain flies it rather than the pilot's stick: height hold (the height at
// entry) and a panic's landing (a steady descent). Two loops on the height estimate
// (height_estimator.hpp), run at its rate:
//
//   climb set-point  w = clamp(Kh (h_ref - h), +-kMaxHoldClimb)        (height hold; a landing
//                                                                       sets w = -descent rate)
//   acceleration     u = clamp(Kv (w - v) + I, +-kMaxAccel),  I += Ki dt (w - v), |I| <= kMaxTrim
//   thrust           T = T0 (1 + u / g0)                                per engine, thrust units
//
// Thrust, not the lift stick, is what accelerates the vehicle, and the mixer takes a per-engine
// thrust (engine_mixer.hpp): so u is an acceleration in m/s² and the loop's gains do not depend on
// the vehicle. T0 is the thrust that was flying at entry (the pilot's lift in height hold, the
// safety machine's flying lift in a landing): it carries the weight from the first run, and the
// integral takes out what it gets wrong (a battery sagging, a lift that was climbing).
//
// Gains: the speed loop's poles are a double pole at 2 rad/s (Kv = 4 /s, Ki = 4 /s²), well
// below the motors' 30-50 ms lag and the height estimate's 1 s crossover is where the
// barometer takes over; the height loop (Kh = 1 /s) sits below the speed loop. docs/signal-chain.md
// has the figures they fly.
#pragma once

#include <stdint.h>

#include <qr/core/chain/numeric.hpp>

namespace qr::chain {

template <class N, uint32_t RunHz>
class VerticalController {
 public:
  using Height = typename N::Height;
  using Climb = typename N::Climb;
  using VerticalAccel = typename N::VerticalAccel;
  using Thrust = typename N::Thrust;

  static constexpr Climb kMaxHoldClimb = Climb(0.5);              // m/s: height hold's correction at most
  static constexpr VerticalAccel kMaxAccel = VerticalAccel(4.9);  // m/s², half a g either way
  static constexpr VerticalAccel kMaxTrim = VerticalAccel(2.9);   // m/s²: the integral, 30 % of the weight

  // hover: the per-engine thrust that was flying; height: where to hold (height hold).
  void start(Thrust hover, Height height) {
    hover_ = hover;
    thrust_per_accel_ = product<Thrust>(hover, kPerG0);
    held_ = height;
    integral_ = {};
    want_ = {};
    p_term_ = {};
    thrust_ = hover;
  }

  // Height hold's climb set-point for the estimated height.
  Climb climb_to_hold(Height height) const {
    return clamp(N::template convert_sat<Climb>(fx::mul_wide(kKh, held_ - height)), -kMaxHoldClimb, kMaxHoldClimb);
  }

  // One run: the per-engine thrust for the climb set-point `want` at the estimated climb. The
  // integral holds while told not to integrate (on the ground).
  Thrust update(Climb want, Climb climb, bool integrate) {
    want_ = want;
    const Climb error = want - climb;
    if (integrate) integral_ = clamp(integral_ + product<VerticalAccel>(kKiDt, error), -kMaxTrim, kMaxTrim);
    p_term_ = N::template convert_sat<VerticalAccel>(fx::mul_wide(kKv, error));
    const VerticalAccel u = clamp(p_term_ + integral_, -kMaxAccel, kMaxAccel);
    thrust_ = hover_ + product_sat<Thrust>(thrust_per_accel_, u);
    return thrust_;
  }

  Thrust thrust() const { return thrust_; }  // the last run's (the hover's before the first)
  Height held() const { return held_; }
  VerticalAccel integral() const { return integral_; }
  // The last run's climb set-point and its speed loop's proportional term, Kv (w - v) (kept for
  // a live plot).
  Climb climb_setpoint() const { return want_; }
  VerticalAccel p_term() const { return p_term_; }

 private:
  using Gain = typename N::HeightGain;  // 1/s and 1/s²
  using Scale = typename N::Scale;
  static constexpr Gain kKh = Gain(1.0);
  static constexpr Gain kKv = Gain(4.0);
  static constexpr Scale kKiDt = Scale(4.0 / RunHz);
  static constexpr Scale kPerG0 = Scale(1.0 / 9.80665);  // thrust per m/s² = T0 / g0

  Thrust hover_{}, thrust_per_accel_{}, thrust_{};
  Height held_{};
  VerticalAccel integral_{};
  Climb want_{};
  VerticalAccel p_term_{};
};

// A landing's touchdown. Both ways count only once the descent has been seen (faster than half
// the descent rate, or flown for 2 s, which covers a panic that began on or near the ground and
// never got going): before that the loop may be braking a climb, which the accelerometer feels
// as a push up.
//
// 1. The impact, every tick: the filtered specific force along body z beyond 1.3 g for 5 ms. A
//    steady descent reads 1 g (its loop's corrections are a few hundredths of a g), while the
//    ground stops the vehicle within a few milliseconds: at 0.5 m/s the simulated contact peaks
//    near 17 g, the sensor clips it at 4 g, and the 20 Hz low-pass leaves about 1.5 g for 20 ms.
// 2. The stop, on the height estimate's vertical speed: slower than a quarter of the rate for
//    0.2 s while the loop asks for the descent. Slower, because the clipped impact leaves most of
//    the stop out of the integrated accelerometer and the barometer (1 s crossover) brings the
//    estimate to rest over about a second; it covers a touchdown too soft for the first.
template <class N, uint32_t RunHz, uint32_t SampleHz>
class TouchdownDetector {
 public:
  using Climb = typename N::Climb;
  using Accel = typename N::Accel;

  static constexpr Accel kImpact = Accel(-1.3);               // g, along body z (-1 at rest)
  static constexpr uint32_t kImpactSamples = SampleHz / 200;  // 5 ms

  static constexpr uint32_t kEstablishRuns = 2 * RunHz;  // 2 s
  static constexpr uint32_t kStillRuns = RunHz / 5;      // 0.2 s

  // panic_descent_mm_s (parameter changes only; a product, not a 64-bit division: it runs in
  // the link task's tick).
  void set_descent(int32_t mm_s) {
    descent_ = product<Climb>(N::template fixed<0>(mm_s), kPerMille);
    half_ = -product<Climb>(descent_, kHalf);
    quarter_ = -product<Climb>(descent_, kQuarter);
  }
  Climb descent() const { return descent_; }

  void start() {
    runs_ = 0;
    still_ = 0;
    hits_ = 0;
    descending_ = false;
  }

  // Every tick: f_z the calibrated, filtered specific force along body z, g. True on the impact.
  bool impact(Accel f_z) {
    hits_ = descending_ && f_z < kImpact ? hits_ + 1 : 0;
    return hits_ >= kImpactSamples;
  }

  // One run; true once touched down.
  bool update(Climb climb) {
    if (runs_ < kEstablishRuns) ++runs_;
    if (climb < half_ || runs_ >= kEstablishRuns) descending_ = true;
    still_ = descending_ && quarter_ < climb ? still_ + 1 : 0;
    return still_ >= kStillRuns;
  }

 private:
  static constexpr typename N::Scale kHalf = typename N::Scale(0.5), kQuarter = typename N::Scale(0.25),
                                     kPerMille = typename N::Scale(0.001);
  Climb descent_ = Climb(0.5), half_ = Climb(-0.25), quarter_ = Climb(-0.125);
  uint32_t runs_ = 0;
  uint32_t still_ = 0;
  uint32_t hits_ = 0;
  bool descending_ = false;
};

}  // namespace qr::chain
