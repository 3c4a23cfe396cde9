// The chain's values as decimal integers, named by their unit: roll_e4() is the roll estimate in
// 1e-4 rad, climb_mm_s() the vertical speed in mm/s. Each is the chain's own number converted
// once (decimal_units.hpp: rounded half up; the angles and rates saturated to int16, as the wire
// carries them). They are the columns of the replay's CSV (replay_tick.hpp), what the chain
// checksum folds (tests/chain/chain_checksum.hpp) and what the chain's tests compare.
//
// The flight never reads these: what it sends, logs and streams goes through the observables'
// readers (qr/core/observable_readers.hpp), which read the chain's own numbers and convert them
// by the observable table's scales. A base of FlightChain (Chain is the chain itself), reading
// only what the chain exposes publicly.
#pragma once

#include <stdint.h>

#include <common/units.hpp>
#include <qr/core/chain/decimal_units.hpp>
#include <qr/core/chain/engine_mixer.hpp>

namespace qr::chain {

template <class Chain>
class DecimalReadouts {
 public:
  int16_t roll_e4() const { return e4(self().roll()); }
  int16_t pitch_e4() const { return e4(self().pitch()); }
  int16_t yaw_e4() const { return e4(self().yaw()); }
  int16_t p_e3() const { return e3_i16(self().p()); }
  int16_t q_e3() const { return e3_i16(self().q()); }
  int16_t r_e3() const { return e3_i16(self().r()); }
  int16_t roll_setpoint_e4() const { return e4(self().roll_setpoint()); }
  int16_t pitch_setpoint_e4() const { return e4(self().pitch_setpoint()); }
  int16_t yaw_rate_setpoint_e3() const { return e3_i16(self().yaw_rate_setpoint()); }

  // The accelerometer's own angles, the gyro bias estimates, the angle loops' rate set-points.
  int16_t roll_from_accel_e4() const { return e4(self().estimator().roll_from_accel()); }
  int16_t pitch_from_accel_e4() const { return e4(self().estimator().pitch_from_accel()); }
  int32_t p_bias_e6() const { return decimal<6>(self().estimator().p_bias()); }
  int32_t q_bias_e6() const { return decimal<6>(self().estimator().q_bias()); }
  int16_t p_setpoint_e3() const { return e3_i16(self().rate_setpoint(0)); }
  int16_t q_setpoint_e3() const { return e3_i16(self().rate_setpoint(1)); }
  int16_t rate_setpoint_e3(int axis) const { return e3_i16(self().rate_setpoint(axis)); }

  // The controllers' terms (axis 0 roll, 1 pitch, 2 yaw) in 0.1 thrust units, the rate loops'
  // integrals also in 1e-3 thrust units; the moments the last mix was asked for and realised.
  int32_t p_term_e1(int axis) const { return decimal<1>(self().p_term(axis)); }
  int32_t d_term_e1(int axis) const { return decimal<1>(self().d_term(axis)); }
  int32_t integral_e1(int axis) const { return decimal<1>(self().integral(axis)); }
  int32_t moment_e1(int axis) const { return decimal<1>(self().moment(axis)); }
  int32_t roll_integral_e3() const { return decimal<3>(self().integral(0)); }
  int32_t pitch_integral_e3() const { return decimal<3>(self().integral(1)); }
  Moments<int32_t> moments_e3() const { return moments_e3(self().moments()); }
  Moments<int32_t> applied_moments_e3() const { return moments_e3(self().applied_moments()); }

  // The height estimate's (height_mm() is the chain's own: the safety machine reads it) and the
  // vertical loops'.
  int32_t climb_mm_s() const { return decimal<3>(self().climb()); }
  int32_t accel_bias_mm_s2() const { return decimal<3>(self().height_estimator().accel_bias()); }
  int32_t baro_height_mm() const { return decimal<3>(self().height_estimator().baro_height()); }
  int32_t climb_setpoint_mm_s() const { return decimal<3>(self().climb_setpoint()); }
  int32_t vertical_thrust_e1() const { return decimal<1>(self().vertical_thrust()); }
  int32_t vertical_thrust_e3() const { return decimal<3>(self().vertical_thrust()); }

 private:
  const Chain& self() const { return static_cast<const Chain&>(*this); }

  template <int Digits, class T>
  static int32_t decimal(T x) {
    return in_decimal_units<Digits, typename Chain::Numbers>(x);
  }
  template <class T>
  static int16_t e4(T angle) {
    return wire::saturate_i16(decimal<4>(angle));
  }
  template <class T>
  static int16_t e3_i16(T rate) {
    return wire::saturate_i16(decimal<3>(rate));
  }
  template <class T>
  static Moments<int32_t> moments_e3(const Moments<T>& m) {
    return {decimal<3>(m.roll), decimal<3>(m.pitch), decimal<3>(m.yaw)};
  }
};

}  // namespace qr::chain
