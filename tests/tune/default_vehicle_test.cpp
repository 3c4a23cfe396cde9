// The default vehicle (sim/vehicles/in4073.txt) in the model's terms, derived from its file; the
// fit on a record flown on that model; the default gains' and the designed gains' figures; all
// printed as one JSON line, {"tune_design": {...}}, the line docs/signal-chain.md quotes
// ("Autotune: fit and design").
//
// The vehicle's axes are derived from its file by qrsim's own axes_of (qr/sim_runner/vehicle_axes.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <qr/sim_runner/vehicle_axes.hpp>
#include <sim/vehicle.hpp>
#include <tune/axis_fit.hpp>
#include <tune/loop_design.hpp>
#include <tune/report_json.hpp>

#include "closed_loop_flight.hpp"

namespace tune {
namespace {

using qrsim::axes_of;
using qrsim::VehicleAxes;

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
      json_number(axes.thrust_unit_n * 1e3).c_str(), model_json(axes.roll).c_str(), model_json(axes.yaw).c_str(),
      model_json(roll_fit).c_str(), model_json(yaw_fit).c_str(), design_json(rp_default, yaw_default).c_str(),
      design_json(rp, yaw).c_str(), params_json(rp.gains, yaw.gains).c_str());
}

}  // namespace
}  // namespace tune
