#include <tune/loop_design.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include <tune/cascade.hpp>

namespace tune {
namespace {

// Rule 2's reserve: P2 is chosen before the integral exists, and the integral's zero a twentieth of
// the way to the angle loop's bandwidth takes a few degrees from the rate loop's phase. Rule 4
// checks the margins again with it.
constexpr double kIntegralPhaseReserveDeg = 5;
// Rule 3: the integral's zero I / P2 at a twentieth of P1. The integral is a trim (a centre of mass
// off the middle, unequal motors), not a controller of its own: far below the angle loop it adds
// little overshoot to a step, and what it learns while an upset holds the vehicle off level it
// gives back slowly (the defaults have the zero at P1 / 15). At a tenth, measured on the truth,
// 60 ms motors came back from large-push within 1 deg in 1.23 s (7 of 10 seeds), at a twentieth in
// 0.89 s (10 of 10).
constexpr double kIntegralShare = 0.05;
// Yaw: its integral's zero at a tenth of the crossover, for the same reason.
constexpr double kYawIntegralShare = 0.1;
// The design aims this far inside the overshoot target: the firmware flies the model's loop with
// clamps, an integral that learns slower beyond 5 deg of error, and a rate set-point feed-forward,
// and a vehicle is not its model.
constexpr double kOvershootCushionPct = 1;
// The search: halvings of the interval (on a log scale), then steps of 2 % down while a target is
// missed (rounding, or a non-monotone corner).
constexpr int kBisections = 24;
constexpr double kBackOff = 0.98;

// The largest x in [lo, hi] for which ok(x), given ok(lo) and ok false above some point.
template <class Ok>
double largest(double lo, double hi, const Ok& ok) {
  if (ok(hi)) return hi;
  for (int n = 0; n < kBisections; ++n) {
    const double mid = std::sqrt(lo * hi);
    (ok(mid) ? lo : hi) = mid;
  }
  return lo;
}

double smallest_step(wire::ParamId id) {
  return std::ldexp(1.0, -wire::find_parameter(static_cast<uint8_t>(id))->frac_bits);
}

bool margins_kept(const Margins& m, const DesignLimits& limits, double reserve_deg = 0) {
  return m.phase_margin_deg >= limits.min_phase_margin_deg + reserve_deg &&
         m.gain_margin_db >= limits.min_gain_margin_db;
}

DesignLimits aimed(const DesignLimits& limits) {
  DesignLimits aim = limits;
  aim.max_overshoot_pct -= kOvershootCushionPct;
  return aim;
}

// Rules 3 and 1 for a P1 and P2.
RollPitchGains cascade_gains(double p1, double p2, double tau) {
  return flown(RollPitchGains{p1, p2, kIntegralShare * p1 * p2, tau * p2});
}

YawGains yaw_gains(const AxisModel& model, double p, const DesignLimits& limits) {
  const YawGains proportional = flown(YawGains{p, 0});
  const MeasuredPlant plant(model, limits);
  const Margins m = margins_of([&](double w) { return yaw_loop(plant, proportional, w); }, limits.control_hz);
  return flown(YawGains{p, kYawIntegralShare * p * 2 * std::numbers::pi * m.crossover_hz});
}

}  // namespace

AxisDesign evaluate(const AxisModel& model, const RollPitchGains& gains, const DesignLimits& limits) {
  const RollPitchGains g = flown(gains);
  const MeasuredPlant plant(model, limits);
  AxisDesign d;
  d.gains = g;
  d.inner = margins_of([&](double w) { return inner_loop(plant, g, w); }, limits.control_hz);
  d.outer = margins_of([&](double w) { return outer_loop(plant, g, w); }, limits.control_hz);
  d.step = angle_step(model, g, limits);
  return d;
}

YawDesign evaluate(const AxisModel& model, const YawGains& gains, const DesignLimits& limits) {
  const YawGains g = flown(gains);
  const MeasuredPlant plant(model, limits);
  YawDesign d;
  d.gains = g;
  d.loop = margins_of([&](double w) { return yaw_loop(plant, g, w); }, limits.control_hz);
  d.step = yaw_step(model, g, limits);
  return d;
}

bool keeps_targets(const AxisDesign& d, const DesignLimits& limits) {
  return margins_kept(d.inner, limits) && margins_kept(d.outer, limits) &&
         d.step.overshoot_pct < limits.max_overshoot_pct && d.step.peak_moment <= 2 * limits.max_engine_share;
}

bool keeps_targets(const YawDesign& d, const DesignLimits& limits) {
  return margins_kept(d.loop, limits) && d.step.overshoot_pct < limits.max_overshoot_pct &&
         d.step.peak_moment <= 4 * limits.max_engine_share;
}

RollPitchGains design_roll_pitch(std::span<const AxisModel> models, const DesignLimits& limits) {
  double tau = 0;
  for (const AxisModel& m : models) tau += m.motor_tau_s / static_cast<double>(models.size());
  std::vector<MeasuredPlant> plants;
  for (const AxisModel& m : models) plants.emplace_back(m, limits);

  // Rule 2: the rate loop alone (P1 = 0, I = 0), D = lag x P2 (rule 1).
  const auto inner_ok = [&](double p2) {
    const RollPitchGains g = flown(RollPitchGains{0, p2, 0, tau * p2});
    for (const MeasuredPlant& plant : plants) {
      const Margins m = margins_of([&](double w) { return inner_loop(plant, g, w); }, limits.control_hz);
      if (!margins_kept(m, limits, kIntegralPhaseReserveDeg)) return false;
    }
    return true;
  };
  const double p2_lo = smallest_step(wire::ParamId::roll_pitch_p2);
  const double p2 = largest(p2_lo, range_of(wire::ParamId::roll_pitch_p2).max, inner_ok);

  // Rule 4: the whole cascade on every model.
  const auto all_ok = [&](double p1) {
    const RollPitchGains g = cascade_gains(p1, p2, tau);
    for (const AxisModel& m : models) {
      if (!keeps_targets(evaluate(m, g, limits), aimed(limits))) return false;
    }
    return true;
  };
  const double p1_lo = smallest_step(wire::ParamId::roll_pitch_p1);
  double p1 = largest(p1_lo, range_of(wire::ParamId::roll_pitch_p1).max, all_ok);
  while (p1 > p1_lo && !all_ok(p1)) p1 *= kBackOff;
  return cascade_gains(p1, p2, tau);
}

AxisDesign design_roll_pitch(const AxisModel& model, const DesignLimits& limits) {
  return evaluate(model, design_roll_pitch(std::span<const AxisModel>(&model, 1), limits), limits);
}

YawDesign design_yaw(const AxisModel& model, const DesignLimits& limits) {
  const MeasuredPlant plant(model, limits);
  const auto proportional_ok = [&](double p) {
    const YawGains g = flown(YawGains{p, 0});
    const Margins m = margins_of([&](double w) { return yaw_loop(plant, g, w); }, limits.control_hz);
    return margins_kept(m, limits, kIntegralPhaseReserveDeg) &&
           g.p * limits.yaw_step_rad_s <= 4 * limits.max_engine_share;
  };
  const double p_lo = smallest_step(wire::ParamId::yaw_p);
  double p = largest(p_lo, range_of(wire::ParamId::yaw_p).max, proportional_ok);
  YawDesign d = evaluate(model, yaw_gains(model, p, limits), limits);
  while (p > p_lo && !keeps_targets(d, aimed(limits))) {
    p *= kBackOff;
    d = evaluate(model, yaw_gains(model, p, limits), limits);
  }
  return d;
}

}  // namespace tune
