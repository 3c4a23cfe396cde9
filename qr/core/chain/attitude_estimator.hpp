// Roll and pitch from the gyro and the accelerometer, the IN4073 report's "Kalman" filter (a
// complementary filter with gyro bias estimation), per axis and per control period:
//
//   rate  = gyro - bias                       gyro rate, bias-corrected
//   angle = angle + (rate + coupling) dt      predict by integrating the Euler rate
//   e     = angle - accel_angle               disagreement with the accelerometer's angle
//   angle = angle - e / C1                    pull toward the accelerometer angle
//   bias  = bias + e / (C2 dt)                a drifting-ahead angle means the gyro reads high
//                                             (less while the body yaws: see update())
//
// Signs: with a gyro that reads high (bias > 0 in truth), the integrated angle runs ahead of the
// accelerometer's, e > 0, and the bias estimate grows toward the truth; rate = gyro - bias then
// drops. Dynamics: s^2 + s / (C1 dt) + 1 / (C2 dt^2), damping sqrt(C2) / (2 C1); the angle follows
// the accelerometer with time constant C1 samples. The defaults (C1 = 8000, C2 = 4 C1^2) are
// critically damped and slow on purpose: in free flight a multirotor's accelerometer reads the
// tilt only through a lag of seconds (docs/signal-chain.md).
//
// Fixed point: the divisions become multiplications by 1 / C1 and fs / C2, computed when a
// parameter changes. The angle accumulates in a 64-bit Wide (AngleIntegral below), and the bias
// in a 64-bit Wide with 52 fractional bits, both exactly:
// every product e x fs / C2 adds in without rounding, so a bias error too small to show in the
// rate format still moves the accumulator (with the report's rate-format bias, e / C2 would round
// to zero below about 0.05 gyro counts of error and the bias would stop converging there).
//
// Accelerometer angles (docs/conventions.md): roll = atan2(-f_y, -f_z),
// pitch = atan2(f_x, sqrt(f_y^2 + f_z^2)). Yaw has no absolute reference: it integrates r.
// The angle update turns body rates into Euler rates (AttitudeEstimator::update), so that a yaw
// turn while tilted is not read as a roll or pitch rate for the seconds C1 takes to undo it.
#pragma once

#include <stdint.h>

#include <qr/core/chain/angles.hpp>
#include <qr/core/chain/numeric.hpp>

namespace qr::chain {

// An angle kept as the exact sum of its increments. rate x dt is 2e-9 rad per step for a rate of
// 2e-6 rad/s, about half an lsb of the Angle format: summed in Angle, each step would round to 0
// or 1 lsb, and a small rate (a small bias error) would be integrated wrongly or not at all. The
// sum is a Wide in the products' own format (rate x dt and angle x 1/C1 are both Angle x Q<30>
// for FixedNumbers: Wide<58>, +-32 rad), so every increment adds in exactly; the angle is read
// from it rounded once. Wrapped into [-pi, pi) after every change. In the Q formats the sum is
// kept biased by half an Angle lsb: rounding the true sum half up is then the floor of the biased
// one, a shift where narrow() also adds the rounding bit (three RV32 instructions fewer per read,
// seven reads a tick; the same angles).
template <class N>
class AngleIntegral {
 public:
  using Angle = typename N::Angle;
  using Sum = decltype(fx::mul_wide(typename N::Angle{}, typename N::AngleGain{}));
  static_assert(fx::detail::is_same<Sum, decltype(fx::mul_wide(typename N::Rate{}, typename N::Scale{}))>,
                "rate x dt and angle x gain must add in the same wide format");

  void set(Angle a) {
    sum_ = fx::mul_wide(a, kOne) + kHalfLsb;
    angle_ = a;
  }
  void add(Sum delta) {
    sum_ += delta;
    normalise(read(sum_));
  }
  // The same, for a caller that has just read peek(delta): the angle is that value, not read again.
  void add(Sum delta, Angle peeked) {
    sum_ += delta;
    normalise(peeked);
  }
  // The angle the sum would read with delta added, not wrapped (Angle holds +-8 rad, so a value
  // just past +-pi is still right; callers wrap differences).
  Angle peek(Sum delta) const { return read(sum_ + delta); }
  Angle angle() const { return angle_; }

 private:
  static constexpr typename N::AngleGain kOne = typename N::AngleGain(1.0);

  // Half an Angle lsb in the sum's units (numeric.hpp; 0 in floating point), and the angle of a
  // biased sum: its floor, which is the true sum rounded half up as N::convert rounds it.
  static constexpr Sum kHalfLsb = half_lsb<Angle, Sum>();
  static Angle read(Sum biased) { return read_biased<Angle>(biased); }

  void normalise(Angle angle) {
    angle_ = angle;
    if (!(angle_ < kPiAngle<Angle>)) {
      sum_ -= fx::mul_wide(kTwoPiAngle<Angle>, kOne);
      angle_ = read(sum_);
    } else if (angle_ < -kPiAngle<Angle>) {
      sum_ += fx::mul_wide(kTwoPiAngle<Angle>, kOne);
      angle_ = read(sum_);
    }
  }

  Sum sum_{};
  Angle angle_{};
};

// One tilt axis (roll or pitch): angle and gyro bias.
template <class N, uint32_t SampleHz>
class TiltEstimator {
 public:
  using Rate = typename N::Rate;
  using Angle = typename N::Angle;

  // Beyond this the bias is clamped (and its accumulator with it): a gyro offset left after
  // calibration is far smaller, and the clamp keeps a broken sensor from overflowing the sum.
  static constexpr Rate kMaxBias = Rate(0.5);

  void set_gain(typename N::AngleGain k1) { k1_ = k1; }
  // Starts from this angle (e.g. the accelerometer's) with no bias.
  void start(Angle angle) {
    angle_.set(angle);
    expected_.set(angle);
    bias_sum_ = kBiasHalf;
    bias_ = {};
  }

  // follow: the share of the gap between the tilt and the accelerometer's expected angle that
  // closes per sample, dt / lag (1: no lag).
  void set_follow(typename N::AngleGain follow) { follow_ = follow; }

  // gyro: the axis' body rate; coupling: what the other axes add to this angle's rate (Euler
  // kinematics, AttitudeEstimator::update), already bias-corrected; cross: what the yaw rate
  // turns into this axis' expected accelerometer angle from the other's (the body's velocity
  // turning with it), already x dt (1 - follow). bias_gain: fs / C2 while the body holds its
  // heading, less in a turn (AttitudeEstimator::update says why).
  void update(Rate gyro, Rate coupling, typename AngleIntegral<N>::Sum cross, Angle accel_angle, bool no_lag,
              typename N::BiasGain bias_gain) {
    rate_ = gyro - bias_;
    // in_register (numeric.hpp): these factors come from a select, a narrowed sum or a difference
    // GCC tracks in 64 bits, and would cost a 64 x 32 product each.
    const auto predict = fx::mul_wide(detail::in_register(rate_), kDt) +
                         fx::mul_wide(detail::in_register(coupling), kDt);
    // The angle the accelerometer should show: the predicted tilt seen through the drag's lag.
    // With follow = 1 (no lag) it is the predicted angle itself, and this is the plain
    // complementary filter.
    const auto expect = fx::mul_wide(detail::in_register(wrap_angle(angle_.peek(predict) - expected_.angle())),
                                     detail::in_register(no_lag ? kNoLag : follow_)) +
                        cross;
    const Angle expected_angle = expected_.peek(expect);
    const Angle e = wrap_angle(expected_angle - accel_angle);
    angle_.add(predict - fx::mul_wide(e, k1_));  // predict and correct, wrapped once
    expected_.add(expect, expected_angle);
    bias_sum_ += fx::mul_wide(detail::in_register(e), detail::in_register(bias_gain));
    bias_ = read_biased_sat<Rate>(bias_sum_);
    if (kMaxBias < bias_) {
      bias_ = kMaxBias;
      bias_sum_ = N::widen(kMaxBias) + kBiasHalf;
    } else if (bias_ < -kMaxBias) {
      bias_ = -kMaxBias;
      bias_sum_ = N::widen(-kMaxBias) + kBiasHalf;
    }
  }

  // A turn the gyro did not see (ClipBridge, gyro_clip.hpp): the angle moves, the accelerometer's
  // expected angle follows it through the drag's lag as it does every turn.
  void turn(Angle missed) { angle_.add(fx::mul_wide(missed, kOne)); }

  // The accelerometer angle the model expects now (for the other axis' cross term, the logs).
  Angle expected() const { return expected_.angle(); }
  Angle angle() const { return angle_.angle(); }
  Rate rate() const { return rate_; }
  Rate bias() const { return bias_; }

 private:
  static constexpr typename N::Scale kDt = typename N::Scale(1.0 / SampleHz);
  using BiasSum = typename N::BiasSum;
  // The bias sum is kept biased by half a Rate lsb (numeric.hpp, read_biased_sat): the bias it
  // reads is its floor, a shift without the rounding bit.
  static constexpr BiasSum kBiasHalf = half_lsb<Rate, BiasSum>();

  static constexpr typename N::AngleGain kOne = typename N::AngleGain(1.0);
  typename N::AngleGain k1_{};
  static constexpr typename N::AngleGain kNoLag = typename N::AngleGain(1.0);
  typename N::AngleGain follow_ = kNoLag;  // dt / lag, at most 1
  AngleIntegral<N> angle_;
  AngleIntegral<N> expected_;  // the accelerometer's expected angle
  Rate rate_{};
  Rate bias_{};
  BiasSum bias_sum_ = kBiasHalf;
};

// Two steps: update_accel() takes the accelerometer's angles (two atan2 and a square root) and
// may run at a fraction of the rate (the flight's task table runs it at 250 Hz: flight_chain.hpp
// says why that is enough); update() integrates the gyro every tick and corrects towards the
// angles last taken. A (re)start takes fresh angles itself, whatever tick it falls on.
template <class N, uint32_t SampleHz>
class AttitudeEstimator {
 public:
  using Rate = typename N::Rate;
  using Accel = typename N::Accel;
  using Angle = typename N::Angle;
  using Magnitude = typename N::Magnitude;

  // c1, c2 in samples (parameter table). Two divisions, at parameter changes only.
  void set_divisors(int32_t c1, int32_t c2) {
    const auto k1 = N::template ratio<typename N::AngleGain>(1, c1);
    roll_.set_gain(k1);
    pitch_.set_gain(k1);
    k2_ = N::template ratio<typename N::BiasGain>(static_cast<int32_t>(SampleHz), c2);
    c1_dt_ = N::template ratio<Seconds>(c1, static_cast<int32_t>(SampleHz));
    spin_limit_ = N::template ratio<Rate>(static_cast<int32_t>(SampleHz), c1);  // a radian in C1 samples
  }

  // lag_ms: the time constant with which the accelerometer's angle follows a change of tilt in
  // free flight (the rotors' drag: 1 / mu, docs/signal-chain.md); 0 for none (a vehicle on a
  // stand, whose accelerometer sees gravity at once). One division, at parameter changes only.
  void set_lag(int32_t lag_ms) {
    const int64_t samples_x1000 = static_cast<int64_t>(lag_ms) * SampleHz;  // lag in samples, x 1000
    const auto follow = samples_x1000 <= 1000
                            ? kNoLag
                            : N::template ratio<typename N::AngleGain>(
                                  1000, static_cast<int32_t>(samples_x1000 < INT32_MAX ? samples_x1000 : INT32_MAX));
    roll_.set_follow(follow);
    pitch_.set_follow(follow);
    cross_dt_ = product<typename N::Scale>(kDt, kNoLag - follow);
  }

  // The next update starts over from the accelerometer's angles, with no bias and yaw 0.
  void restart() { started_ = false; }

  // The slow step: calibrated, filtered specific force (g), x y z -> the accelerometer's angles,
  // and the Euler factors refreshed from the current attitude.
  void update_accel(const Accel (&accel)[3]) {
    take_accel_angles(accel);
    if (started_) euler_ = euler_terms(roll_.angle(), pitch_.angle());
  }

  // Every tick: calibrated, filtered body rates (rad/s); the specific force is used only to
  // (re)start from the accelerometer's angles. on_ground: the vehicle cannot move (the landed
  // detector), so its accelerometer sees gravity at once: no lag, whatever set_lag() said.
  void update(const Rate (&rate)[3], const Accel (&accel)[3], bool on_ground = false) {
    if (!started_) start(accel);
    update_rates(rate, on_ground);
  }
  // The same in two steps, for a caller that forms the specific force only when it is needed:
  // start() while started() is false, then update_rates().
  bool started() const { return started_; }
  void start(const Accel (&accel)[3]) {
    take_accel_angles(accel);
    roll_.start(roll_from_accel_);
    pitch_.start(pitch_from_accel_);
    yaw_.set(Angle{});
    euler_ = euler_terms(roll_.angle(), pitch_.angle());
    started_ = true;
  }
  void update_rates(const Rate (&rate)[3], bool on_ground = false) {
    // Body rates to Euler rates (Z-Y-X): roll' = p + (q sin roll + r cos roll) tan pitch,
    // pitch' = q cos roll - r sin roll. Without this a yaw turn while tilted reads as a roll or
    // pitch rate, and the accelerometer, which in free flight may only pull slowly (C1 of
    // seconds), would take that long to undo it. The rates are this tick's; the factors, which
    // move with the attitude, are refreshed with the accelerometer angles (update_accel: at 250
    // Hz they are at most 3 ms old, against the 11 ms the gyro's own low-pass delays the rates by).
    yaw_rate_ = rate[2];
    const Rate q = rate[1] - pitch_.bias();
    const EulerTerms& k = euler_;
    const Rate across = N::template convert_sat<Rate>(fx::mul_wide(q, k.sin_roll) +
                                                      fx::mul_wide(yaw_rate_, k.cos_roll));
    const Rate roll_coupling = product_sat<Rate>(across, k.tan_pitch);
    // |q (cos - 1)| + |r sin| <= 10 x 1/2 + 9.5 x 5/6 rad/s (angles clamped to 1 rad, filtered
    // gyro within 9.5 rad/s, bias within 0.5): inside the Rate format, no saturation needed.
    const Rate pitch_coupling = N::template convert<Rate>(fx::mul_wide(q, k.cos_roll - kOne) -
                                                          fx::mul_wide(yaw_rate_, k.sin_roll));
    // The accelerometer's expected angles turn with the yaw rate: they are the body's horizontal
    // velocity seen through the drag (f = -mu v), and the velocity of a yawing body turns in its
    // own axes, v' = ... - r x v: roll' += r pitch, pitch' -= r roll (times dt (1 - follow), so
    // that with no lag the expected angle is the predicted angle exactly).
    const auto turn = on_ground ? typename N::AngleGain{} : product<typename N::AngleGain>(yaw_rate_, cross_dt_);
    const auto roll_cross = fx::mul_wide(pitch_.expected(), turn);
    const auto pitch_cross = -fx::mul_wide(roll_.expected(), turn);
    // The bias loop adds each axis' error into that axis' bias: right while the body holds its
    // heading. A yaw turn carries a tilt error from one axis into the other (the kinematics
    // above), so the loop integrates an error that turns under it, and once the body turns a
    // sizeable angle within the correction's time constant (C1 samples) it integrates the error
    // late by a quarter turn and more: it feeds the error instead of taking it out, and a slow
    // orbit drifts the estimate off the truth by degrees within minutes (sim/scenarios/
    // long-turn.txt, docs/signal-chain.md). So the bias learns at its full gain only while the
    // body does not turn, less the more it turns in C1 samples, and not at all beyond a radian
    // (0.125 rad/s at the default C1 of 8000): a bias does not change within a turn, it is learnt
    // before and after. ArduPilot's DCM stops its gyro-drift integrator the same way above a spin
    // rate of 20 deg/s (SPIN_RATE_LIMIT in AP_AHRS_DCM.cpp).
    const Rate spin = magnitude(yaw_rate_);
    const auto bias_gain = spin < spin_limit_
                               ? product<typename N::BiasGain>(
                                     k2_, max_of(kFullTurn - product<typename N::AngleGain>(spin, c1_dt_),
                                                 typename N::AngleGain{}))
                               : typename N::BiasGain{};
    roll_.update(rate[0], roll_coupling, roll_cross, roll_from_accel_, on_ground, bias_gain);
    pitch_.update(rate[1], pitch_coupling, pitch_cross, pitch_from_accel_, on_ground, bias_gain);
    yaw_.add(fx::mul_wide(yaw_rate_, kDt));
  }

  // Turns the gyro missed while it read full scale (gyro_clip.hpp), about the body's x, y and z:
  // roll, pitch and yaw take them as they are (the Euler coupling of a few degrees is left out).
  void turn(const Angle (&missed)[3]) {
    roll_.turn(missed[0]);
    pitch_.turn(missed[1]);
    yaw_.add(fx::mul_wide(missed[2], kOneAngle));
  }

  Angle roll() const { return roll_.angle(); }
  Angle pitch() const { return pitch_.angle(); }
  Angle yaw() const { return yaw_.angle(); }
  Rate p() const { return roll_.rate(); }
  Rate q() const { return pitch_.rate(); }
  Rate r() const { return yaw_rate_; }
  Rate p_bias() const { return roll_.bias(); }
  Rate q_bias() const { return pitch_.bias(); }
  Angle roll_from_accel() const { return roll_from_accel_; }
  Angle pitch_from_accel() const { return pitch_from_accel_; }
  // What the model expects the accelerometer's angles to be (equal to the angles with no lag).
  Angle roll_expected() const { return roll_.expected(); }
  Angle pitch_expected() const { return pitch_.expected(); }

  // The body rates that hold roll and pitch where they are while the body yaws at r (Euler
  // kinematics, Z-Y-X, the inverse of update()'s): p = -r tan(pitch) / cos(roll),
  // q = r tan(roll). An angle loop that asks only for its angle error leaves that error standing
  // at (these rates) / P1 while yawing; the controllers add them as a feed-forward.
  Rate p_to_hold() const { return product_sat<Rate>(product_sat<Rate>(yaw_rate_, euler_.tan_pitch), -euler_.sec_roll); }
  Rate q_to_hold() const { return product_sat<Rate>(yaw_rate_, euler_.tan_roll); }

 private:
  using Unit = typename N::Coefficient;  // sin, cos, tan: Q<30>, +-2
  static constexpr typename N::Scale kDt = typename N::Scale(1.0 / SampleHz);
  static constexpr Unit kOne = Unit(1.0);
  static constexpr typename N::AngleGain kNoLag = typename N::AngleGain(1.0);
  static constexpr typename N::AngleGain kOneAngle = typename N::AngleGain(1.0);

  // One copy for both callers (the accelerometer-angle task and a restart): inlined into each, it
  // cost the image 1.3 KiB twice over.
  [[gnu::noinline]] void take_accel_angles(const Accel (&accel)[3]) {
    roll_from_accel_ = N::atan2(-accel[1], -accel[2]);
    const auto horizontal_squared = fx::mul_wide(accel[1], accel[1]) + fx::mul_wide(accel[2], accel[2]);
    const Magnitude horizontal = N::sqrt(N::template convert<Magnitude>(horizontal_squared));
    pitch_from_accel_ = N::atan2(N::template convert<Magnitude>(accel[0]), horizontal);
  }

  struct EulerTerms {
    Unit sin_roll, cos_roll, tan_pitch, tan_roll, sec_roll;
  };
  // sin, cos, tan and sec by their series to the fifth order (the fourth for cos, sec):
  // sin x = x (1 - x^2/6 (1 - x^2/20)), cos x = 1 - x^2/2 (1 - x^2/12),
  // tan x = x (1 + x^2/3 (1 + 2 x^2/5)), sec x = 1 + x^2/2 (1 + 5 x^2/12): a dozen multiplies at
  // 250 Hz instead of a sin/cos evaluation and divisions. At 0.52 rad (30 degrees) they are off by
  // 2e-6, 3e-5, 5e-4 and 2e-3 (relative 0.1 % and 0.15 % for tan and sec). The third-order series
  // were 1 % off in tan at 30 degrees: at full sticks (30 degrees of roll and pitch, 2 rad/s of
  // yaw) that is 0.01 rad/s of false roll rate in the kinematics, a standing degree of true error.
  // The angles are clamped to +-1 rad first: beyond that (57 degrees, past the tilt limit's
  // default of 45) the series part from the functions, and the vehicle is not flying but falling
  // or flipping.
  static EulerTerms euler_terms(Angle roll, Angle pitch) {
    const Angle limit = Angle(1.0);
    const Unit r = N::template convert<Unit>(clamp(roll, -limit, limit));
    const Unit t = N::template convert<Unit>(clamp(pitch, -limit, limit));
    const Unit r2 = product<Unit>(r, r), t2 = product<Unit>(t, t);
    return {product<Unit>(r, kOne - product<Unit>(product<Unit>(r2, kSixth), kOne - product<Unit>(r2, kTwentieth))),
            kOne - product<Unit>(product<Unit>(r2, kHalf), kOne - product<Unit>(r2, kTwelfth)),
            product<Unit>(t, kOne + product<Unit>(product<Unit>(t2, kThird), kOne + product<Unit>(t2, kTwoFifths))),
            product<Unit>(r, kOne + product<Unit>(product<Unit>(r2, kThird), kOne + product<Unit>(r2, kTwoFifths))),
            kOne + product<Unit>(product<Unit>(r2, kHalf), kOne + product<Unit>(r2, kFiveTwelfths))};
  }
  static constexpr Unit kHalf = Unit(1.0 / 2), kThird = Unit(1.0 / 3), kSixth = Unit(1.0 / 6),
                        kTwelfth = Unit(1.0 / 12), kTwentieth = Unit(1.0 / 20), kTwoFifths = Unit(2.0 / 5),
                        kFiveTwelfths = Unit(5.0 / 12);

  using Seconds = typename N::template Fixed<22>;  // C1 dt: up to 131 s (C1 65535 at 500 Hz)
  static constexpr typename N::AngleGain kFullTurn = typename N::AngleGain(1.0);  // rad in C1 samples

  TiltEstimator<N, SampleHz> roll_, pitch_;
  typename N::BiasGain k2_{};  // fs / C2
  Seconds c1_dt_{};            // the correction's time constant
  Rate spin_limit_{};          // 1 / c1_dt_: the yaw rate from which the bias learns nothing
  AngleIntegral<N> yaw_;
  Rate yaw_rate_{};
  Angle roll_from_accel_{};
  Angle pitch_from_accel_{};
  EulerTerms euler_{Unit{}, kOne, Unit{}, Unit{}, kOne};  // at level
  typename N::Scale cross_dt_{};                          // dt (1 - follow): the turn per rad/s of yaw
  bool started_ = false;
};

}  // namespace qr::chain
