// The default vehicle (sim/vehicles/in4073.txt) in the model's terms, derived from its file; the
// fit on a record flown on that model; the default gains' and the designed gains' figures; all
// printed as one JSON line, {"tune_design": {...}}, the line docs/signal-chain.md quotes
// ("Autotune: fit and design").
//
// The derivation (the numbers are this vehicle's):
//   Hover: each rotor turns at w_h = sqrt(m g / (4 k_f)) = 415.6 rad/s. The pack at its initial
//   charge rests at 3 cells x 4.06 V; at hover it gives I = 4 k_m w_h^3 / (eta V) + I_avionics
//   = 8.1 A, so V = 12.19 - 8.1 x 0.030 = 11.95 V.
//   Engine 1000 sets the motor's target speed w_max = KV x load x 2 pi / 60 x V = 783 rad/s: one
//   engine at full speed lifts T_full = k_f w_max^2 = 8.7 N. Thrust goes with speed squared and the
//   command with speed, and the mixer's per-engine thrust is w = ae^2 / 1000 (engine_mixer.hpp):
//   one thrust unit is T_full / 1000 = 8.7 mN (hover 281 units, engine 530: the file's "about 530").
//   Roll: L = w3 - w1 thrust units, the two rotors arm_m from the centre: a torque of
//   arm x T_full / 1000 = 1.96 mN m per unit, over I_xx: gain 0.178 rad/s^2 per thrust unit.
//   Yaw: the drag torque k_m w^2 changes by (k_m / k_f) x the thrust's change, N = w1 + w3 - w0 - w2:
//   gain (k_m / k_f) T_full / (1000 I_zz) = 6.9e-3. A rotor sped up by dw also twists the airframe
//   by J_r dw/dt while it accelerates, J_r / (2 k_m w_h) = 0.23 s of lead on the drag's 2 k_m w_h dw;
//   and a turning airframe meets the rotors' in-plane drag c w_h v at each hub, v = r arm:
//   damping 4 c w_h arm^2 / I_zz = 0.80 1/s.
//   Motor lag: the speed follows its target with tau_up rising and tau_down falling; a moment
//   speeds one motor up as it slows the opposite one, so for small moments the lag is the mean of
//   the two: 40 ms.
//   Delay 0: the simulator's engines take a tick's command at that tick and the gyro is sampled at
//   the next (qr/boards/sim/sim_board.hpp); the hold and the low-pass are the model's own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <sim/battery.hpp>
#include <sim/rotor.hpp>
#include <sim/vehicle.hpp>
#include <tune/axis_fit.hpp>
#include <tune/loop_design.hpp>

#include "closed_loop_flight.hpp"

namespace tune {
namespace {

constexpr double kGravity = 9.80665;

struct VehicleAxes {
  AxisModel roll, yaw;
  double thrust_unit_n, hover_engine;
};

VehicleAxes axes_of(const sim::VehicleParams& v) {
  const double w_h = v.hover_speed();
  const double rest = v.battery_cells * sim::lipo_cell_volts(v.battery_initial_soc);
  double volts = rest;
  for (int n = 0; n < 4; ++n) {  // the current depends on the voltage it sags
    const double current = 4 * sim::rotor_shaft_power(v, w_h) / (v.powertrain_efficiency * volts) +
                           v.avionics_current_a;
    volts = rest - current * v.battery_resistance_ohm;
  }
  const double w_max = v.speed_per_volt() * volts;
  const double unit = v.thrust_coeff * w_max * w_max / 1000;
  const double tau = (v.motor_tau_up_s + v.motor_tau_down_s) / 2;
  VehicleAxes a;
  a.roll = {v.arm_m * unit / v.inertia_kgm2.x, tau, 0, 0, 0, 0};
  a.yaw = {v.torque_coeff / v.thrust_coeff * unit / v.inertia_kgm2.z,
           tau,
           0,
           v.rotor_inertia / (2 * v.torque_coeff * w_h),
           4 * v.rotor_drag_coeff * w_h * v.arm_m * v.arm_m / v.inertia_kgm2.z,
           0};
  a.thrust_unit_n = unit;
  a.hover_engine = std::sqrt(1000 * v.mass_kg * kGravity / 4 / unit);
  return a;
}

// ---- one JSON line, written by hand (no JSON library in the project) ----

std::string number(double x) {
  if (!std::isfinite(x)) return "null";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

std::string model_json(const AxisModel& m) {
  return "{\"gain\": " + number(m.gain) + ", \"motor_tau_s\": " + number(m.motor_tau_s) +
         ", \"delay_s\": " + number(m.delay_s) + ", \"lead_s\": " + number(m.lead_s) +
         ", \"damping_per_s\": " + number(m.damping_per_s) + ", \"residual\": " + number(m.residual) + "}";
}

std::string margins_json(const Margins& m) {
  return "{\"phase_margin_deg\": " + number(m.phase_margin_deg) + ", \"gain_margin_db\": " + number(m.gain_margin_db) +
         ", \"crossover_hz\": " + number(m.crossover_hz) + "}";
}

std::string step_json(const StepFigures& s) {
  return "{\"rise_s\": " + number(s.rise_s) + ", \"overshoot_pct\": " + number(s.overshoot_pct) +
         ", \"settle_s\": " + number(s.settle_s) + ", \"peak_moment\": " + number(s.peak_moment) + "}";
}

std::string design_json(const AxisDesign& rp, const YawDesign& yaw) {
  return "{\"roll_pitch\": {\"p1\": " + number(rp.gains.p1) + ", \"p2\": " + number(rp.gains.p2) +
         ", \"i\": " + number(rp.gains.i) + ", \"d\": " + number(rp.gains.d) +
         ", \"inner\": " + margins_json(rp.inner) + ", \"outer\": " + margins_json(rp.outer) +
         ", \"step\": " + step_json(rp.step) + "}, \"yaw\": {\"p\": " + number(yaw.gains.p) +
         ", \"i\": " + number(yaw.gains.i) + ", \"loop\": " + margins_json(yaw.loop) +
         ", \"step\": " + step_json(yaw.step) + "}}";
}

std::string params_json(const RollPitchGains& rp, const YawGains& yaw) {
  std::string s = "{";
  const auto add = [&](const RawParameter& p) {
    s += (s.size() > 1 ? ", \"" : "\"") + std::string(p.name()) + "\": " + p.text();
  };
  for (const RawParameter& p : raw_parameters(rp)) add(p);
  for (const RawParameter& p : raw_parameters(yaw)) add(p);
  return s + "}";
}

AxisModel fitted(const AxisModel& truth, bool yaw) {
  test::FlightSetup s;
  s.truth = truth;
  s.yaw = yaw;
  s.prbs_amplitude = yaw ? 200 : 40;
  std::string why;
  const auto m = fit_axis(test::fly(s).record, &why);
  EXPECT_TRUE(m.has_value()) << why;
  return m.value_or(AxisModel{});
}

TEST(TuneDefaultVehicle, ModelDesignAndMarginsPrinted) {
  const VehicleAxes axes = axes_of(sim::default_vehicle());
  // The thrust unit against the vehicle file's own hover figure, and the roll gain against the
  // signal-chain page's "one thrust unit of roll is 1.9e-3 N m".
  EXPECT_NEAR(axes.hover_engine, 530, 10);
  EXPECT_NEAR(axes.roll.gain * sim::default_vehicle().inertia_kgm2.x, 1.9e-3, 0.1e-3);
  EXPECT_NEAR(axes.roll.gain, 0.178, 0.002);
  EXPECT_NEAR(axes.yaw.gain, 6.9e-3, 0.1e-3);
  EXPECT_NEAR(axes.yaw.lead_s, 0.23, 0.01);
  EXPECT_NEAR(axes.yaw.damping_per_s, 0.80, 0.02);

  const AxisModel roll_fit = fitted(axes.roll, false), yaw_fit = fitted(axes.yaw, true);
  EXPECT_NEAR(roll_fit.gain / axes.roll.gain, 1, 0.05);
  EXPECT_NEAR(yaw_fit.gain / axes.yaw.gain, 1, 0.05);

  const DesignLimits limits;
  const AxisDesign rp_default = evaluate(axes.roll, default_roll_pitch_gains(), limits);
  const YawDesign yaw_default = evaluate(axes.yaw, default_yaw_gains(), limits);
  // The design from the fitted models, judged on the true ones.
  const AxisDesign rp = evaluate(axes.roll, design_roll_pitch(roll_fit, limits).gains, limits);
  const YawDesign yaw = evaluate(axes.yaw, design_yaw(yaw_fit, limits).gains, limits);
  EXPECT_TRUE(keeps_targets(rp, limits));
  EXPECT_TRUE(keeps_targets(yaw, limits));
  // The defaults fly this vehicle (the scenarios say so): their loops are stable here too.
  EXPECT_GT(rp_default.inner.phase_margin_deg, 30);
  EXPECT_GT(rp_default.outer.phase_margin_deg, 30);
  EXPECT_GT(yaw_default.loop.phase_margin_deg, 30);

  std::printf(
      "{\"tune_design\": {\"vehicle\": \"sim/vehicles/in4073.txt\", \"thrust_unit_mn\": %s, \"model\": {\"roll\": %s, "
      "\"yaw\": %s}, \"fitted\": {\"roll\": %s, \"yaw\": %s}, \"default\": %s, \"designed\": %s, \"params\": %s}}\n",
      number(axes.thrust_unit_n * 1e3).c_str(), model_json(axes.roll).c_str(), model_json(axes.yaw).c_str(),
      model_json(roll_fit).c_str(), model_json(yaw_fit).c_str(), design_json(rp_default, yaw_default).c_str(),
      design_json(rp, yaw).c_str(), params_json(rp.gains, yaw.gains).c_str());
}

}  // namespace
}  // namespace tune
