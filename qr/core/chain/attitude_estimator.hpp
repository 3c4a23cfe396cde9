// Roll and pitch from the gyro and the accelerometer, the IN4073 report's "Kalman" filter (a
// complementary filter with gyro bias estimation), per axis and per control period:
//
//   rate  = gyro - bias                       gyro rate, bias-corrected
//   angle = angle + rate dt                   predict by integrating the rate
//   e     = angle - accel_angle               disagreement with the accelerometer's angle
//   angle = angle - e / C1                    pull toward the accelerometer angle
//   bias  = bias + e / (C2 dt)                a drifting-ahead angle means the gyro reads high
//
// Signs: with a gyro that reads high (bias > 0 in truth), the integrated angle runs ahead of the
// accelerometer's, e > 0, and the bias estimate grows toward the truth; rate = gyro - bias then
// drops. Dynamics: the bias error decays with time constant about C2 / C1 samples (3.9 s with the
// defaults at 1 kHz), the angle follows the accelerometer with time constant C1 samples.
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
// The angle update uses body rates as Euler rates (small-angle kinematics): the accelerometer
// correction removes what that neglects while the vehicle is near level, which is where it flies.
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
  void subtract(Sum delta) {
    sum_ -= delta;
    normalise();
  }
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

  void update(Rate gyro, Angle accel_angle) {
    rate_ = gyro - bias_;
    angle_.add(fx::mul_wide(rate_, kDt));
    const Angle e = wrap_angle(angle_.angle() - accel_angle);
    angle_.subtract(fx::mul_wide(e, k1_));
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

  // Calibrated, filtered body rates (rad/s) and specific force (g), x y z.
  void update(const Rate (&rate)[3], const Accel (&accel)[3]) {
    roll_from_accel_ = N::atan2(-accel[1], -accel[2]);
    const auto horizontal_squared = fx::mul_wide(accel[1], accel[1]) + fx::mul_wide(accel[2], accel[2]);
    const Magnitude horizontal = N::sqrt(N::template convert<Magnitude>(horizontal_squared));
    pitch_from_accel_ = N::atan2(N::template convert<Magnitude>(accel[0]), horizontal);
    if (!started_) {
      roll_.start(roll_from_accel_);
      pitch_.start(pitch_from_accel_);
      yaw_.set(Angle{});
      started_ = true;
    }
    roll_.update(rate[0], roll_from_accel_);
    pitch_.update(rate[1], pitch_from_accel_);
    yaw_rate_ = rate[2];
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
  static constexpr typename N::Scale kDt = typename N::Scale(1.0 / SampleHz);

  TiltEstimator<N, SampleHz> roll_, pitch_;
  AngleIntegral<N> yaw_;
  Rate yaw_rate_{};
  Angle roll_from_accel_{};
  Angle pitch_from_accel_{};
  bool started_ = false;
};

}  // namespace qr::chain
