// Roll and pitch from the gyro and the accelerometer, the IN4073 report's "Kalman" filter (a
// complementary filter with gyro bias estimation), per axis and per control period:
//
//   rate  = gyro - bias                       gyro rate, bias-corrected
//   angle = angle + (rate + coupling) dt      predict by integrating the Euler rate
//   e     = angle - accel_angle               disagreement with the accelerometer's angle
//   angle = angle - e / C1                    pull toward the accelerometer angle
//   bias  = bias + e / (C2 dt)                a drifting-ahead angle means the gyro reads high
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
// from it rounded once. Wrapped into [-pi, pi) after every change.
template <class N>
class AngleIntegral {
 public:
  using Angle = typename N::Angle;
  using Sum = decltype(fx::mul_wide(typename N::Angle{}, typename N::AngleGain{}));
  static_assert(fx::detail::is_same<Sum, decltype(fx::mul_wide(typename N::Rate{}, typename N::Scale{}))>,
                "rate x dt and angle x gain must add in the same wide format");

  void set(Angle a) {
    sum_ = fx::mul_wide(a, kOne);
    angle_ = a;
  }
  void add(Sum delta) {
    sum_ += delta;
    normalise();
  }
  // The angle the sum would read with delta added, not wrapped (Angle holds +-8 rad, so a value
  // just past +-pi is still right; callers wrap differences).
  Angle peek(Sum delta) const { return N::template convert<Angle>(sum_ + delta); }
  Angle angle() const { return angle_; }

 private:
  static constexpr typename N::AngleGain kOne = typename N::AngleGain(1.0);

  void normalise() {
    angle_ = N::template convert<Angle>(sum_);
    if (!(angle_ < kPiAngle<Angle>)) {
      sum_ -= fx::mul_wide(kTwoPiAngle<Angle>, kOne);
      angle_ = N::template convert<Angle>(sum_);
    } else if (angle_ < -kPiAngle<Angle>) {
      sum_ += fx::mul_wide(kTwoPiAngle<Angle>, kOne);
      angle_ = N::template convert<Angle>(sum_);
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

  void set_gains(typename N::AngleGain k1, typename N::BiasGain k2) {
    k1_ = k1;
    k2_ = k2;
  }
  // Starts from this angle (e.g. the accelerometer's) with no bias.
  void start(Angle angle) {
    angle_.set(angle);
    bias_sum_ = {};
    bias_ = {};
  }

  // gyro: the axis' body rate; coupling: what the other axes add to this angle's rate (Euler
  // kinematics, AttitudeEstimator::update), already bias-corrected.
  void update(Rate gyro, Rate coupling, Angle accel_angle) {
    rate_ = gyro - bias_;
    const auto predict = fx::mul_wide(rate_, kDt) + fx::mul_wide(coupling, kDt);
    const Angle e = wrap_angle(angle_.peek(predict) - accel_angle);
    angle_.add(predict - fx::mul_wide(e, k1_));  // predict and correct, wrapped once
    bias_sum_ += fx::mul_wide(e, k2_);
    bias_ = N::template convert_sat<Rate>(bias_sum_);
    if (kMaxBias < bias_) {
      bias_ = kMaxBias;
      bias_sum_ = N::widen(kMaxBias);
    } else if (bias_ < -kMaxBias) {
      bias_ = -kMaxBias;
      bias_sum_ = N::widen(-kMaxBias);
    }
  }

  Angle angle() const { return angle_.angle(); }
  Rate rate() const { return rate_; }
  Rate bias() const { return bias_; }

 private:
  static constexpr typename N::Scale kDt = typename N::Scale(1.0 / SampleHz);

  typename N::AngleGain k1_{};
  typename N::BiasGain k2_{};
  AngleIntegral<N> angle_;
  Rate rate_{};
  Rate bias_{};
  typename N::BiasSum bias_sum_{};
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
    const auto k2 = N::template ratio<typename N::BiasGain>(static_cast<int32_t>(SampleHz), c2);
    roll_.set_gains(k1, k2);
    pitch_.set_gains(k1, k2);
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
  // (re)start from the accelerometer's angles.
  void update(const Rate (&rate)[3], const Accel (&accel)[3]) {
    if (!started_) {
      take_accel_angles(accel);
      roll_.start(roll_from_accel_);
      pitch_.start(pitch_from_accel_);
      yaw_.set(Angle{});
      euler_ = euler_terms(roll_.angle(), pitch_.angle());
      started_ = true;
    }
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
    roll_.update(rate[0], roll_coupling, roll_from_accel_);
    pitch_.update(rate[1], pitch_coupling, pitch_from_accel_);
    yaw_.add(fx::mul_wide(yaw_rate_, kDt));
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

 private:
  using Unit = typename N::Coefficient;  // sin, cos, tan: Q<30>, +-2
  static constexpr typename N::Scale kDt = typename N::Scale(1.0 / SampleHz);
  static constexpr Unit kOne = Unit(1.0);

  void take_accel_angles(const Accel (&accel)[3]) {
    roll_from_accel_ = N::atan2(-accel[1], -accel[2]);
    const auto horizontal_squared = fx::mul_wide(accel[1], accel[1]) + fx::mul_wide(accel[2], accel[2]);
    const Magnitude horizontal = N::sqrt(N::template convert<Magnitude>(horizontal_squared));
    pitch_from_accel_ = N::atan2(N::template convert<Magnitude>(accel[0]), horizontal);
  }

  struct EulerTerms {
    Unit sin_roll, cos_roll, tan_pitch;
  };
  // sin and cos of the roll and tan of the pitch by their series to the third order:
  // sin x = x (1 - x^2/6), cos x = 1 - x^2/2, tan x = x (1 + x^2/3), five multiplies instead of a
  // sin/cos evaluation and a division. At 0.35 rad (20 degrees) they are off by 4e-5, 6e-4 and
  // 7e-4, so a 2 rad/s yaw turn at 20 degrees of bank leaves at most 2e-3 rad/s of rate error
  // (the first-order terms alone, roll' = p + r pitch, pitch' = q - r roll, would leave 3e-2),
  // which the accelerometer and the bias loop take out. The angles are clamped to +-1 rad first:
  // beyond that (57 degrees, past the tilt limit's default of 45) the series part from the
  // functions, and the vehicle is not flying but falling or flipping.
  static EulerTerms euler_terms(Angle roll, Angle pitch) {
    const Angle limit = Angle(1.0);
    const Unit r = N::template convert<Unit>(clamp(roll, -limit, limit));
    const Unit t = N::template convert<Unit>(clamp(pitch, -limit, limit));
    const Unit r2 = product<Unit>(r, r), t2 = product<Unit>(t, t);
    return {product<Unit>(r, kOne - product<Unit>(r2, kSixth)), kOne - product<Unit>(r2, kHalf),
            product<Unit>(t, kOne + product<Unit>(t2, kThird))};
  }
  static constexpr Unit kHalf = Unit(1.0 / 2), kThird = Unit(1.0 / 3), kSixth = Unit(1.0 / 6);

  TiltEstimator<N, SampleHz> roll_, pitch_;
  AngleIntegral<N> yaw_;
  Rate yaw_rate_{};
  Angle roll_from_accel_{};
  Angle pitch_from_accel_{};
  EulerTerms euler_{Unit{}, kOne, Unit{}};  // at level
  bool started_ = false;
};

}  // namespace qr::chain
