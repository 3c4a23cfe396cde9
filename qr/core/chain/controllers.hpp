// The controllers, each a proportional law with its gain from the parameter table. Outputs are
// moments in thrust units (engine_mixer.hpp), positive in the sense of docs/conventions.md:
// a positive roll moment rolls right (right side down), positive pitch pitches nose up, positive
// yaw yaws right. So an error "set-point minus estimate" > 0 must give a positive output, and
// every law below is gain x (set-point - measurement) with a non-negative gain.
//
// The error and the product are formed in one wide accumulator, gain x set-point minus gain x
// measurement: a yaw set-point of 8 rad/s against a rate of -9 rad/s is 17 rad/s of error, which
// the rate format (+-16) could not hold, and the product is clamped once.
#pragma once

#include <qr/core/chain/chain_parameters.hpp>
#include <qr/core/chain/numeric.hpp>

namespace qr::chain {

// Largest moment a controller asks for, per axis: a whole engine's thrust. The mixer scales
// moments down further when the engines cannot deliver them.
template <class N>
inline constexpr typename N::Thrust kMaxMoment = typename N::Thrust(1000.0);

// Largest rate set-point the angle loop asks for (230 deg/s).
template <class N>
inline constexpr typename N::Rate kMaxTiltRateSetpoint = typename N::Rate(4.0);

// gain x (setpoint - measured), clamped to [-limit, limit].
template <class Out, class G, class T>
constexpr Out proportional(G gain, T setpoint, T measured, Out limit) {
  return clamp(fx::narrow_sat<Out>(fx::mul_wide(gain, setpoint) - fx::mul_wide(gain, measured)), -limit, limit);
}

// Yaw: rate loop. moment = yaw_p x (r_setpoint - r).
template <class N>
class YawRateController {
 public:
  using Gain = typename N::template Fixed<kYawPFrac>;  // thrust units per rad/s

  void set_gain(int32_t yaw_p_raw) { gain_ = N::template fixed<kYawPFrac>(yaw_p_raw); }
  typename N::Thrust moment(typename N::Rate setpoint, typename N::Rate r) const {
    return proportional(gain_, setpoint, r, kMaxMoment<N>);
  }

 private:
  Gain gain_{};
};

// Roll or pitch: angle loop P1 (angle error -> rate set-point) around rate loop P2 (rate error ->
// moment).
template <class N>
class AttitudeController {
 public:
  using P1 = typename N::template Fixed<kP1Frac>;  // 1/s
  using P2 = typename N::template Fixed<kP2Frac>;  // thrust units per rad/s

  void set_gains(int32_t p1_raw, int32_t p2_raw) {
    p1_ = N::template fixed<kP1Frac>(p1_raw);
    p2_ = N::template fixed<kP2Frac>(p2_raw);
  }

  typename N::Thrust moment(typename N::Angle setpoint, typename N::Angle angle, typename N::Rate rate) {
    rate_setpoint_ = proportional(p1_, setpoint, angle, kMaxTiltRateSetpoint<N>);
    return proportional(p2_, rate_setpoint_, rate, kMaxMoment<N>);
  }
  typename N::Rate rate_setpoint() const { return rate_setpoint_; }

 private:
  P1 p1_{};
  P2 p2_{};
  typename N::Rate rate_setpoint_{};
};

}  // namespace qr::chain
