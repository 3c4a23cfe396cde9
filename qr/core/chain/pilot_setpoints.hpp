// The pilot's sticks (qr::ControlInput) as set-points and open-loop moments:
//   full control: roll/pitch stick +-1000 -> angle set-point +-max_tilt_mrad (parameter, 30 deg)
//   yaw and full control: yaw stick +-1000 -> yaw rate set-point +-max_yaw_rate (parameter)
//   manual (all three) and yaw control (roll, pitch): stick +-1000 -> moment +-kMaxStickMoment
//   lift 0..1000 -> per-engine thrust lift^2 / 1000, so with no moments every engine runs at
//   the lift stick's value (engine_mixer.hpp).
// Signs follow docs/conventions.md: stick right rolls right, pull pitches nose up, twist right
// yaws right, so each stick maps to a set-point or moment of its own sign.
#pragma once

#include <stdint.h>

#include <common/units.hpp>
#include <qr/core/chain/chain_parameters.hpp>
#include <qr/core/chain/numeric.hpp>
#include <qr/core/flight_types.hpp>

namespace qr::chain {

inline constexpr double kMaxStickMoment = 200.0;  // thrust units at full stick

template <class N>
class PilotSetpoints {
 public:
  using Angle = typename N::Angle;
  using Rate = typename N::Rate;
  using Thrust = typename N::Thrust;
  using Scale = typename N::Scale;

  // max_yaw_rate parameter (raw, Q<10> rad/s): one division, at parameter changes only.
  void set_max_yaw_rate(int32_t raw) {
    yaw_rate_per_stick_ = N::template ratio<Scale>(raw, int32_t{wire::kStickMax} << kMaxYawRateFrac);
  }

  // max_tilt_mrad parameter (raw, mrad): one division, at parameter changes only.
  void set_max_tilt(int32_t mrad) {
    angle_per_stick_ = N::template ratio<Scale>(mrad, int32_t{wire::kStickMax} * 1000);
  }

  void update(const ControlInput& c) {
    lift_ = c.lift > wire::kLiftMax ? wire::kLiftMax : c.lift;
    const auto roll = stick(c.roll), pitch = stick(c.pitch), yaw = stick(c.yaw);
    roll_stick_ = roll;
    pitch_stick_ = pitch;
    roll_angle_ = product<Angle>(roll, angle_per_stick_);
    pitch_angle_ = product<Angle>(pitch, angle_per_stick_);
    yaw_rate_ = product<Rate>(yaw, yaw_rate_per_stick_);
    roll_moment_ = product<Thrust>(roll, kMomentPerStick);
    pitch_moment_ = product<Thrust>(pitch, kMomentPerStick);
    yaw_moment_ = product<Thrust>(yaw, kMomentPerStick);
  }

  uint16_t lift() const { return lift_; }
  Angle roll_angle() const { return roll_angle_; }
  Angle pitch_angle() const { return pitch_angle_; }
  Rate yaw_rate() const { return yaw_rate_; }
  // Acro (engine_sources.hpp, Tilt::rate): roll and pitch rates at the yaw's scale, full stick
  // max_yaw_rate_rad_s; formed only when that mode asks.
  Rate roll_rate() const { return product<Rate>(roll_stick_, yaw_rate_per_stick_); }
  Rate pitch_rate() const { return product<Rate>(pitch_stick_, yaw_rate_per_stick_); }
  Thrust roll_moment() const { return roll_moment_; }
  Thrust pitch_moment() const { return pitch_moment_; }
  Thrust yaw_moment() const { return yaw_moment_; }

 private:
  static constexpr Scale kMomentPerStick = Scale(kMaxStickMoment / wire::kStickMax);

  // A stick value clamped to +-1000 (the wire guarantees the range; the clamp makes the chain's
  // outputs bounded whatever it is fed).
  static typename N::template Fixed<0> stick(int16_t v) {
    const int32_t clamped = v > wire::kStickMax ? wire::kStickMax : v < -wire::kStickMax ? -wire::kStickMax : v;
    return N::template fixed<0>(clamped);
  }

  uint16_t lift_ = 0;
  typename N::template Fixed<0> roll_stick_{}, pitch_stick_{};
  Angle roll_angle_{}, pitch_angle_{};
  Rate yaw_rate_{};
  Thrust roll_moment_{}, pitch_moment_{}, yaw_moment_{};
  Scale yaw_rate_per_stick_{};
  Scale angle_per_stick_{};
};

}  // namespace qr::chain
