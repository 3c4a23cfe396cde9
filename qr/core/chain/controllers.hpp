// The controllers, with their gains from the parameter table: yaw a proportional rate loop, roll
// and pitch an angle loop around a PID rate loop. Outputs are moments in thrust units
// (engine_mixer.hpp), positive in the sense of docs/conventions.md: a positive roll moment rolls
// right (right side down), positive pitch pitches nose up, positive yaw yaws right. So an error
// "set-point minus estimate" > 0 must give a positive output, and every term below is
// gain x (set-point - measurement) with a non-negative gain (the derivative: -D x the measured
// rate's change).
//
// In the yaw loop the error and the product are formed in one wide accumulator, gain x set-point
// minus gain x measurement: a yaw set-point of 8 rad/s against a rate of -9 rad/s is 17 rad/s of
// error, which the rate format (+-16) could not hold, and the product is clamped once.
#pragma once

#include <stdint.h>

#include <qr/core/chain/chain_parameters.hpp>
#include <qr/core/chain/numeric.hpp>
#include <qr/core/control_rate.hpp>

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

// Largest moment the roll/pitch rate loop's integral holds (thrust units): a trim, not a
// controller of its own. About 20 % of one engine: it covers a centre of mass 4 cm off the motor
// cross of a 1 kg vehicle, or ten times the rotor-drag moment of a held 10 degree bank, and is
// small enough that a wound-up integral cannot take the vehicle away from the pilot.
template <class N>
inline constexpr typename N::Thrust kMaxIntegralMoment = typename N::Thrust(200.0);

// Largest moment the yaw rate loop's integral holds (thrust units): what the rotors' drag asks
// for at the largest yaw rate set-point, with room.
template <class N>
inline constexpr typename N::Thrust kMaxYawIntegralMoment = typename N::Thrust(300.0);

// Yaw: rate loop, PI. moment = yaw_p x (r_setpoint - r) + integral, integral += yaw_i dt x error.
// P alone leaves a standing error against the rotors' drag (a 1 rad/s set-point held 0.72 rad/s
// in the simulator); the integral takes it out. It integrates only while told (lift above zero,
// the mixer not saturated), holds at its clamp, and starts empty on entering a mode that runs it.
template <class N, uint32_t SampleHz = kControlHz>
class YawRateController {
 public:
  using Gain = typename N::template Fixed<kYawPFrac>;  // thrust units per rad/s
  using Thrust = typename N::Thrust;
  using Rate = typename N::Rate;
  using IntegralGain = typename N::template Fixed<19>;  // I dt: thrust units per rad/s, per tick
  using IntegralSum = decltype(fx::mul_wide(IntegralGain{}, Rate{}));

  void set_gains(int32_t yaw_p_raw, int32_t yaw_i_raw = 0) {
    gain_ = N::template fixed<kYawPFrac>(yaw_p_raw);
    i_dt_ = product<IntegralGain>(N::template fixed<kYawIFrac>(yaw_i_raw), kDt);
  }
  void reset() {
    integral_sum_ = {};
    integral_ = {};
  }
  Thrust moment(Rate setpoint, Rate r, bool integrate = false) {
    const Thrust p = proportional(gain_, setpoint, r, kMaxMoment<N>);
    p_term_ = p;
    if (integrate && magnitude(p + integral_) < kMaxMoment<N>) {
      // The error saturates to the rate format (+-16 rad/s): beyond it the P term is at its clamp.
      const Rate error = N::template convert_sat<Rate>(N::widen(setpoint) - N::widen(r));
      integral_sum_ += fx::mul_wide(i_dt_, error);
      integral_ = N::template convert<Thrust>(integral_sum_);
      if (kMaxYawIntegralMoment<N> < integral_) {
        integral_ = kMaxYawIntegralMoment<N>;
        integral_sum_ = fx::mul_wide(integral_, kOne);
      } else if (integral_ < -kMaxYawIntegralMoment<N>) {
        integral_ = -kMaxYawIntegralMoment<N>;
        integral_sum_ = fx::mul_wide(integral_, kOne);
      }
    }
    return clamp(p + integral_, -kMaxMoment<N>, kMaxMoment<N>);
  }
  Thrust integral() const { return integral_; }
  // The last moment's proportional term (for a live plot: moment = P term + integral, clamped).
  Thrust p_term() const { return p_term_; }

 private:
  static constexpr typename N::Scale kDt = typename N::Scale(1.0 / SampleHz);
  static constexpr typename N::template Fixed<30> kOne = typename N::template Fixed<30>(1.0);
  static_assert(fx::detail::is_same<IntegralSum, decltype(fx::mul_wide(Thrust{}, kOne))>,
                "the integral's clamp must write back into the sum's own format");

  Thrust p_term_{};
  Gain gain_{};
  IntegralGain i_dt_{};
  IntegralSum integral_sum_{};
  Thrust integral_{};
};

// Roll or pitch: angle loop P1 (angle error -> rate set-point) around a PID rate loop (rate error
// -> moment):
//
//   rate_setpoint = P1 (angle_setpoint - angle)                       clamped to +-4 rad/s
//   integral     += I dt (rate_setpoint - rate)    when allowed        clamped to +-200
//   moment        = P2 (rate_setpoint - rate) - D d(rate)/dt + integral   clamped to +-1000
//
// The integral is where a steady moment that the controller did not ask for ends up: the rotor
// drag that tilts a banked, moving vehicle back, a centre of mass off the middle, unequal
// motors. Without it the cascade holds an angle error of moment / (P1 P2) against such a moment
// (2.7 degrees in the simulator's 10 degree bank at P1 = 4, P2 = 50). It sits on the rate loop
// because that is where a disturbance moment enters: the integral is in thrust units, a trim that
// survives a gain change without a bump, and its clamp is a moment with a physical meaning.
//
// The derivative acts on the measured rate only (a set-point step gives no kick) and is the
// loop's phase lead: the motors' speed lag (30 ms in the simulator's vehicle, 10-70 ms across its
// sweep) and the gyro low-pass eat the phase a faster angle loop needs; D = tau P2 cancels a lag
// tau at the rate loop's crossover.
//
// Anti-windup: the integral adds nothing while `integrate` is false (the caller's judgement: the
// mixer had to scale the moments down last tick) or while the moment is at its own clamp, and it
// never exceeds kMaxIntegralMoment. Beyond kIntegralZone of angle error it learns at an eighth of
// its rate: a trim shows as a small error, a push as a large one, and what the integral learns
// from a push it must unlearn after it, at the pace of the cascade's slow pole, about
// I P1 / (P2 P1 + I) = 0.34 1/s with the default gains. A 0.6 N m roll push held 1.5 s wound it
// to its clamp, and the vehicle then hung 5 degrees the other way and took 5.2 s to come within
// 1 degree; with the zone it is back in 0.2 s (sim/scenarios/held-push.txt). A trim too large to
// show within the zone (a centre of mass far off) is still learnt, eight times slower. reset() empties it and restarts the derivative (entering
// full control; lift 0).
//
// Fixed point: I dt is formed from the Q<4> parameter when it changes, in Q<19>, so that the sum
// I dt x rate is a Wide<46> into which a Thrust (Q<16> x Q<30> one) writes back exactly: every
// increment adds in without rounding, and one far below the Thrust lsb (a rate error of 1e-6
// rad/s at I = 100) still moves the sum. D fs is the Q<8> parameter times the sample rate, an
// integer product, exact; P2 (Q<4>) is held in Q<8> too, so P2 x error - D fs x change is one
// wide accumulator, rounded and clamped once.
template <class N, uint32_t SampleHz = kControlHz>
class AttitudeController {
 public:
  using P1 = typename N::template Fixed<kP1Frac>;          // 1/s
  using P2 = typename N::template Fixed<kRollPitchDFrac>;  // thrust units per rad/s (Q<8>: see moment())
  using Thrust = typename N::Thrust;
  using Rate = typename N::Rate;
  using IntegralGain = typename N::template Fixed<19>;  // I dt: thrust units per rad/s, per tick
  using IntegralSum = decltype(fx::mul_wide(IntegralGain{}, Rate{}));
  using DerivativeGain = typename N::template Fixed<kRollPitchDFrac>;  // D fs: thrust units per rad/s

  // Raw parameter values (common/parameter_table.hpp). i_raw and d_raw default to 0: P-P.
  void set_gains(int32_t p1_raw, int32_t p2_raw, int32_t i_raw = 0, int32_t d_raw = 0) {
    p1_ = N::template fixed<kP1Frac>(p1_raw);
    p2_ = N::template fixed<kRollPitchDFrac>(p2_raw * (1 << (kRollPitchDFrac - kP2Frac)));  // exact
    i_dt_ = product<IntegralGain>(N::template fixed<kRollPitchIFrac>(i_raw), kDt);
    d_fs_ = N::template fixed<kRollPitchDFrac>(d_raw * static_cast<int32_t>(SampleHz));  // <= 5.2e6
  }

  // Empties the integral; the next moment() has no derivative (no previous rate to difference).
  void reset() {
    integral_sum_ = {};
    integral_ = {};
    primed_ = false;
  }

  // feed_forward: the body rate that holds the angle where it is while the vehicle yaws (Euler
  // kinematics, AttitudeEstimator::p_to_hold / q_to_hold); without it the angle loop holds an
  // error of that rate / P1 for as long as the yaw lasts (1.5 degrees at 10 degrees of bank and
  // 1 rad/s of yaw). moment_feed_forward: a moment known to be needed (the rotors' drag moment,
  // flight_chain.hpp), added to the output so the integral need not find it first.
  Thrust moment(typename N::Angle setpoint, typename N::Angle angle, Rate rate, bool integrate = false,
                Rate feed_forward = Rate{}, Thrust moment_feed_forward = Thrust{}) {
    // The angle error fits the Angle format (+-8 rad): the set-point is within +-0.7 rad (max_tilt_mrad) and
    // the estimate within [-pi, pi). Each part is clamped first (to twice the limit and to the
    // limit), so their sum fits the Rate format (+-16 rad/s) before the sum is clamped.
    const Rate p_part = clamp(product_sat<Rate>(p1_, setpoint - angle), -kTwice, kTwice);
    const Rate ff_part = clamp(feed_forward, -kMaxTiltRateSetpoint<N>, kMaxTiltRateSetpoint<N>);
    rate_setpoint_ = clamp(p_part + ff_part, -kMaxTiltRateSetpoint<N>, kMaxTiltRateSetpoint<N>);
    // Far from the set-point the integral learns at an eighth of its rate (kIntegralZone).
    return rate_loop(rate, integrate, moment_feed_forward, magnitude(setpoint - angle) < kIntegralZone);
  }

  // The rate loop alone (acro, engine_sources.hpp): a rate set-point from the sticks, clamped as
  // the angle loop's is; no angle error, so the integral learns at its full rate.
  Thrust rate_moment(Rate setpoint, Rate rate, bool integrate = false) {
    rate_setpoint_ = clamp(setpoint, -kMaxTiltRateSetpoint<N>, kMaxTiltRateSetpoint<N>);
    return rate_loop(rate, integrate, Thrust{}, true);
  }
  Rate rate_setpoint() const { return rate_setpoint_; }
  Thrust integral() const { return integral_; }
  // The last moment's proportional and derivative terms, P2 (rate_setpoint - rate) and
  // -D d(rate)/dt, each saturated to the moment format: with the integral and the moment
  // feed-forward they make the moment (before its clamp). Read for a live plot, never per tick.
  Thrust p_term() const { return N::template convert_sat<Thrust>(p_wide_); }
  Thrust d_term() const { return N::template convert_sat<Thrust>(-d_wide_); }

 private:
  // PID on rate_setpoint_ - rate, the integral learning fully when `near` (else an eighth).
  Thrust rate_loop(Rate rate, bool integrate, Thrust moment_feed_forward, bool near) {
    // Both differences fit the Rate format (+-16 rad/s): the set-point is within +-4 rad/s and a
    // filtered, calibrated gyro within about +-9.5 (full scale 8.7 rad/s, filter overshoot,
    // bias clamp), so the error is below 14 rad/s; one tick's change of that filtered rate is
    // far smaller still.
    const Rate error = rate_setpoint_ - rate;
    const Rate change = primed_ ? rate - previous_rate_ : Rate{};
    previous_rate_ = rate;
    primed_ = true;
    // P2 error - D fs change in one wide accumulator (P2 in Q<8> holds the Q<4> parameter
    // exactly), rounded and clamped once.
    // The two products are kept as they are (a store each) for a live plot of the terms; they are
    // turned into moments only when read (p_term(), d_term()).
    p_wide_ = fx::mul_wide(p2_, error);
    d_wide_ = fx::mul_wide(d_fs_, detail::in_register(change));  // a select: in_register (numeric.hpp)
    const Thrust pd = clamp(N::template convert_sat<Thrust>(p_wide_ - d_wide_), -kMaxMoment<N>, kMaxMoment<N>) +
                      clamp(moment_feed_forward, -kMaxMoment<N>, kMaxMoment<N>);  // within +-2000: fits
    if (integrate && magnitude(pd + integral_) < kMaxMoment<N>) {
      const Rate learn = near ? error : product<Rate>(error, kOutsideShare);
      integral_sum_ += fx::mul_wide(i_dt_, learn);  // at most 2 x 14 per tick onto at most 200
      integral_ = N::template convert<Thrust>(integral_sum_);
      if (kMaxIntegralMoment<N> < integral_) {
        integral_ = kMaxIntegralMoment<N>;
        integral_sum_ = fx::mul_wide(integral_, kOne);
      } else if (integral_ < -kMaxIntegralMoment<N>) {
        integral_ = -kMaxIntegralMoment<N>;
        integral_sum_ = fx::mul_wide(integral_, kOne);
      }
    }
    return clamp(pd + integral_, -kMaxMoment<N>, kMaxMoment<N>);
  }

  using PWide = decltype(fx::mul_wide(P2{}, Rate{}));
  using DWide = decltype(fx::mul_wide(DerivativeGain{}, Rate{}));
  static_assert(kRollPitchDFrac >= kP2Frac, "P2 moves into D's format without rounding");
  static constexpr Rate kTwice = Rate(8.0);  // twice kMaxTiltRateSetpoint
  // The angle error within which the integral learns at its full rate (5 degrees: the drag of a
  // held bank shows as 1 degree without the integral), and the share it learns beyond.
  static constexpr typename N::Angle kIntegralZone = typename N::Angle(0.087);
  static constexpr typename N::Scale kOutsideShare = typename N::Scale(1.0 / 8);
  static constexpr typename N::Scale kDt = typename N::Scale(1.0 / SampleHz);
  static constexpr typename N::template Fixed<30> kOne = typename N::template Fixed<30>(1.0);
  static_assert(fx::detail::is_same<IntegralSum, decltype(fx::mul_wide(Thrust{}, kOne))>,
                "the integral's clamp must write back into the sum's own format");

  P1 p1_{};
  P2 p2_{};
  IntegralGain i_dt_{};
  DerivativeGain d_fs_{};
  IntegralSum integral_sum_{};
  Thrust integral_{};
  Rate rate_setpoint_{};
  Rate previous_rate_{};
  PWide p_wide_{};
  DWide d_wide_{};
  bool primed_ = false;
};

}  // namespace qr::chain
