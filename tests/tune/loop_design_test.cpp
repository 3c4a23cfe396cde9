// The design (tune/loop_design.hpp) judged by the tests' own closed loop, not by its own model:
// the firmware's controllers with the designed gains fly each vehicle (closed_loop_flight.hpp),
// and
// - a 10 deg step (1 rad/s on yaw) overshoots less than the target, with the rise evaluate() says;
// - the margins evaluate() gives are where the loop really stops ringing down: a kick rings down
//   with the plant's gain (or the angle's) raised to 0.9 of the gain margin, or a delay of 0.9 of
//   what the phase margin allows at the crossover added, and rings up at 1.1 of either.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <tune/loop_design.hpp>

#include "closed_loop_flight.hpp"

namespace tune {
namespace {

const AxisModel kRollModels[] = {
    {0.18, 0.030, 0.004, 0, 0, 0},  // the default vehicle, its motors' rise
    {0.09, 0.060, 0.010, 0, 0, 0},  // heavy, slow motors, an ESC's latency
    {0.35, 0.015, 0.002, 0, 0, 0},  // light and quick
};
const AxisModel kYawModel{0.0069, 0.040, 0.003, 0.23, 0.8, 0};

test::RawGains raw_gains(const RollPitchGains& g) {
  const auto r = raw_parameters(g);
  test::RawGains out;
  out.p1 = r[0].raw;
  out.p2 = r[1].raw;
  out.i = r[2].raw;
  out.d = r[3].raw;
  return out;
}

test::RawGains raw_gains(const YawGains& g) {
  const auto r = raw_parameters(g);
  test::RawGains out;
  out.yaw_p = r[0].raw;
  out.yaw_i = r[1].raw;
  return out;
}

// A quiet flight: no excitation, noise or disturbance.
test::FlightSetup quiet(const AxisModel& truth, const test::RawGains& gains, double seconds) {
  test::FlightSetup s;
  s.truth = truth;
  s.gains = gains;
  s.seconds = seconds;
  s.prbs_amplitude = 0;
  s.gyro_noise = 0;
  s.disturbance = 0;
  return s;
}

// How a kick of a micro-radian per second grows: the largest excursion over the last two seconds
// against the largest over the two after the kick; below 1 the loop rings down. One that grows a
// thousandfold has rung up before it reached the controllers' clamps, which would hold it there.
double growth(test::FlightSetup s, bool angle) {
  constexpr double kKick = 1e-6;
  s.initial_rate = kKick;
  const test::Flight f = test::fly(s);
  const std::vector<double>& x = angle ? f.angle : f.rate;
  if (test::peak(x, s.control_hz, 0, s.seconds) > 1000 * kKick) return 1000;
  return test::peak(x, s.control_hz, s.seconds - 2, s.seconds) / test::peak(x, s.control_hz, 0.5, 2.5);
}

double db_to_gain(double db) { return std::pow(10.0, db / 20); }
double delay_for(const Margins& m) { return m.phase_margin_deg / 360 / m.crossover_hz; }

struct StepSeen {
  double rise_s, overshoot_pct;
  bool settled;  // within 10 % of the step over the last second
};

StepSeen step_seen(const std::vector<double>& x, double hz, double step) {
  StepSeen s{0, 0, true};
  double t10 = -1, t90 = -1, top = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (t10 < 0 && x[k] >= 0.1 * step) t10 = static_cast<double>(k) / hz;
    if (t90 < 0 && x[k] >= 0.9 * step) t90 = static_cast<double>(k) / hz;
    top = std::max(top, x[k]);
    if (static_cast<double>(k) >= static_cast<double>(x.size()) - hz && std::fabs(x[k] - step) > 0.1 * step) {
      s.settled = false;
    }
  }
  s.rise_s = t90 - t10;
  s.overshoot_pct = std::max(0.0, (top - step) / step * 100);
  return s;
}

TEST(TuneDesign, KeepsTheTargetsOnEveryModelAndInTheFirmwaresLoop) {
  const DesignLimits limits;
  for (const AxisModel& model : kRollModels) {
    const AxisDesign d = design_roll_pitch(model, limits);
    EXPECT_TRUE(keeps_targets(d, limits)) << "gain " << model.gain;
    EXPECT_GE(d.inner.phase_margin_deg, 45);
    EXPECT_GE(d.inner.gain_margin_db, 6);
    EXPECT_GE(d.outer.phase_margin_deg, 45);
    EXPECT_GE(d.outer.gain_margin_db, 6);
    EXPECT_LT(d.step.overshoot_pct, 8);
    EXPECT_LE(d.step.peak_moment, 2 * limits.max_engine_share);
    // The integral's zero well below the rate loop's crossover.
    EXPECT_LT(d.gains.i / d.gains.p2, 2 * std::numbers::pi * d.inner.crossover_hz / 10);

    test::FlightSetup step = quiet(model, raw_gains(d.gains), 3);
    step.setpoint = limits.angle_step_rad;
    const StepSeen seen = step_seen(test::fly(step).angle, step.control_hz, limits.angle_step_rad);
    EXPECT_LT(seen.overshoot_pct, 8) << "gain " << model.gain;
    EXPECT_NEAR(seen.rise_s, d.step.rise_s, 0.15 * d.step.rise_s) << "gain " << model.gain;
    EXPECT_TRUE(seen.settled) << "gain " << model.gain;
  }
}

// The rate loop broken at the moment (P1 = 0): the plant's gain and a delay at the moment.
TEST(TuneDesign, InnerMarginsAreWhereTheRateLoopStopsRingingDown) {
  const DesignLimits limits;
  for (const AxisModel& model : {kRollModels[0], kRollModels[1]}) {
    const AxisDesign d = design_roll_pitch(model, limits);
    test::RawGains rate_loop = raw_gains(d.gains);
    rate_loop.p1 = 0;
    test::FlightSetup s = quiet(model, rate_loop, 4);
    const double gm = db_to_gain(d.inner.gain_margin_db), delay = delay_for(d.inner);
    s.plant_gain_scale = 0.9 * gm;
    EXPECT_LT(growth(s, false), 1) << "gain " << model.gain << " x " << s.plant_gain_scale;
    s.plant_gain_scale = 1.1 * gm;
    EXPECT_GT(growth(s, false), 1) << "gain " << model.gain << " x " << s.plant_gain_scale;
    s.plant_gain_scale = 1;
    s.extra_delay_s = 0.9 * delay;
    EXPECT_LT(growth(s, false), 1) << "gain " << model.gain << " + " << s.extra_delay_s << " s";
    s.extra_delay_s = 1.1 * delay;
    EXPECT_GT(growth(s, false), 1) << "gain " << model.gain << " + " << s.extra_delay_s << " s";
  }
}

// The angle loop broken at the angle: a gain on the angle the controller reads, and a delay.
TEST(TuneDesign, OuterMarginsAreWhereTheAngleLoopStopsRingingDown) {
  const DesignLimits limits;
  for (const AxisModel& model : {kRollModels[0], kRollModels[1]}) {
    const AxisDesign d = design_roll_pitch(model, limits);
    test::FlightSetup s = quiet(model, raw_gains(d.gains), 8);
    const double gm = db_to_gain(d.outer.gain_margin_db), delay = delay_for(d.outer);
    s.angle_gain_scale = 0.9 * gm;
    EXPECT_LT(growth(s, true), 1) << "gain " << model.gain << " x " << s.angle_gain_scale;
    s.angle_gain_scale = 1.1 * gm;
    EXPECT_GT(growth(s, true), 1) << "gain " << model.gain << " x " << s.angle_gain_scale;
    s.angle_gain_scale = 1;
    s.angle_delay_ticks = static_cast<int>(std::lround(0.9 * delay * limits.control_hz));
    EXPECT_LT(growth(s, true), 1) << "gain " << model.gain << " + " << s.angle_delay_ticks << " ticks";
    s.angle_delay_ticks = static_cast<int>(std::lround(1.1 * delay * limits.control_hz));
    EXPECT_GT(growth(s, true), 1) << "gain " << model.gain << " + " << s.angle_delay_ticks << " ticks";
  }
}

TEST(TuneDesign, YawKeepsTheTargetsAndItsMarginsAreReal) {
  const DesignLimits limits;
  const YawDesign d = design_yaw(kYawModel, limits);
  EXPECT_TRUE(keeps_targets(d, limits));
  EXPECT_LE(d.step.peak_moment, 4 * limits.max_engine_share);
  EXPECT_LT(d.gains.i / d.gains.p, 2 * std::numbers::pi * d.loop.crossover_hz / 5);

  test::FlightSetup s = quiet(kYawModel, raw_gains(d.gains), 3);
  s.yaw = true;
  s.setpoint = limits.yaw_step_rad_s;
  const StepSeen seen = step_seen(test::fly(s).rate, s.control_hz, limits.yaw_step_rad_s);
  EXPECT_LT(seen.overshoot_pct, 8);
  EXPECT_NEAR(seen.rise_s, d.step.rise_s, 0.15 * d.step.rise_s);
  EXPECT_TRUE(seen.settled);

  s.setpoint = 0;
  s.seconds = 4;
  const double gm = db_to_gain(d.loop.gain_margin_db), delay = delay_for(d.loop);
  s.plant_gain_scale = 0.9 * gm;
  EXPECT_LT(growth(s, false), 1);
  s.plant_gain_scale = 1.1 * gm;
  EXPECT_GT(growth(s, false), 1);
  s.plant_gain_scale = 1;
  s.extra_delay_s = 0.9 * delay;
  EXPECT_LT(growth(s, false), 1);
  s.extra_delay_s = 1.1 * delay;
  EXPECT_GT(growth(s, false), 1);
}

// evaluate() is not a flatterer: the default gains on a vehicle twice as quick as the default
// have no phase margin left, and the firmware's loop does ring up there.
TEST(TuneDesign, DefaultsAreUnstableOnAQuickVehicle) {
  const DesignLimits limits;
  const AxisDesign d = evaluate(kRollModels[2], default_roll_pitch_gains(), limits);
  EXPECT_LT(d.inner.phase_margin_deg, 0);
  EXPECT_FALSE(keeps_targets(d, limits));
  EXPECT_GT(growth(quiet(kRollModels[2], test::RawGains{}, 4), false), 1);
}

// Roll and pitch share their gains: one set that keeps the targets on both.
TEST(TuneDesign, OneSetForTwoAxes) {
  const DesignLimits limits;
  const AxisModel roll = kRollModels[0];
  AxisModel pitch = roll;
  pitch.gain *= 1.3;  // a longer frame than wide
  const AxisModel both[] = {roll, pitch};
  const RollPitchGains g = design_roll_pitch(both, limits);
  EXPECT_TRUE(keeps_targets(evaluate(roll, g, limits), limits));
  EXPECT_TRUE(keeps_targets(evaluate(pitch, g, limits), limits));
  // The set for roll alone is too much for pitch.
  EXPECT_FALSE(keeps_targets(evaluate(pitch, design_roll_pitch(roll, limits).gains, limits), limits));
}

}  // namespace
}  // namespace tune
