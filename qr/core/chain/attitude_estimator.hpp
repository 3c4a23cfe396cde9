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
// parameter changes. The bias accumulates in a 64-bit Wide with 52 fractional bits, exactly:
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
    angle_ = angle;
    bias_sum_ = {};
    bias_ = {};
  }

  void update(Rate gyro, Angle accel_angle) {
    rate_ = gyro - bias_;
    angle_ = wrap_angle(angle_ + product<Angle>(rate_, kDt));
    const Angle e = wrap_angle(angle_ - accel_angle);
    angle_ = wrap_angle(angle_ - product<Angle>(e, k1_));
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

  Angle angle() const { return angle_; }
  Rate rate() const { return rate_; }
  Rate bias() const { return bias_; }

 private:
  static constexpr typename N::Scale kDt = typename N::Scale(1.0 / SampleHz);

  typename N::AngleGain k1_{};
  typename N::BiasGain k2_{};
  Angle angle_{};
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
      yaw_ = Angle{};
      started_ = true;
    }
    roll_.update(rate[0], roll_from_accel_);
    pitch_.update(rate[1], pitch_from_accel_);
    yaw_rate_ = rate[2];
    yaw_ = wrap_angle(yaw_ + product<Angle>(yaw_rate_, kDt));
  }

  Angle roll() const { return roll_.angle(); }
  Angle pitch() const { return pitch_.angle(); }
  Angle yaw() const { return yaw_; }
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
  Angle yaw_{};
  Rate yaw_rate_{};
  Angle roll_from_accel_{};
  Angle pitch_from_accel_{};
  bool started_ = false;
};

}  // namespace qr::chain
