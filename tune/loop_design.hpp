// Gains from a model (axis_model.hpp), with the margins and the step response they predict, and
// the same figures for any gains (the defaults, or a pilot's).
//
// The loops as the firmware flies them (qr/core/chain/controllers.hpp), at the control rate T:
//   roll, pitch  rate_sp = P1 (angle_sp - angle)        angle = the integral of the measured rate
//                moment  = P2 (rate_sp - y) - D (y - y_prev) / T + integral,  integral += I T (rate_sp - y)
//   yaw          moment  = P (rate_sp - y) + integral,   integral += I T (rate_sp - y)
// y the rate through the sensor low-pass, the moment held over the period, the plant the model.
//
// Margins (margins.hpp), of the discrete loop with the low-pass, the delay and the hold:
//   inner  the rate loop broken at the moment, the angle loop open (P1 = 0): (P2 + D + I) x plant;
//   outer  the angle loop broken at the angle, the rate loop closed;
//   yaw    the rate loop broken at the moment.
// Step figures: on the same discrete model from rest, the true angle after a 10 deg angle step
// (roll, pitch) or the true rate after a 1 rad/s rate step (yaw): rise 10-90 %, overshoot in % of
// the step, settle the time after which it stays within 10 % of the step (1 deg of 10, the
// scenarios' band), and the largest moment the controller asks for.
//
// The design rules (loop_design.cpp says why each):
//   1. D = motor lag x P2: the derivative's zero cancels the motors' lag.
//   2. P2 the largest with the inner loop's margins at the targets, 5 deg of phase kept for the
//      integral (without it, D = lag x P2).
//   3. I = P1 P2 / 20: the integral's zero I / P2 a twentieth of the angle loop's bandwidth (about P1).
//   4. P1 the largest with every target kept: both loops' margins (with I), the step's overshoot,
//      and the step's moment within what the motors can give at hover.
//   Yaw: P the largest with the loop's margins (5 deg kept) and the step's moment; I = P x its
//   crossover / 10.
// Every gain is rounded to its parameter's format and clamped to its range (gains.hpp) before it
// is judged, so the figures are those of the gains the firmware will fly.
#pragma once

#include <span>

#include <tune/axis_model.hpp>
#include <tune/gains.hpp>
#include <tune/margins.hpp>

namespace tune {

struct DesignLimits {
  double control_hz = 1000;      // kControlHz
  double filter_cutoff_hz = 20;  // filter_cutoff_hz
  // The floor is 45 deg, 6 dB and a step's 8 % overshoot; the design aims at 55 deg and 4 %:
  // measured on the truth (qrsim --sweep, 10 seeds), gains at 45 deg and 8 % bring the small step
  // faster but a large upset, where the mixer clips and the integral learns, back past 1 deg
  // (large-push within 1 deg in 1 s: 0 of 30 on 60 ms motors, 10 of 30 at 0.7 x inertia).
  double min_phase_margin_deg = 55;
  double min_gain_margin_db = 6;
  double max_overshoot_pct = 4;
  // What one engine may move from its hover thrust in a step (thrust units): a roll or pitch moment
  // M moves two engines by M / 2, a yaw moment all four by M / 4. The default vehicle hovers at
  // 280 per engine with 32 at idle (idle_level 180): 200 keeps the step away from the mixer's
  // limits, so the rise the model predicts is one the motors can give.
  double max_engine_share = 200;
  double angle_step_rad = 0.17453292519943295;  // 10 deg
  double yaw_step_rad_s = 1;
};

struct StepFigures {
  double rise_s = 0;         // 10 % to 90 %, first crossings (infinite if never)
  double overshoot_pct = 0;  // beyond the step, % of it (0 if none)
  double settle_s = 0;       // within 10 % of the step from then on (infinite if not within 4 s)
  double peak_moment = 0;    // the largest moment asked for (thrust units)
};

struct AxisDesign {
  RollPitchGains gains;
  Margins inner, outer;
  StepFigures step;
};

struct YawDesign {
  YawGains gains;
  Margins loop;
  StepFigures step;
};

// The figures of these gains (as flown: rounded and clamped) on this model.
AxisDesign evaluate(const AxisModel& model, const RollPitchGains& gains, const DesignLimits& limits);
YawDesign evaluate(const AxisModel& model, const YawGains& gains, const DesignLimits& limits);

// Whether the figures keep the targets.
bool keeps_targets(const AxisDesign& design, const DesignLimits& limits);
bool keeps_targets(const YawDesign& design, const DesignLimits& limits);

// The design for one model; roll and pitch share their gains (one set of parameters), so the
// second form designs one set that keeps the targets on every model given (roll and pitch). A
// model no gains within the parameters' ranges can serve gets the smallest gains the search
// tried: keeps_targets() says so.
AxisDesign design_roll_pitch(const AxisModel& model, const DesignLimits& limits);
RollPitchGains design_roll_pitch(std::span<const AxisModel> models, const DesignLimits& limits);
YawDesign design_yaw(const AxisModel& model, const DesignLimits& limits);

}  // namespace tune
